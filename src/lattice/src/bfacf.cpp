#include "ek/lattice/bfacf.hpp"

#include <gsl/gsl_rng.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "ek/core/errors.hpp"
#include "ek/core/hash.hpp"

namespace ek {

namespace {


// Unit directions are coded 0..5 as 2·axis + (negative ? 1 : 0); the
// opposite of d is d ^ 1.
inline int dir_code(int axis, int sign) { return 2 * axis + (sign < 0 ? 1 : 0); }

// Per vertex: the hot record read by every attempt (8 bytes, so that the
// records of a polygon of a few thousand vertices stay in the L1 cache) and
// the cold data read only by moves that can apply.
struct VertexLink {
  std::int32_t next;
  std::int8_t in, out;  // codes of the edges prev -> this and this -> next
  std::int16_t comp;    // the polygon (component) the vertex is on
};
struct Site3 {
  std::int32_t p[3];
};

inline std::uint64_t key_of(const std::int32_t* p) { return site_key(p[0], p[1], p[2]); }

int step_code(const std::int32_t* from, const std::int32_t* to) {
  for (int k = 0; k < 3; ++k)
    if (to[k] != from[k]) return dir_code(k, to[k] - from[k]);
  return -1;
}

}  // namespace

struct BfacfWalk::Impl {
  std::vector<VertexLink> link;
  std::vector<Site3> pos;
  std::vector<std::int32_t> prev;
  std::vector<std::int32_t> slot;  // index in live[comp]
  std::vector<std::int32_t> free_nodes;
  std::vector<std::vector<std::int32_t>> live;  // per component, its live vertices; edge = (live[c][k], next)
  int total = 0;                                // vertices of all components
  SiteSet sites;
  gsl_rng* rng = nullptr;

  ~Impl() {
    if (rng) gsl_rng_free(rng);
  }

  int length() const { return total; }
  int length(int c) const { return static_cast<int>(live[static_cast<size_t>(c)].size()); }

  // Exactly uniform integer in [0, range) from 32-bit MT19937 outputs
  // (Lemire's multiply-and-reject; range < 2^32).
  std::uint32_t uniform_below(std::uint32_t range) {
    std::uint64_t m = static_cast<std::uint64_t>(gsl_rng_get(rng)) * range;
    auto low = static_cast<std::uint32_t>(m);
    if (low < range) {
      const std::uint32_t threshold = static_cast<std::uint32_t>(-range) % range;
      while (low < threshold) {
        m = static_cast<std::uint64_t>(gsl_rng_get(rng)) * range;
        low = static_cast<std::uint32_t>(m);
      }
    }
    return static_cast<std::uint32_t>(m >> 32);
  }
  // true with probability p (a uniform 32-bit draw u accepted when u/2^32 < p)
  bool bernoulli(double p) { return static_cast<double>(gsl_rng_get(rng)) < p * 4294967296.0; }

  std::int32_t new_node(const std::int32_t* p, std::int16_t comp) {
    std::int32_t id;
    if (!free_nodes.empty()) {
      id = free_nodes.back();
      free_nodes.pop_back();
    } else {
      id = static_cast<std::int32_t>(link.size());
      link.push_back({});
      pos.push_back({});
      prev.push_back(0);
      slot.push_back(0);
    }
    const auto u = static_cast<size_t>(id);
    std::copy(p, p + 3, pos[u].p);
    link[u].comp = comp;
    auto& mine = live[static_cast<size_t>(comp)];
    slot[u] = static_cast<std::int32_t>(mine.size());
    mine.push_back(id);
    ++total;
    return id;
  }

  void delete_node(std::int32_t id) {
    auto& mine = live[static_cast<size_t>(link[static_cast<size_t>(id)].comp)];
    const std::int32_t s = slot[static_cast<size_t>(id)];
    const std::int32_t last = mine.back();
    mine[static_cast<size_t>(s)] = last;
    slot[static_cast<size_t>(last)] = s;
    mine.pop_back();
    free_nodes.push_back(id);
    --total;
  }

