#include "ek/contact/contact_potential.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "ek/core/errors.hpp"

namespace ek {

namespace {

inline std::uint64_t mix(std::uint64_t h, std::uint64_t v) {
  // splitmix64 finaliser of (h ^ v), chained
  std::uint64_t z = h ^ (v + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2));
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

inline Vec3 row(const Points& x, int i) { return x.row(i).transpose(); }

// Whether the boxes of segments [a0, a1] and [b0, b1] of x, inflated by r, overlap.
inline bool boxes_overlap(const Points& x, int a0, int a1, int b0, int b1, double r) {
  const double *pa0 = x.data() + 3 * a0, *pa1 = x.data() + 3 * a1, *pb0 = x.data() + 3 * b0, *pb1 = x.data() + 3 * b1;
  bool overlap = true;
  for (int k = 0; k < 3 && overlap; ++k)
    overlap = std::min(pa0[k], pa1[k]) - r <= std::max(pb0[k], pb1[k]) + r &&
              std::min(pb0[k], pb1[k]) - r <= std::max(pa0[k], pa1[k]) + r;
  return overlap;
}

}  // namespace

void ContactOptions::validate() const {
  require(std::isfinite(dhat) && dhat > 0.0, "ContactOptions: dhat must be positive and finite");
  require(std::isfinite(stiffness) && stiffness >= 0.0, "ContactOptions: stiffness must be >= 0 and finite");
  require(excluded_neighbors >= 1, "ContactOptions: excluded_neighbors must be >= 1 (edges sharing a vertex)");
  require(parallel_threshold >= 0.0 && parallel_threshold < 1.0,
          "ContactOptions: parallel_threshold must be in [0, 1)");
  require(ccd_separation > 0.0 && ccd_separation < 1.0, "ContactOptions: ccd_separation must be in (0, 1)");
  require(ccd_tolerance > 0.0 && ccd_tolerance <= 1.0, "ContactOptions: ccd_tolerance must be in (0, 1]");
  require(ccd_max_iterations >= 1, "ContactOptions: ccd_max_iterations must be >= 1");
  require(std::isfinite(broad_phase_skin) && broad_phase_skin >= 0.0,
          "ContactOptions: broad_phase_skin must be >= 0 and finite");
  require(std::isfinite(hessian_margin) && hessian_margin >= 0.0,
          "ContactOptions: hessian_margin must be >= 0 and finite");
  require(std::isfinite(ccd_skin) && ccd_skin >= 0.0, "ContactOptions: ccd_skin must be >= 0 and finite");
}

ContactPotential::ContactPotential(CurveTopology topology, ContactOptions options)
    : options_((options.validate(), options)),
      n_(topology.num_vertices()),
      broad_(topology, options.excluded_neighbors),
      ccd_broad_(std::move(topology), options.excluded_neighbors) {
  structure_ = mix(0x636f6e74616374ull, static_cast<std::uint64_t>(n_));
  min_distance_ = std::numeric_limits<double>::infinity();
}

void ContactPotential::update(const Points& x) {
  if (x.rows() != n_)  // (checks in hot paths build their message only on failure)
    require(false, "ContactPotential::update: expected " + std::to_string(n_) + " points, got " +
                       std::to_string(x.rows()));
  narrow_phase(x, candidate_pairs(x));
  // The Hessian's pattern: the active set itself (margin 0), or the pairs
  // within d̂ + margin at the last rebuild, rebuilt when an active pair is
  // not among them. active_slot_[k]: index of active pair k in pattern_.
  active_slot_.resize(active_.size());
  if (!(options_.hessian_margin > 0.0 && have_pattern_ && pattern_covers_active())) rebuild_pattern();
  // The Hessian plan is built by add_hessian() when the pattern has changed:
  // the line search calls update() at every trial, and most trials' active
  // sets are never assembled.
}

const std::vector<EdgePair>& ContactPotential::candidate_pairs(const Points& x) {
  const double dhat = options_.dhat;
  const double skin = options_.broad_phase_skin;
  // Reuse the pairs of the last broad phase while no vertex has moved skin/2,
  // or those of the last collision detection's motion while every vertex is
  // within skin/2 of its path (the line search's trials lie on that path).
  const double limit = 0.25 * skin * skin * (1.0 - 1e-9);
  bool reuse = verlet_valid_ && skin > 0.0;
  if (reuse)
    for (int i = 0; i < n_ && reuse; ++i) reuse = (x.row(i) - x_ref_.row(i)).squaredNorm() < limit;
  const std::vector<EdgePair>* list = &verlet_;
  if (!reuse && path_valid_ && skin > 0.0 && on_path(x, limit)) {
    list = &path_pairs_;
    reuse = true;
  }
  if (!reuse) {
    // pairs within d̂ + hessian_margin now, and (with the skin) until a vertex has moved skin/2
    verlet_ = broad_.static_pairs(x, 0.5 * (dhat + options_.hessian_margin + skin));
    x_ref_ = x;
    verlet_valid_ = skin > 0.0;
    ++broad_phase_runs_;
  }
  return *list;
}

bool ContactPotential::on_path(const Points& x, double limit) const {
  bool inside = true;
  for (int i = 0; i < n_ && inside; ++i) {
    const Vec3 p = (x.row(i) - path_x_.row(i)).transpose(), u = path_dx_.row(i).transpose();
    const double uu = u.squaredNorm();
    const double s = uu > 0.0 ? std::clamp(p.dot(u) / uu, 0.0, 1.0) : 0.0;
    inside = (p - s * u).squaredNorm() < limit;
  }
  return inside;
}

void ContactPotential::narrow_phase(const Points& x, const std::vector<EdgePair>& list) {
  const double dhat = options_.dhat;
  const double skin = options_.broad_phase_skin;
  const double margin = options_.hessian_margin;
  active_.clear();
  near_.clear();
  candidates_ = 0;
  double min_d2 = std::numeric_limits<double>::infinity();
  const double r = 0.5 * (dhat + margin);
  const double near2 = (dhat + margin) * (dhat + margin);
  for (const EdgePair& p : list) {
    const int a1 = broad_.edge_end(p.a), b1 = broad_.edge_end(p.b);
    // the boxes of the current segments, inflated by (d̂ + margin)/2, must overlap
    if (skin > 0.0 && !boxes_overlap(x, p.a, a1, p.b, b1, r)) continue;
    ++candidates_;
    ContactPair c;
    c.edge_a = p.a;
    c.edge_b = p.b;
    c.a0 = p.a;
    c.a1 = broad_.edge_end(p.a);
    c.b0 = p.b;
    c.b1 = broad_.edge_end(p.b);
    const EdgeEdgeClosest cl = edge_edge_closest(row(x, c.a0), row(x, c.a1), row(x, c.b0), row(x, c.b1));
    min_d2 = std::min(min_d2, cl.distance_squared);
    if (cl.distance_squared < dhat * dhat) {
      c.type = cl.type;
      c.distance = std::sqrt(cl.distance_squared);
      active_.push_back(c);
    }
    if (margin > 0.0 && cl.distance_squared < near2) near_.push_back(p);
  }
  min_distance_ = std::sqrt(min_d2);
}

bool ContactPotential::pattern_covers_active() {
  bool covered = true;
  size_t q = 0;
  for (size_t k = 0; k < active_.size() && covered; ++k) {
    const EdgePair e{active_[k].edge_a, active_[k].edge_b};
    while (q < pattern_.size() && pattern_[q] < e) ++q;
    covered = q < pattern_.size() && pattern_[q] == e;
    if (covered) active_slot_[k] = static_cast<int>(q);
  }
  return covered;
}

void ContactPotential::rebuild_pattern() {
  if (options_.hessian_margin > 0.0) {
    pattern_ = near_;
  } else {
    pattern_.resize(active_.size());
    for (size_t k = 0; k < active_.size(); ++k) pattern_[k] = EdgePair{active_[k].edge_a, active_[k].edge_b};
  }
  have_pattern_ = true;
  std::uint64_t h = mix(0x636f6e74616374ull, static_cast<std::uint64_t>(n_));
  for (const EdgePair& p : pattern_)
    h = mix(h, (static_cast<std::uint64_t>(static_cast<std::uint32_t>(p.a)) << 32) | static_cast<std::uint32_t>(p.b));
  structure_ = mix(h, pattern_.size());
  // every active pair is in the new pattern (in the same sorted order)
  size_t q = 0;
  for (size_t k = 0; k < active_.size(); ++k) {
    const EdgePair e{active_[k].edge_a, active_[k].edge_b};
    while (pattern_[q] != e) ++q;
    active_slot_[k] = static_cast<int>(q);
  }
}

void ContactPotential::build_hessian_plan() const {
  // keys of the 10 vertex pairs of every active pair, then the distinct keys in
  // sorted order (a deterministic function of the active set)
  struct Key {
    std::uint64_t key;
    int pair, slot;
    bool transposed;
  };
  std::vector<Key> keys;
  keys.reserve(10 * pattern_.size());
  for (size_t p = 0; p < pattern_.size(); ++p) {
    const EdgePair& e = pattern_[p];
    const int v[4] = {e.a, broad_.edge_end(e.a), e.b, broad_.edge_end(e.b)};
    int slot = 0;
    for (int k = 0; k < 4; ++k)
      for (int l = k; l < 4; ++l, ++slot) {
        const int u = std::min(v[k], v[l]), w = std::max(v[k], v[l]);
        keys.push_back({(static_cast<std::uint64_t>(static_cast<std::uint32_t>(u)) << 32) | static_cast<std::uint32_t>(w),
                        static_cast<int>(p), slot, v[k] > v[l]});
      }
  }
  std::sort(keys.begin(), keys.end(), [](const Key& a, const Key& b) { return a.key < b.key; });
  blocks_.clear();
  pair_blocks_.assign(pattern_.size(), {});
  for (size_t i = 0; i < keys.size(); ++i) {
    if (i == 0 || keys[i].key != keys[i - 1].key)
      blocks_.emplace_back(static_cast<int>(keys[i].key >> 32), static_cast<int>(keys[i].key & 0xffffffffu));
    const int b = static_cast<int>(blocks_.size()) - 1;
    pair_blocks_[static_cast<size_t>(keys[i].pair)][static_cast<size_t>(keys[i].slot)] =
        keys[i].transposed ? (b | (1 << 30)) : b;
  }
  block_values_.resize(blocks_.size());
  plan_structure_ = structure_;
}

double ContactPotential::energy(const Points& x) const {
  if (x.rows() != n_) require(false, "ContactPotential::energy: wrong number of points");
  if (active_.empty()) return 0.0;
  const PairBarrierParams params = pair_params();
  double e = 0.0;
  for (const ContactPair& c : active_)
    e += edge_edge_barrier(row(x, c.a0), row(x, c.a1), row(x, c.b0), row(x, c.b1), params);
  return options_.stiffness * e;
}

VecX ContactPotential::gradient(const Points& x) const {
  VecX g = VecX::Zero(3 * static_cast<Eigen::Index>(n_));
  add_gradient(x, g);
  return g;
}

void ContactPotential::add_gradient(const Points& x, Eigen::Ref<VecX> g) const {
  if (x.rows() != n_ || g.size() != 3 * static_cast<Eigen::Index>(n_))
    require(false, "ContactPotential::add_gradient: wrong sizes");
  if (active_.empty()) return;
  const PairBarrierParams params = pair_params();
  const double w = options_.stiffness;
  Vec12 gl;
  for (const ContactPair& c : active_) {
    edge_edge_barrier_derivatives(row(x, c.a0), row(x, c.a1), row(x, c.b0), row(x, c.b1), params, &gl, nullptr, w);
    const int v[4] = {c.a0, c.a1, c.b0, c.b1};
    for (int k = 0; k < 4; ++k) g.segment<3>(3 * v[k]) += gl.segment<3>(3 * k);
  }
}

void ContactPotential::add_hessian(const Points& x, SparseAssembler& A) const {
  add_hessian(x, A, options_.project_psd ? HessianKind::Projected : HessianKind::Exact);
}

void ContactPotential::add_hessian(const Points& x, SparseAssembler& A, HessianKind kind) const {
  const PairHessian pair_kind = kind == HessianKind::Exact ? PairHessian::Exact
                                : options_.gauss_newton_projection ? PairHessian::GaussNewton
                                                                   : PairHessian::Projected;
  if (x.rows() != n_) require(false, "ContactPotential::add_hessian: wrong number of points");
  if (plan_structure_ != structure_ || pair_blocks_.size() != pattern_.size()) build_hessian_plan();
  if (blocks_.empty()) return;
  const PairBarrierParams params = pair_params();
  const double w = options_.stiffness;
  for (Mat3& B : block_values_) B.setZero();
  Mat12 H;
  for (size_t p = 0; p < active_.size(); ++p) {
    const ContactPair& c = active_[p];
    edge_edge_barrier_derivatives(row(x, c.a0), row(x, c.a1), row(x, c.b0), row(x, c.b1), params, nullptr, &H, w,
                                  pair_kind);
    const auto& plan = pair_blocks_[static_cast<size_t>(active_slot_[p])];
    int slot = 0;
    for (int k = 0; k < 4; ++k)
      for (int l = k; l < 4; ++l, ++slot) {
        const int b = plan[static_cast<size_t>(slot)];
        if (b & (1 << 30))
          block_values_[static_cast<size_t>(b & ~(1 << 30))] += H.block<3, 3>(3 * k, 3 * l).transpose();
        else
          block_values_[static_cast<size_t>(b)] += H.block<3, 3>(3 * k, 3 * l);
      }
  }
  // A diagonal vertex block gets one copy of H_kk per pair, an off-diagonal
  // block (u < v) the H_kl with v_k = u, v_l = v: exactly the upper triangle.
  for (size_t b = 0; b < blocks_.size(); ++b) {
    const int u = blocks_[b].first, v = blocks_[b].second;
    const Mat3& B = block_values_[b];
    if (u == v) {
      for (int i = 0; i < 3; ++i)
        for (int j = i; j < 3; ++j) A.add(3 * u + i, 3 * u + j, B(i, j));
    } else {
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) A.add(3 * u + i, 3 * v + j, B(i, j));
    }
  }
}

