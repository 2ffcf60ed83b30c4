#pragma once
/// \file
/// Knot notations as they appear in the KnotInfo table (paper Section 3 and
/// Appendix A): Dowker-Thistlethwaite (DT), planar diagram (PD) and braid words.
///
/// Parsers accept the table's spelling ("[4; 6; 8; 2]", "[[4;2;5;1];[8;6;1;5]]",
/// "{1;-2;1;-2}") and also commas as separators. Malformed or impossible codes
/// throw InputError with a message naming the offending token and the reason.
#include <array>
#include <string>
#include <vector>

namespace ek {

/// DT code of a knot with c crossings: c signed even integers whose absolute
/// values are a permutation of 2, 4, ..., 2c (Appendix A). Entry k is the even
/// label paired with the odd label 2k + 1; negative means the strand with the
/// even label passes over.
struct DTCode {
  std::vector<int> labels;  ///< c signed even labels; entry k pairs with the odd label 2k + 1.
  int crossings() const { return static_cast<int>(labels.size()); }  ///< c, the number of crossings.
};

/// One PD crossing X[a, b, c, d]: the four edge labels counterclockwise,
/// starting at the incoming under-edge a (c is the outgoing under-edge; b and
/// d are the over-strand's edges). KnotInfo convention.
struct PDCrossing {
  std::array<int, 4> e{};  ///< Edge labels a, b, c, d (1..2c), counterclockwise from the incoming under-edge.
  /// +1 for a positive (right-handed) crossing, -1 for a negative one: the
  /// over strand runs d -> b (b = d + 1 mod 2c) for a positive crossing.
  /// `edges` is the number of edge labels 2c. Requires a non-degenerate code.
  int sign(int edges) const;
};

/// PD code of a knot diagram with c crossings and 2c edges labelled 1..2c
/// along the orientation.
struct PDCode {
  std::vector<PDCrossing> crossings;                               ///< The c crossings, in the code's order.
  int size() const { return static_cast<int>(crossings.size()); }  ///< c, the number of crossings.
};

/// Braid word on `strands` strands: letters ±i for σ_i^{±1}, 1 <= i < strands.
/// σ_i is a positive crossing of strands i and i+1 (the closure's diagram
/// has writhe = Σ sign(letters)).
struct BraidWord {
  int strands = 0;           ///< Number of strands (≥ 1 + max |letter|).
  std::vector<int> letters;  ///< ±i for σ_i^{±1}, in the order of the word.
  /// Number of letters (crossings of the closure's diagram).
  int length() const { return static_cast<int>(letters.size()); }
};

/// Parses a DT code. Checks: non-empty; every entry even and nonzero; the
/// absolute values are exactly 2, 4, ..., 2c with no repeats.
DTCode parse_dt(const std::string& text);

/// Parses a PD code. Checks: groups of exactly 4 positive labels; labels
/// 1..2c each used exactly twice; at every crossing the under-strand's edges
/// a, c and the over-strand's edges b, d are consecutive labels (mod 2c); the
/// edges form one closed strand (a knot).
PDCode parse_pd(const std::string& text);

/// PD code of a knot or a link (KnotInfo's and LinkInfo's convention): the
/// crossings as for a knot, the edge labels 1..2c, each component's labels
/// a range of consecutive integers in the order of its orientation (its
/// last label followed by its first). A knot's code is one range [1, 2c].
struct PDLinkCode {
  PDCode code;                                 ///< The crossings, labels 1..2c over all components.
  std::vector<std::array<int, 2>> components;  ///< [first, last] label of each component, by first label
  std::vector<int> over_in;                    ///< per crossing: the over strand's incoming label, b or d
  /// +1 when the over strand runs d -> b (a right-handed crossing, as PDCrossing::sign), -1 otherwise.
  int sign(int crossing) const;
};

/// Parses a PD code of a knot or a link. Checks those of parse_pd() for the
/// groups and labels; the components are the label sets that the strands
/// join (a with c, b with d), each a range of consecutive labels of at least
/// two edges; at every crossing a -> c, and b, d in one order or the other,
/// are consecutive in their component, and every edge enters exactly one
/// crossing. A component of two edges does not order its over strands by
/// the labels: they are oriented from its under crossings, or, when it only
/// passes over, by sending its smaller label into the first crossing listing it.
PDLinkCode parse_pd_link(const std::string& text);

/// Parses a braid word. Checks: non-empty; no letter 0. The number of strands
/// is 1 + max |letter| unless `strands` > 0 is given (then every |letter| must
/// be < strands). The closure must be a knot (one component): the braid's
/// permutation must be a single cycle; otherwise the error names the number of
/// components.
BraidWord parse_braid(const std::string& text, int strands = 0);

/// Parses a braid word as parse_braid() does, its closure a knot or a link
/// (closure_components() tells how many components).
BraidWord parse_braid_word(const std::string& text, int strands = 0);

/// Parses the table's braid field: a single word "{1;-2;1;-2}" or a list of
/// alternative words "[{...};{...}]" (KnotInfo lists two for some knots).
std::vector<BraidWord> parse_braid_list(const std::string& text);

/// Table spellings: "[4; 6; 8; 2]", "[[4;2;5;1];[8;6;1;5]]", "{1;-2;1;-2}".
std::string to_string(const DTCode& code);
std::string to_string(const PDCode& code);     ///< The table's spelling, "[[4;2;5;1];[8;6;1;5]]".
std::string to_string(const BraidWord& word);  ///< The table's spelling, "{1;-2;1;-2}".

/// Number of components of the braid's closure (cycles of its permutation).
int closure_components(const BraidWord& word);

/// The cycles of the braid's permutation, one per component of its closure:
/// each the sorted strand positions (1 .. strands) it occupies at the word's
/// start, the cycles ordered by their lowest position.
std::vector<std::vector<int>> closure_cycles(const BraidWord& word);

}  // namespace ek
