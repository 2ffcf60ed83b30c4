#include "ek/knots/codes.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <functional>
#include <map>
#include <numeric>

#include "ek/core/errors.hpp"

namespace ek {
namespace {

/// A tokenizer for bracketed integer lists: yields '[', ']', '{', '}', and
/// integers; ';' ',' and spaces separate.
struct Token {
  enum Kind { Open, Close, Number, End } kind;
  long value = 0;
  std::string text;
  size_t pos = 0;
};

class Lexer {
 public:
  Lexer(const std::string& text, std::string what) : s_(text), what_(std::move(what)) {}

  Token next() {
    while (i_ < s_.size() && (std::isspace(static_cast<unsigned char>(s_[i_])) || s_[i_] == ';' || s_[i_] == ','))
      ++i_;
    Token t{Token::End, 0, "", i_};
    if (i_ >= s_.size()) return t;
    char c = s_[i_];
    if (c == '[' || c == '{' || c == '(') {
      ++i_;
      t.kind = Token::Open;
      t.text = std::string(1, c);
      return t;
    }
    if (c == ']' || c == '}' || c == ')') {
      ++i_;
      t.kind = Token::Close;
      t.text = std::string(1, c);
      return t;
    }
    size_t j = i_;
    if (s_[j] == '-' || s_[j] == '+') ++j;
    while (j < s_.size() && std::isdigit(static_cast<unsigned char>(s_[j]))) ++j;
    std::string tok = s_.substr(i_, j - i_);
    if (j == i_ || tok == "-" || tok == "+") {
      size_t k = i_;
      while (k < s_.size() && !std::isspace(static_cast<unsigned char>(s_[k])) && s_[k] != ';' && s_[k] != ',' &&
             s_[k] != ']' && s_[k] != '}')
        ++k;
      throw InputError(what_ + " '" + s_ + "': unexpected token '" + s_.substr(i_, std::max<size_t>(k - i_, 1)) +
                       "' at character " + std::to_string(i_ + 1));
    }
    const char* b = tok.c_str() + (tok[0] == '+' ? 1 : 0);
    auto [p, ec] = std::from_chars(b, tok.c_str() + tok.size(), t.value);
    if (ec != std::errc())
      throw InputError(what_ + " '" + s_ + "': number '" + tok + "' is out of range");
    (void)p;
    t.kind = Token::Number;
    t.text = tok;
    i_ = j;
    return t;
  }

  [[noreturn]] void fail(const std::string& why) const { throw InputError(what_ + " '" + s_ + "': " + why); }