StepReport ContactPotential::max_step_report(const Points& x, const Points& dx) const {
  if (x.rows() != n_ || dx.rows() != n_)
    require(false, "ContactPotential::max_step: x and dx need " + std::to_string(n_) + " rows");
  StepReport rep;
  const double sep = options_.ccd_separation;
  const double skin = options_.broad_phase_skin;
  // With a skin, the broad phase collects the pairs whose swept boxes come
  // within d̂ + hessian_margin + skin: update() reuses them at any point
  // within skin/2 of the path (the line search's trials), and the pairs
  // tested here are their subset within ccd_separation·d̂ (the same list as a
  // broad phase of its own).
  if (skin > 0.0) {
    const double inflation = 0.5 * (options_.dhat + options_.hessian_margin + skin);
    if (options_.ccd_skin > 0.0) {
      if (sweep_box_.empty() || !sweep_covers(x, dx)) keep_sweep(x, dx, inflation + options_.ccd_skin);
      path_pairs_ = ccd_broad_.swept_subset(sweep_pairs_, x, dx, inflation);
    } else {
      path_pairs_ = ccd_broad_.swept_pairs(x, dx, inflation);
      ++swept_broad_phase_runs_;
    }
    path_x_ = x;
    path_dx_ = dx;
    path_valid_ = true;
  }
  const auto& pairs = skin > 0.0 ? ccd_broad_.swept_subset(path_pairs_, x, dx, 0.5 * sep * options_.dhat)
                                 : ccd_broad_.swept_pairs(x, dx, 0.5 * sep * options_.dhat);
  rep.candidates = static_cast<int>(pairs.size());
  CcdParams params;
  params.separation = sep;
  params.distance_cap = options_.dhat;
  params.tolerance = options_.ccd_tolerance;
  params.max_iterations = options_.ccd_max_iterations;
  double t = 1.0;
  for (const EdgePair& p : pairs) {
    const int a0 = p.a, a1 = ccd_broad_.edge_end(p.a), b0 = p.b, b1 = ccd_broad_.edge_end(p.b);
    const CcdResult r = edge_edge_ccd(row(x, a0), row(x, a1), row(x, b0), row(x, b1), row(dx, a0), row(dx, a1),
                                      row(dx, b0), row(dx, b1), t, params);
    rep.iterations += r.iterations + 1;
    if (r.t < t) {
      t = r.t;
      rep.edge_a = p.a;
      rep.edge_b = p.b;
      rep.start_distance = r.distance;
      rep.floor = r.floor;
    }
    if (t <= 0.0) break;
  }
  rep.t = t;
  return rep;
}

