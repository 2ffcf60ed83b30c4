#include "ek/knots/pretzel.hpp"

#include <array>
#include <cstdlib>
#include <sstream>

#include "ek/core/errors.hpp"

namespace ek {
namespace {

// Ports of a crossing, counterclockwise: 0 = lower left, 1 = lower right,
// 2 = upper right, 3 = upper left. A strand passes straight through: q <-> q+2.
constexpr int kSW = 0, kSE = 1, kNE = 2, kNW = 3;

struct Port {
  int crossing = -1, port = -1;
};

/// The standard pretzel diagram as crossings whose ports are joined in pairs.
struct PortGraph {
  std::vector<std::array<Port, 4>> partner;  ///< partner[c][q]: the port joined to port q of crossing c
  std::vector<bool> slash_over;              ///< at crossing c the strand from lower left to upper right passes over (p_i > 0)

  void join(Port a, Port b) {
    partner[static_cast<size_t>(a.crossing)][static_cast<size_t>(a.port)] = b;
    partner[static_cast<size_t>(b.crossing)][static_cast<size_t>(b.port)] = a;
  }
};

PortGraph pretzel_graph(const std::vector<int>& twists) {
  const int k = static_cast<int>(twists.size());
  std::vector<int> bottom(static_cast<size_t>(k)), top(static_cast<size_t>(k));
  int c = 0;
  for (int i = 0; i < k; ++i) {
    bottom[static_cast<size_t>(i)] = c;
    c += std::abs(twists[static_cast<size_t>(i)]);
    top[static_cast<size_t>(i)] = c - 1;
  }
  PortGraph g;
  g.partner.resize(static_cast<size_t>(c));
  g.slash_over.resize(static_cast<size_t>(c));
  for (int i = 0; i < k; ++i) {
    for (int j = bottom[static_cast<size_t>(i)]; j <= top[static_cast<size_t>(i)]; ++j) {
      g.slash_over[static_cast<size_t>(j)] = twists[static_cast<size_t>(i)] > 0;
      if (j < top[static_cast<size_t>(i)]) {  // up the column: left to left, right to right
        g.join({j, kNW}, {j + 1, kSW});
        g.join({j, kNE}, {j + 1, kSE});
      }
    }
  }
  for (int i = 0; i + 1 < k; ++i) {  // neighbouring columns, at the top and at the bottom
    g.join({top[static_cast<size_t>(i)], kNE}, {top[static_cast<size_t>(i + 1)], kNW});
    g.join({bottom[static_cast<size_t>(i)], kSE}, {bottom[static_cast<size_t>(i + 1)], kSW});
  }
  // around the outside: first column's left ends to the last column's right ends
  g.join({top.front(), kNW}, {top.back(), kNE});
  g.join({bottom.front(), kSW}, {bottom.back(), kSE});
  return g;
}

}  // namespace

PDCode pretzel_pd(const std::vector<int>& twists) {
  require_input(twists.size() >= 2, "pretzel knot: at least two twist columns expected");
  for (int p : twists) require_input(p != 0, "pretzel knot " + pretzel_name(twists) + ": a column with 0 crossings");
  const PortGraph g = pretzel_graph(twists);
  const int c = static_cast<int>(g.partner.size());
  // Trace the strand from the lower left of crossing 0; label[x][q] is the
  // edge at port q of crossing x, entered[x][q] whether the strand enters there.
  std::vector<std::array<int, 4>> label(static_cast<size_t>(c), {0, 0, 0, 0});
  std::vector<std::array<bool, 4>> entered(static_cast<size_t>(c), {false, false, false, false});
  Port at{0, kSW};
  int edge = 1, steps = 0;
  do {
    const int out = (at.port + 2) % 4;
    label[static_cast<size_t>(at.crossing)][static_cast<size_t>(at.port)] = edge;
    entered[static_cast<size_t>(at.crossing)][static_cast<size_t>(at.port)] = true;
    edge = edge % (2 * c) + 1;
    label[static_cast<size_t>(at.crossing)][static_cast<size_t>(out)] = edge;
    at = g.partner[static_cast<size_t>(at.crossing)][static_cast<size_t>(out)];
    ++steps;
  } while ((at.crossing != 0 || at.port != kSW) && steps <= 2 * c);
  if (steps != 2 * c) {
    // count the components for the message: trace from every unvisited port
    int components = 1;
    std::vector<std::array<bool, 4>> seen(static_cast<size_t>(c));
    for (int x = 0; x < c; ++x)
      for (int q = 0; q < 4; ++q) seen[static_cast<size_t>(x)][static_cast<size_t>(q)] = label[static_cast<size_t>(x)][static_cast<size_t>(q)] != 0;
    for (int x = 0; x < c; ++x)
      for (int q = 0; q < 4; ++q) {
        if (seen[static_cast<size_t>(x)][static_cast<size_t>(q)]) continue;
        ++components;
        Port p{x, q};
        do {
          seen[static_cast<size_t>(p.crossing)][static_cast<size_t>(p.port)] = true;
          const int out = (p.port + 2) % 4;
          seen[static_cast<size_t>(p.crossing)][static_cast<size_t>(out)] = true;
          p = g.partner[static_cast<size_t>(p.crossing)][static_cast<size_t>(out)];
        } while (!seen[static_cast<size_t>(p.crossing)][static_cast<size_t>(p.port)]);
      }
    throw InputError("pretzel " + pretzel_name(twists) + " is a link of " + std::to_string(components) +
                     " components, not a knot");
  }
  PDCode pd;
  for (int x = 0; x < c; ++x) {
    // p_i > 0: the strand through the lower left and upper right passes over, so
    // the under strand runs through ports kSE and kNW (otherwise kSW and kNE)
    const int under_pair = g.slash_over[static_cast<size_t>(x)] ? kSE : kSW;  // ports under_pair, under_pair + 2
    const int a = entered[static_cast<size_t>(x)][static_cast<size_t>(under_pair)] ? under_pair : under_pair + 2;
    PDCrossing X;
    for (int r = 0; r < 4; ++r) X.e[static_cast<size_t>(r)] = label[static_cast<size_t>(x)][static_cast<size_t>((a + r) % 4)];
    pd.crossings.push_back(X);
  }
  return pd;
}

std::string pretzel_name(const std::vector<int>& twists) {
  std::ostringstream s;
  s << "P(";
  for (size_t i = 0; i < twists.size(); ++i) s << (i ? "," : "") << twists[i];
  s << ")";
  return s.str();
}

std::vector<int> parse_pretzel(const std::string& text) {
  std::string t = text;
  if (!t.empty() && (t[0] == 'P' || t[0] == 'p')) t = t.substr(1);
  std::vector<int> out;
  std::string token;
  auto flush = [&] {
    if (token.empty()) throw InputError("pretzel '" + text + "': expected P(p1,p2,...) with nonzero integers");
    char* end = nullptr;
    const long v = std::strtol(token.c_str(), &end, 10);
    if (*end != '\0' || v == 0 || v > 1000 || v < -1000)
      throw InputError("pretzel '" + text + "': '" + token + "' is not a nonzero integer of at most 1000");
    out.push_back(static_cast<int>(v));
    token.clear();
  };
  size_t i = 0;
  const bool paren = !t.empty() && t[0] == '(';
  if (paren) ++i;
  for (; i < t.size(); ++i) {
    const char ch = t[i];
    if (ch == ' ') continue;
    if (ch == ',') flush();
    else if (ch == ')' && paren && i + 1 == t.size()) break;
    else token += ch;
  }
  if (paren && (t.size() < 2 || t.back() != ')')) throw InputError("pretzel '" + text + "': missing ')'");
  flush();
  return out;
}

}  // namespace ek