 private:
  const std::string& s_;
  std::string what_;
  size_t i_ = 0;
};

/// Parses "[n n n]" or "{n n n}" (flat list).
std::vector<long> parse_flat(const std::string& text, const std::string& what, char open, char close) {
  Lexer lex(text, what);
  Token t = lex.next();
  if (t.kind != Token::Open || t.text[0] != open)
    lex.fail(std::string("expected '") + open + "' at the start");
  std::vector<long> values;
  for (;;) {
    t = lex.next();
    if (t.kind == Token::Number) {
      values.push_back(t.value);
    } else if (t.kind == Token::Close) {
      if (t.text[0] != close) lex.fail("unexpected '" + t.text + "' (expected '" + std::string(1, close) + "')");
      break;
    } else if (t.kind == Token::End) {
      lex.fail("missing closing '" + std::string(1, close) + "'");
    } else {
      lex.fail("unexpected nested '" + t.text + "' at character " + std::to_string(t.pos + 1));
    }
  }
  if (lex.next().kind != Token::End) lex.fail("text after the closing '" + std::string(1, close) + "'");
  return values;
}

}  // namespace

int PDCrossing::sign(int edges) const {
  const int b = e[1], d = e[3];
  auto succ = [edges](int x) { return x % edges + 1; };
  if (succ(d) == b && succ(b) != d) return +1;
  if (succ(b) == d && succ(d) != b) return -1;
  // 2c = 2 (a one-crossing diagram): both hold; the sign is not determined by
  // the labels, and does not affect any invariant computed from it.
  return +1;
}

DTCode parse_dt(const std::string& text) {
  const std::string what = "DT code";
  auto values = parse_flat(text, what, '[', ']');
  if (values.empty()) throw InputError(what + " '" + text + "': empty code");
  const long c = static_cast<long>(values.size());
  std::vector<int> seen(static_cast<size_t>(2 * c + 1), 0);
  DTCode code;
  for (size_t k = 0; k < values.size(); ++k) {
    long v = values[k];
    const std::string at = " at position " + std::to_string(k + 1);
    if (v == 0) throw InputError(what + " '" + text + "': label 0" + at + " (labels are nonzero even numbers)");
    long a = std::labs(v);
    if (a % 2 != 0)
      throw InputError(what + " '" + text + "': label " + std::to_string(v) + at +
                       " is odd (DT labels are even numbers 2.." + std::to_string(2 * c) + ")");
    if (a > 2 * c)
      throw InputError(what + " '" + text + "': label " + std::to_string(v) + at + " exceeds 2c = " +
                       std::to_string(2 * c) + " for " + std::to_string(c) + " crossings");
    if (seen[static_cast<size_t>(a)]++)
      throw InputError(what + " '" + text + "': label " + std::to_string(a) + at + " is repeated");
    code.labels.push_back(static_cast<int>(v));
  }
  return code;
}

namespace {

/// The crossings of a PD code with every label 1..2c used exactly twice
/// (the checks that knots and links share).
PDCode read_pd_groups(Lexer& lex) {
  Token t = lex.next();
  if (t.kind != Token::Open) lex.fail("expected '[' at the start");
  PDCode code;
  for (;;) {
    t = lex.next();
    if (t.kind == Token::Close) break;
    if (t.kind == Token::End) lex.fail("missing closing ']'");
    if (t.kind != Token::Open)
      lex.fail("expected '[' to start crossing " + std::to_string(code.size() + 1) + ", got '" + t.text + "'");
    PDCrossing x;
    int k = 0;
    for (;;) {
      t = lex.next();
      if (t.kind == Token::Close) break;
      if (t.kind != Token::Number)
        lex.fail("crossing " + std::to_string(code.size() + 1) + " is not closed by ']'");
      if (k >= 4) lex.fail("crossing " + std::to_string(code.size() + 1) + " has more than 4 labels");
      if (t.value <= 0)
        lex.fail("label " + t.text + " in crossing " + std::to_string(code.size() + 1) +
                 " is not positive (edge labels are 1..2c)");
      if (t.value > 1000000) lex.fail("label " + t.text + " is out of range");
      x.e[static_cast<size_t>(k++)] = static_cast<int>(t.value);
    }
    if (k != 4)
      lex.fail("crossing " + std::to_string(code.size() + 1) + " has " + std::to_string(k) + " labels, expected 4");
    code.crossings.push_back(x);
  }
  if (lex.next().kind != Token::End) lex.fail("text after the closing ']'");
  if (code.crossings.empty()) lex.fail("empty code");
  const int c = code.size(), m = 2 * c;
  std::vector<int> count(static_cast<size_t>(m + 1), 0);
  for (int i = 0; i < c; ++i)
    for (int label : code.crossings[static_cast<size_t>(i)].e) {
      if (label > m)
        lex.fail("label " + std::to_string(label) + " in crossing " + std::to_string(i + 1) + " exceeds 2c = " +
                 std::to_string(m) + " for " + std::to_string(c) + " crossings");
      ++count[static_cast<size_t>(label)];
    }
  for (int label = 1; label <= m; ++label)
    if (count[static_cast<size_t>(label)] != 2)
      lex.fail("label " + std::to_string(label) + " appears " + std::to_string(count[static_cast<size_t>(label)]) +
               " times (every edge label must pair up: exactly 2)");
  return code;
}

std::string crossing_text(const PDCode& code, int i) {
  const auto& e = code.crossings[static_cast<size_t>(i)].e;
  return "crossing " + std::to_string(i + 1) + " [" + std::to_string(e[0]) + ";" + std::to_string(e[1]) + ";" +
         std::to_string(e[2]) + ";" + std::to_string(e[3]) + "]";
}

/// The strand checks of knot and link codes, with succ(x) the label after x
/// along its component: at every crossing a -> c are consecutive, and b, d
/// in one order or the other. Returns each crossing's incoming over label, 0
/// where both orders hold (a component of two edges).
std::vector<int> check_strands(const PDCode& code, const std::function<int(int)>& succ, const Lexer& lex) {
  std::vector<int> over_in(static_cast<size_t>(code.size()), 0);
  for (int i = 0; i < code.size(); ++i) {
    const auto& e = code.crossings[static_cast<size_t>(i)].e;
    if (succ(e[0]) != e[2])
      lex.fail(crossing_text(code, i) + ": under-strand edges " + std::to_string(e[0]) + " -> " +
               std::to_string(e[2]) + " are not consecutive labels");
    const bool b_to_d = succ(e[1]) == e[3], d_to_b = succ(e[3]) == e[1];
    if (!b_to_d && !d_to_b)
      lex.fail(crossing_text(code, i) + ": over-strand edges " + std::to_string(e[1]) + ", " +
               std::to_string(e[3]) + " are not consecutive labels");
    if (b_to_d != d_to_b) over_in[static_cast<size_t>(i)] = b_to_d ? e[1] : e[3];
  }
  return over_in;
}

/// Each edge label must leave one crossing and enter another: incoming edges
/// are a (under) and the over strand's tail over_in.
void check_incoming(const PDCode& code, const std::vector<int>& over_in, const Lexer& lex) {
  const int m = 2 * code.size();
  std::vector<int> incoming(static_cast<size_t>(m + 1), 0);
  for (int i = 0; i < code.size(); ++i) {
    ++incoming[static_cast<size_t>(code.crossings[static_cast<size_t>(i)].e[0])];
    ++incoming[static_cast<size_t>(over_in[static_cast<size_t>(i)])];
  }
  for (int label = 1; label <= m; ++label)
    if (incoming[static_cast<size_t>(label)] != 1)
      lex.fail("edge " + std::to_string(label) + " enters " + std::to_string(incoming[static_cast<size_t>(label)]) +
               " crossings (the orientation of the labels is inconsistent)");
}

}  // namespace

PDCode parse_pd(const std::string& text) {
  Lexer lex(text, "PD code");
  const PDCode code = read_pd_groups(lex);
  const int m = 2 * code.size();
  std::vector<int> over_in = check_strands(code, [m](int x) { return x % m + 1; }, lex);
  for (int i = 0; i < code.size(); ++i)  // one crossing (2c = 2): both orders hold; take d -> b
    if (over_in[static_cast<size_t>(i)] == 0) over_in[static_cast<size_t>(i)] = code.crossings[static_cast<size_t>(i)].e[3];
  check_incoming(code, over_in, lex);
  return code;
}

int PDLinkCode::sign(int crossing) const {
  const auto& e = code.crossings[static_cast<size_t>(crossing)].e;
  return over_in[static_cast<size_t>(crossing)] == e[3] ? +1 : -1;
}

namespace {

/// The components of a PD code: labels joined along the strands (a with c,
/// b with d), each component a range of consecutive labels.
std::vector<std::array<int, 2>> pd_label_ranges(const PDCode& code, Lexer& lex) {
  const int m = 2 * code.size();
  std::vector<int> parent(static_cast<size_t>(m + 1));
  std::iota(parent.begin(), parent.end(), 0);
  const std::function<int(int)> find = [&](int x) {
    return parent[static_cast<size_t>(x)] == x ? x : parent[static_cast<size_t>(x)] = find(parent[static_cast<size_t>(x)]);
  };
  for (const PDCrossing& x : code.crossings) {
    parent[static_cast<size_t>(find(x.e[0]))] = find(x.e[2]);
    parent[static_cast<size_t>(find(x.e[1]))] = find(x.e[3]);
  }
  std::map<int, std::array<int, 3>> groups;  // root -> lowest label, highest label, size
  for (int label = 1; label <= m; ++label) {
    auto [it, fresh] = groups.try_emplace(find(label), std::array<int, 3>{label, label, 0});
    it->second[1] = label;
    ++it->second[2];
  }
  std::vector<std::array<int, 2>> ranges;
  for (const auto& [root, g] : groups) {
    if (g[1] - g[0] + 1 != g[2])
      lex.fail("the labels of the component through label " + std::to_string(g[0]) +
               " are not consecutive (each component's edges are numbered in a row along it)");
    if (g[2] < 2) lex.fail("edge " + std::to_string(g[0]) + " is a component of one edge (a kink closed on itself)");
    ranges.push_back({g[0], g[1]});
  }
  std::sort(ranges.begin(), ranges.end());
  return ranges;
}

/// The over strands of the two-edge components ({l, l'}, each the other's
/// successor), which the labels leave unordered: an edge that ends as an
/// under strand's a elsewhere leaves here, one that starts as a c elsewhere
/// enters here, and one whose other end is an oriented over strand follows
/// it. A component that only passes over has no such end: its orientation is
/// a choice, made by sending its smaller label into the first crossing that
/// lists it.
void orient_two_edge_components(PDLinkCode& out) {
  const int c = out.code.size(), m = 2 * c;
  // +1: the label ends at an under strand's a, -1: it starts at a c
  std::vector<int> under_role(static_cast<size_t>(m + 1), 0);
  for (const PDCrossing& x : out.code.crossings) {
    under_role[static_cast<size_t>(x.e[0])] = +1;
    under_role[static_cast<size_t>(x.e[2])] = -1;
  }
  std::vector<std::vector<int>> over_at(static_cast<size_t>(m + 1));
  for (int i = 0; i < c; ++i)
    for (int slot : {1, 3}) over_at[static_cast<size_t>(out.code.crossings[static_cast<size_t>(i)].e[static_cast<size_t>(slot)])].push_back(i);
  // +1: `label` enters crossing i, -1: it leaves i, 0: not known yet
  const auto direction = [&](int label, int i) {
    if (under_role[static_cast<size_t>(label)] != 0) return -under_role[static_cast<size_t>(label)];
    for (int j : over_at[static_cast<size_t>(label)])
      if (j != i && out.over_in[static_cast<size_t>(j)] != 0) return out.over_in[static_cast<size_t>(j)] == label ? -1 : +1;
    return 0;
  };
  for (;;) {
    bool changed = false;
    for (int i = 0; i < c; ++i) {
      if (out.over_in[static_cast<size_t>(i)] != 0) continue;
      const auto& e = out.code.crossings[static_cast<size_t>(i)].e;
      const int db = direction(e[1], i), dd = direction(e[3], i);
      if (db == +1 || dd == -1) out.over_in[static_cast<size_t>(i)] = e[1];
      else if (db == -1 || dd == +1) out.over_in[static_cast<size_t>(i)] = e[3];
      else continue;
      changed = true;
    }
    if (changed) continue;
    int open = -1;
    for (int i = 0; i < c && open < 0; ++i)
      if (out.over_in[static_cast<size_t>(i)] == 0) open = i;
    if (open < 0) return;
    const auto& e = out.code.crossings[static_cast<size_t>(open)].e;
    out.over_in[static_cast<size_t>(open)] = std::min(e[1], e[3]);
  }
}

}  // namespace

PDLinkCode parse_pd_link(const std::string& text) {
  Lexer lex(text, "PD code");
  PDLinkCode out;
  out.code = read_pd_groups(lex);
  out.components = pd_label_ranges(out.code, lex);
  std::vector<std::array<int, 2>> range_of(static_cast<size_t>(2 * out.code.size() + 1));
  for (const auto& r : out.components)
    for (int label = r[0]; label <= r[1]; ++label) range_of[static_cast<size_t>(label)] = r;
  const auto succ = [&](int x) { return x == range_of[static_cast<size_t>(x)][1] ? range_of[static_cast<size_t>(x)][0] : x + 1; };
  out.over_in = check_strands(out.code, succ, lex);
  orient_two_edge_components(out);
  check_incoming(out.code, out.over_in, lex);
  return out;
}

std::vector<std::vector<int>> closure_cycles(const BraidWord& word) {
  std::vector<int> perm(static_cast<size_t>(word.strands));
  std::iota(perm.begin(), perm.end(), 0);
  // position -> strand after applying the letters left to right
  for (int letter : word.letters) {
    const int i = std::abs(letter) - 1;
    std::swap(perm[static_cast<size_t>(i)], perm[static_cast<size_t>(i + 1)]);
  }
  std::vector<char> seen(perm.size(), 0);
  std::vector<std::vector<int>> cycles;
  for (size_t s = 0; s < perm.size(); ++s) {
    if (seen[s]) continue;
    cycles.emplace_back();
    for (size_t x = s; !seen[x]; x = static_cast<size_t>(perm[x])) {
      seen[x] = 1;
      cycles.back().push_back(static_cast<int>(x) + 1);
    }
    std::sort(cycles.back().begin(), cycles.back().end());
  }
  return cycles;
}

int closure_components(const BraidWord& word) { return static_cast<int>(closure_cycles(word).size()); }

BraidWord parse_braid(const std::string& text, int strands) {
  const BraidWord word = parse_braid_word(text, strands);
  const int comps = closure_components(word);
  if (comps != 1)
    throw InputError("braid word '" + text + "': its closure has " + std::to_string(comps) +
                     " components (a link), not one (a knot)");
  return word;
}

BraidWord parse_braid_word(const std::string& text, int strands) {
  const std::string what = "braid word";
  auto values = parse_flat(text, what, '{', '}');
  if (values.empty()) throw InputError(what + " '" + text + "': empty word");
  BraidWord word;
  long max_abs = 0;
  for (size_t k = 0; k < values.size(); ++k) {
    long v = values[k];
    if (v == 0)
      throw InputError(what + " '" + text + "': generator 0 at position " + std::to_string(k + 1) +
                       " (generators are ±1, ±2, ...)");
    if (std::labs(v) > 1000)
      throw InputError(what + " '" + text + "': generator " + std::to_string(v) + " is out of range");
    max_abs = std::max(max_abs, std::labs(v));
    word.letters.push_back(static_cast<int>(v));
  }
  if (strands > 0) {
    if (max_abs >= strands)
      throw InputError(what + " '" + text + "': generator " + std::to_string(max_abs) + " needs more than " +
                       std::to_string(strands) + " strands");
    word.strands = strands;
  } else {
    word.strands = static_cast<int>(max_abs) + 1;
  }
  return word;
}

std::vector<BraidWord> parse_braid_list(const std::string& text) {
  size_t i = 0;
  while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
  if (i >= text.size() || text[i] != '[') return {parse_braid(text)};
  const size_t close = text.find_last_of(']');
  if (close == std::string::npos || close < i)
    throw InputError("braid list '" + text + "': missing closing ']'");
  for (size_t k = close + 1; k < text.size(); ++k)
    if (!std::isspace(static_cast<unsigned char>(text[k])))
      throw InputError("braid list '" + text + "': text after the closing ']'");
  std::vector<BraidWord> words;
  size_t pos = i + 1;
  while (pos < close) {
    const size_t open = text.find('{', pos);
    if (open == std::string::npos || open > close) {
      for (size_t k = pos; k < close; ++k)
        if (!std::isspace(static_cast<unsigned char>(text[k])) && text[k] != ';' && text[k] != ',')
          throw InputError("braid list '" + text + "': unexpected '" + std::string(1, text[k]) + "' at character " +
                           std::to_string(k + 1));
      break;
    }
    for (size_t k = pos; k < open; ++k)
      if (!std::isspace(static_cast<unsigned char>(text[k])) && text[k] != ';' && text[k] != ',')
        throw InputError("braid list '" + text + "': unexpected '" + std::string(1, text[k]) + "' at character " +
                         std::to_string(k + 1));
    const size_t end = text.find('}', open);
    if (end == std::string::npos || end > close) throw InputError("braid list '" + text + "': missing closing '}'");
    words.push_back(parse_braid(text.substr(open, end - open + 1)));
    pos = end + 1;
  }
  if (words.empty()) throw InputError("braid list '" + text + "': empty list");
  return words;
}

std::string to_string(const DTCode& code) {
  std::string s = "[";
  for (size_t i = 0; i < code.labels.size(); ++i) s += (i ? "; " : "") + std::to_string(code.labels[i]);
  return s + "]";
}

std::string to_string(const PDCode& code) {
  std::string s = "[";
  for (size_t i = 0; i < code.crossings.size(); ++i) {
    const auto& e = code.crossings[i].e;
    s += (i ? ";[" : "[") + std::to_string(e[0]) + ";" + std::to_string(e[1]) + ";" + std::to_string(e[2]) + ";" +
         std::to_string(e[3]) + "]";
  }
  return s + "]";
}

std::string to_string(const BraidWord& word) {
  std::string s = "{";
  for (size_t i = 0; i < word.letters.size(); ++i) s += (i ? ";" : "") + std::to_string(word.letters[i]);
  return s + "}";
}

}  // namespace ek