void ContactPotential::keep_sweep(const Points& x, const Points& dx, double inflation) const {
  sweep_pairs_ = ccd_broad_.swept_pairs(x, dx, inflation);
  sweep_box_.resize(6 * static_cast<size_t>(n_));
  for (int i = 0; i < n_; ++i)
    for (int k = 0; k < 3; ++k) {
      sweep_box_[6 * i + k] = std::min(x(i, k), x(i, k) + dx(i, k));
      sweep_box_[6 * i + 3 + k] = std::max(x(i, k), x(i, k) + dx(i, k));
    }
  ++swept_broad_phase_runs_;
}

// Every start and end point of the query within ccd_skin of its vertex's box
// when the kept pairs were found, per axis. Each edge's swept box, inflated
// by r, then lies within its box then, inflated by r + ccd_skin, so a pair
// that overlaps now overlapped then. The boxes widen by a few ulps of the
// coordinates (at most 16 ε·m, m the largest |coordinate| or |step|): the
// reach is short of ccd_skin by 1e-6 of it, which must exceed that.
bool ContactPotential::sweep_covers(const Points& x, const Points& dx) const {
  const double reach = options_.ccd_skin * (1.0 - 1e-6);
  double m = 0.0;
  for (int i = 0; i < n_; ++i)
    for (int k = 0; k < 3; ++k) {
      const double a = x(i, k), b = x(i, k) + dx(i, k);
      if (std::min(a, b) < sweep_box_[6 * i + k] - reach || std::max(a, b) > sweep_box_[6 * i + 3 + k] + reach)
        return false;
      m = std::max({m, std::abs(a), std::abs(b), std::abs(dx(i, k))});
    }
  return 1e-6 * options_.ccd_skin > 16.0 * std::numeric_limits<double>::epsilon() * m;
}

double ContactPotential::max_step(const Points& x, const Points& dx) const { return max_step_report(x, dx).t; }

double max_step(const Points& x, const Points& dx, const CurveTopology& topology, const ContactOptions& options) {
  return ContactPotential(topology, options).max_step(x, dx);
}

}  // namespace ek
