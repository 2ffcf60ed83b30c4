#pragma once
/// \file
/// PD codes of pretzel knots P(p_1, ..., p_k) (paper Section 8.4, Fig.\ 15:
/// 9_35 = P(3,3,3) is "three circular parts joined through crossings at their
/// touching regions"; varying the crossings of each region gives knots beyond
/// the table).
///
/// The standard diagram: k vertical twist columns, left to right; column i is
/// a twist of |p_i| crossings of two strands; the top ends of neighbouring
/// columns are joined (top right of column i to top left of column i+1), the
/// top left of the first to the top right of the last by an arc around the
/// top, and the same at the bottom. Its regions between the columns (with the
/// outer region) are the "circles" of Fig. 15; each column is where two of
/// them touch.
///
/// Sign convention (Kawauchi; Wikipedia "Pretzel link"): P(-1,-1,-1) is the
/// right-handed trefoil (three positive crossings, writhe +3) and P(1,1,1) the
/// left-handed one. In the diagram, p_i > 0 means that at each crossing of
/// column i the strand from lower left to upper right passes over, p_i < 0
/// the strand from lower right to upper left. In a column with an odd number
/// of crossings of a knot with every p_i odd the two strands run in opposite
/// directions, and those crossings have the sign -sign(p_i). Examples checked
/// in the tests: P(3,3,3) = 9_35, P(5,-1,-1) = 6_1, P(-2,3,7) = 12n_242
/// (Alexander polynomial: Lehmer's polynomial).
///
/// The diagram is a knot (one component) when every p_i is odd and k is odd,
/// or when exactly one p_i is even; otherwise it is a link and
/// pretzel_pd() throws InputError naming the number of components.
/// (Counted by tracing the diagram, not from this rule.)
#include <string>
#include <vector>

#include "ek/knots/codes.hpp"

namespace ek {

/// PD code (KnotInfo convention, codes.hpp) of the standard diagram of
/// P(p_1, ..., p_k) with c = Σ|p_i| crossings. The orientation enters the
/// bottom crossing of the first column from its lower left, and edge 1 is
/// that incoming edge; edges are labelled 1..2c along the orientation.
/// Requires k >= 2 and every p_i != 0 (InputError otherwise); the result is a valid code for parse_pd()
/// (to_string() then parse_pd() returns it).
PDCode pretzel_pd(const std::vector<int>& twists);

/// "P(3,3,5)".
std::string pretzel_name(const std::vector<int>& twists);

/// Parses "P(3,3,5)", "3,3,5" or "(3, 3, 5)" into the twist counts (InputError otherwise).
std::vector<int> parse_pretzel(const std::string& text);

}  // namespace ek