  /// A uniform draw r in [0, 4·(edges)) and the vertex u of edge r / 4: over
  /// all components (only = -1: uniform over all edges) or one component. A
  /// single polygon draws exactly as it always has.
  std::pair<std::int32_t, std::uint32_t> draw_edge(int only) {
    if (only >= 0 || live.size() == 1) {
      const auto& mine = live[static_cast<size_t>(std::max(only, 0))];
      const std::uint32_t r = uniform_below(4 * static_cast<std::uint32_t>(mine.size()));
      return {mine[r >> 2], r};
    }
    const std::uint32_t r = uniform_below(4 * static_cast<std::uint32_t>(total));
    std::uint32_t k = r >> 2;
    size_t c = 0;
    while (k >= live[c].size()) k -= static_cast<std::uint32_t>(live[c++].size());
    return {live[c][k], r};
  }

  BfacfMove attempt(double p_plus, double p_minus, std::uint32_t max_length, int only = -1) {
    const auto n = static_cast<std::uint32_t>(total);
    const auto [i, r] = draw_edge(only);
    const auto ui = static_cast<size_t>(i);
    const std::int32_t j = link[ui].next;
    const auto uj = static_cast<size_t>(j);
    // e = edge u -> v; w = one of the 4 unit vectors perpendicular to it
    const int e = link[ui].out;
    const int axis = e >> 1;
    const int q = static_cast<int>(r & 3);
    const int waxis = (axis + 1 + (q >> 1)) % 3;
    const int w = dir_code(waxis, (q & 1) ? -1 : 1);
    const std::int32_t wstep = (q & 1) ? -1 : 1;
    const bool A = link[ui].in == (w ^ 1);  // a = u + w: the edge a -> u is -w
    const bool B = link[uj].out == w;       // b = v + w: the edge v -> b is +w
    if (A && B) {
      // I: a, u, v, b -> a, b (never below the square)
      if (length(link[ui].comp) <= 4) return BfacfMove::None;
      if (p_minus < 1.0 && !bernoulli(p_minus)) return BfacfMove::None;
      const std::int32_t ia = prev[ui], ib = link[uj].next;
      sites.erase(key_of(pos[ui].p));
      sites.erase(key_of(pos[uj].p));
      link[static_cast<size_t>(ia)].next = ib;
      prev[static_cast<size_t>(ib)] = ia;
      link[static_cast<size_t>(ia)].out = static_cast<std::int8_t>(e);
      link[static_cast<size_t>(ib)].in = static_cast<std::int8_t>(e);
      delete_node(i);
      delete_node(j);
      return BfacfMove::I;
    }
    if (A) {
      // III: a, u, v -> a, v + w, v
      std::int32_t t[3] = {pos[uj].p[0], pos[uj].p[1], pos[uj].p[2]};
      t[waxis] += wstep;
      const std::uint64_t tk = key_of(t);
      if (sites.contains(tk)) return BfacfMove::None;
      sites.erase(key_of(pos[ui].p));
      sites.insert(tk);
      std::copy(t, t + 3, pos[ui].p);
      link[ui].in = static_cast<std::int8_t>(e);
      link[ui].out = static_cast<std::int8_t>(w ^ 1);
      link[static_cast<size_t>(prev[ui])].out = static_cast<std::int8_t>(e);
      link[uj].in = static_cast<std::int8_t>(w ^ 1);
      return BfacfMove::III;
    }
    if (B) {
      // III: u, v, b -> u, u + w, b
      std::int32_t t[3] = {pos[ui].p[0], pos[ui].p[1], pos[ui].p[2]};
      t[waxis] += wstep;
      const std::uint64_t tk = key_of(t);
      if (sites.contains(tk)) return BfacfMove::None;
      sites.erase(key_of(pos[uj].p));
      sites.insert(tk);
      std::copy(t, t + 3, pos[uj].p);
      link[uj].in = static_cast<std::int8_t>(w);
      link[uj].out = static_cast<std::int8_t>(e);
      link[ui].out = static_cast<std::int8_t>(w);
      link[static_cast<size_t>(link[uj].next)].in = static_cast<std::int8_t>(e);
      return BfacfMove::III;
    }
    // II: u, v -> u, u + w, v + w, v (the random number first: cheap rejection when p+ is small)
    if (p_plus < 1.0 && !bernoulli(p_plus)) return BfacfMove::None;
    if (n + 2 > max_length) return BfacfMove::None;
    std::int32_t t1[3] = {pos[ui].p[0], pos[ui].p[1], pos[ui].p[2]};
    std::int32_t t2[3] = {pos[uj].p[0], pos[uj].p[1], pos[uj].p[2]};
    t1[waxis] += wstep;
    t2[waxis] += wstep;
    const std::uint64_t k1key = key_of(t1), k2key = key_of(t2);
    if (sites.contains(k1key) || sites.contains(k2key)) return BfacfMove::None;
    sites.insert(k1key);
    sites.insert(k2key);
    const std::int32_t k1 = new_node(t1, link[ui].comp);
    const std::int32_t k2 = new_node(t2, link[ui].comp);
    const auto u1 = static_cast<size_t>(k1), u2 = static_cast<size_t>(k2);
    link[ui].next = k1;
    prev[u1] = i;
    link[u1].next = k2;
    prev[u2] = k1;
    link[u2].next = j;
    prev[uj] = k2;
    link[ui].out = link[u1].in = static_cast<std::int8_t>(w);
    link[u1].out = link[u2].in = static_cast<std::int8_t>(e);
    link[u2].out = link[uj].in = static_cast<std::int8_t>(w ^ 1);
    return BfacfMove::II;
  }
};

namespace {

// longest polygon the walk may make (site keys are unique below kMaxLatticeLength)
constexpr std::uint32_t kMaxLength = kMaxLatticeLength - 2;

void check_fugacity(double beta) {
  require(std::isfinite(beta) && beta > 0.0, "BFACF: the fugacity must be positive and finite");
}

void count(BfacfRunReport& rep, BfacfMove m) {
  switch (m) {
    case BfacfMove::I:
      ++rep.accepted_I;
      break;
    case BfacfMove::II:
      ++rep.accepted_II;
      break;
    case BfacfMove::III:
      ++rep.accepted_III;
      break;
    case BfacfMove::None:
      break;
  }
}

}  // namespace

BfacfWalk::BfacfWalk(const LatticePoints& start, std::uint64_t seed)
    : BfacfWalk(std::vector<LatticePoints>{start}, seed) {}

BfacfWalk::BfacfWalk(const std::vector<LatticePoints>& components, std::uint64_t seed)
    : impl_(std::make_unique<Impl>()) {
  require_input(!components.empty(), "BFACF start: no polygon");
  require_input(components.size() <= 32767, "BFACF start: more than 32767 components");
  Impl& w = *impl_;
  size_t sites = 0;
  for (const LatticePoints& P : components) sites += static_cast<size_t>(P.rows());
  w.sites = SiteSet(sites);
  w.live.resize(components.size());
  std::int32_t first = 0;
  for (size_t c = 0; c < components.size(); ++c) {
    const LatticePoints& start = components[c];
    const LatticePolygonCheck check = check_lattice_polygon(start);
    const std::string which = components.size() > 1 ? " (component " + std::to_string(c + 1) + ")" : "";
    if (!check.ok) throw InputError("BFACF start: not a self-avoiding lattice polygon" + which + ": " + check.problem);
    const auto n = static_cast<std::int32_t>(start.rows());
    for (std::int32_t i = 0; i < n; ++i) {
      const std::int32_t p[3] = {start(i, 0), start(i, 1), start(i, 2)};
      if (!w.sites.insert(key_of(p)))
        throw InputError("BFACF start: component " + std::to_string(c + 1) + " meets another at site (" +
                         std::to_string(p[0]) + ", " + std::to_string(p[1]) + ", " + std::to_string(p[2]) + ")");
      w.new_node(p, static_cast<std::int16_t>(c));
    }
    for (std::int32_t i = 0; i < n; ++i) {
      const auto u = static_cast<size_t>(first + i), v = static_cast<size_t>(first + (i + 1) % n);
      w.link[u].next = static_cast<std::int32_t>(v);
      w.prev[v] = static_cast<std::int32_t>(u);
      w.link[u].out = w.link[v].in = static_cast<std::int8_t>(step_code(w.pos[u].p, w.pos[v].p));
    }
    first += n;
  }
  impl_->rng = gsl_rng_alloc(gsl_rng_mt19937);
  if (!impl_->rng) throw std::bad_alloc();
  // MT19937 takes a 32-bit seed (0 is replaced by GSL's default 4357): hash the
  // 64-bit seed so that small seeds give unrelated streams.
  unsigned long s = static_cast<unsigned long>(splitmix64(seed) & 0xffffffffull);
  if (s == 0) s = 1;
  gsl_rng_set(impl_->rng, s);
}

BfacfWalk::~BfacfWalk() = default;
BfacfWalk::BfacfWalk(BfacfWalk&&) noexcept = default;
BfacfWalk& BfacfWalk::operator=(BfacfWalk&&) noexcept = default;

int BfacfWalk::length() const { return impl_->length(); }

BfacfMove BfacfWalk::attempt(double beta) {
  check_fugacity(beta);
  const double b2 = beta * beta;
  return impl_->attempt(b2 / (1.0 + b2), 1.0 / (1.0 + b2), kMaxLength);
}

BfacfRunReport BfacfWalk::run(long long attempts, double beta, int max_length) {
  check_fugacity(beta);
  require(attempts >= 0, "BFACF: negative number of attempts");
  require(max_length >= 4, "BFACF: the length cap must be >= 4");
  const auto cap = std::min(static_cast<std::uint32_t>(max_length), kMaxLength);
  const double b2 = beta * beta;
  const double p_plus = b2 / (1.0 + b2), p_minus = 1.0 / (1.0 + b2);
  BfacfRunReport rep;
  rep.start_length = rep.min_length = rep.max_length = length();
  for (long long a = 0; a < attempts; ++a) {
    const BfacfMove m = impl_->attempt(p_plus, p_minus, cap);
    count(rep, m);
    if (m == BfacfMove::I) rep.min_length = std::min(rep.min_length, length());
    if (m == BfacfMove::II) rep.max_length = std::max(rep.max_length, length());
  }
  rep.attempts = attempts;
  rep.end_length = length();
  return rep;
}

BfacfRunReport BfacfWalk::run_to_length(int target, double beta, long long max_attempts, int component) {
  check_fugacity(beta);
  require(target >= 4 && target % 2 == 0, "BFACF: the target length must be even and >= 4");
  require(max_attempts >= 0, "BFACF: negative attempt budget");
  require(component >= -1 && component < components(), "BFACF: no component " + std::to_string(component));
  const double b2 = beta * beta;
  const double p_plus = b2 / (1.0 + b2), p_minus = 1.0 / (1.0 + b2);
  // the length that counts: the component's, or all of the walk's
  auto len = [&] { return component >= 0 ? impl_->length(component) : length(); };
  BfacfRunReport rep;
  rep.start_length = rep.min_length = rep.max_length = len();
  long long a = 0;
  if (len() % 2 == target % 2) {
    const bool grow = len() < target;
    while (len() != target && a < max_attempts) {
      const BfacfMove m = impl_->attempt(p_plus, p_minus, kMaxLength, component);
      ++a;
      count(rep, m);
      if (m == BfacfMove::I) {
        rep.min_length = std::min(rep.min_length, len());
        if (!grow && len() <= target) break;
      } else if (m == BfacfMove::II) {
        rep.max_length = std::max(rep.max_length, len());
        if (grow && len() >= target) break;
      }
    }
  }
  rep.attempts = a;
  rep.end_length = len();
  rep.reached = len() == target;
  return rep;
}

LatticePoints BfacfWalk::polygon() const { return polygon_of(0); }

int BfacfWalk::components() const { return static_cast<int>(impl_->live.size()); }

int BfacfWalk::component_length(int c) const {
  require(c >= 0 && c < components(), "BFACF: no component " + std::to_string(c));
  return impl_->length(c);
}

LatticePoints BfacfWalk::polygon_of(int c) const {
  const int n = component_length(c);
  LatticePoints L(n, 3);
  std::int32_t id = impl_->live[static_cast<size_t>(c)][0];
  for (int k = 0; k < n; ++k) {
    const auto u = static_cast<size_t>(id);
    L.row(k) << impl_->pos[u].p[0], impl_->pos[u].p[1], impl_->pos[u].p[2];
    id = impl_->link[u].next;
  }
  return L;
}

std::vector<LatticePoints> BfacfWalk::polygons() const {
  std::vector<LatticePoints> out;
  for (int c = 0; c < components(); ++c) out.push_back(polygon_of(c));
  return out;
}

}  // namespace ek
