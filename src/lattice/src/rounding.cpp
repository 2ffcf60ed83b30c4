#include "ek/lattice/rounding.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <vector>

#include "ek/core/errors.hpp"
#include "ek/core/hash.hpp"
#include "ek/geometry/curve_io.hpp"
#include "ek/geometry/polyline.hpp"
#include "ek/knots/alexander.hpp"

// Proof of the theorem in rounding.hpp.
//
// Notation: Q = s·R·P with edges E_i (m of them, W <= m/2), L the lattice
// polygon. Every step of L was made by the cell walk at a crossing point c on
// some edge of Q. The correspondence φ: Q → L is continuous: it runs along a
// step while x passes a short interval J_c of length η next to c inside the
// edge that made the step (steps made at one point get consecutive intervals),
// and it is constant, equal to the site r, on the arc G_r of Q between the
// intervals of the steps entering and leaving r (the cell's stretch of Q and
// any loops cut out there). Its displacement is at most the measured δ plus η;
// take η so small that s·c_W > 2(δ + η), and write δ for δ + η below.
//
// Straight-line homotopy H_t(x) = (1 − t)·x + t·φ(x). On the common
// subdivision of Q and φ both maps are linear, so every H_t is a closed
// polygon whose vertices move continuously with t. Let x ≠ y be points of Q,
// x ∈ E_i, y ∈ E_j, and t < 1.
//  (a) The cyclic index distance of i and j is >= W: |x − y| >= s·c_W > 2δ,
//      so |H_t(x) − H_t(y)| >= |x − y| − 2tδ > 0.
//  (b) It is < W: the shorter chain of edges from E_i to E_j has at most W
//      edges, so they share a coordinate k and a sign σ with σ·d_k > 0 on all
//      of them, and σ(y_k − x_k) > 0 along the arc from x to y in the chain.
//      φ(y) − φ(x) is a sum of (parts of) steps of L whose intervals J_c meet
//      that arc, so they were made on edges of the chain, on which
//      floor(x_k + 1/2) is monotone in the direction σ (a step made at a
//      vertex by the neighbouring edge outside the chain has the same sign, or
//      is followed by its back-track and both are erased). So
//      σ(φ(y)_k − φ(x)_k) >= 0 and
//         H_t(y)_k − H_t(x)_k = (1 − t)(y_k − x_k) + t(φ(y)_k − φ(x)_k) ≠ 0.
// Hence H_t is an embedded polygon for every t < 1, of the knot type of Q.
// At t = 1, H_1 = φ is injective except that each arc G_r collapses to its
// site. All points of G_r are within δ of r, hence within 2δ of each other, so
// by (a) G_r lies on at most W consecutive edges and is strictly monotone in
// their common coordinate: an unknotted arc. For t close to 1, H_t maps G_r to
// a copy of G_r scaled by 1 − t next to r and is within (1 − t)δ of L
// elsewhere; contracting these small unknotted arcs is an isotopy onto L. So
// L has the knot type of Q, which is that of P.                          ∎
//
// Bounds on δ. Before loop erasure every coordinate of x and of its site
// differ by at most 1/2 (at a crossing the crossing coordinate sits exactly
// half-way between the two sites), so δ₀ <= √3/2. A loop that closes at site r
// is entered at x and left at y with |x − r|, |y − r| <= δ₀, so |x − y| <= 2δ₀.
// With W = 2 and s·c_2 > 2δ₀, (a) puts x and y on adjacent edges (the walk
// along one edge never repeats a site) around a corner p with turning angle
// θ; for θ <= 90° the cut arc is the V x, p, y, whose height over the chord
// [x, y] is at most (|x − y|/2)·tan(θ/2), and |x − p| <= |x − y| <= 2δ₀ (the
// angle at p is >= 90°). So with the walk's start at the midpoint of an edge
// longer than 4δ₀ no cut arc contains the start, δ <= δ₀·(1 + tan(θ_max/2)),
// and the scale
//      s > max( 2·(√3/2)·(1 + tan(θ_max/2)) / c_2 ,  4·(√3/2) / ℓ_max )
// is certified a priori. round_to_lattice starts from the optimistic
// s = 2·(√3/2)/c_W with the largest window W the curve allows (c_W can exceed
// the edge length, which bounds c_2), checks s·c_W > 2δ with the measured δ,
// enlarges s when it fails, and after half of its attempts falls back to
// W = 2 with at least this a-priori scale.

namespace ek {

namespace {

constexpr double kHalfDiagonal = 0.86602540378443865;  // √3/2
constexpr double kMaxWalkSteps = 1e7;                  // larger cell walks are refused

double unit_uniform(std::uint64_t& state) { return splitmix64_uniform(state); }

// Uniform random rotation (Shoemake's unit quaternion).
Mat3 random_rotation_matrix(std::uint64_t& state) {
  const double u1 = unit_uniform(state), u2 = unit_uniform(state), u3 = unit_uniform(state);
  const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1);
  Eigen::Quaterniond q(b * std::cos(2 * M_PI * u3), a * std::sin(2 * M_PI * u2), a * std::cos(2 * M_PI * u2),
                       b * std::sin(2 * M_PI * u3));
  return q.normalized().toRotationMatrix();
}

Points rotated(const Points& P, const Mat3& R) { return P * R.transpose(); }

struct Site {
  std::int32_t p[3];
  std::uint64_t key() const { return site_key(p[0], p[1], p[2]); }
  double distance_to(const Vec3& x) const {
    return std::sqrt((x[0] - p[0]) * (x[0] - p[0]) + (x[1] - p[1]) * (x[1] - p[1]) + (x[2] - p[2]) * (x[2] - p[2]));
  }
};

Site round_site(const Vec3& x) {
  Site s;
  for (int k = 0; k < 3; ++k) {
    const double r = std::floor(x[k] + 0.5);
    require(std::abs(r) < 1e9, "lattice rounding: coordinates too large for the lattice (scale too big)");
    s.p[k] = static_cast<std::int32_t>(r);
  }
  return s;
}

struct Event {
  double tau;
  int axis;
  int dir;
};

/// The cell walk along a polygon: key points (crossings of cell boundaries
/// and polygon vertices) in curve order, and the walk's sites with the key
/// index at which each is entered.
struct CellWalk {
  std::vector<Vec3> keys;
  std::vector<Site> walk;
  std::vector<int> arrive;
  Site cur;                   // the current site
  std::vector<Event> events;  // scratch of piece()

  /// Starts at the point S, in its cell.
  explicit CellWalk(const Vec3& S, int m) : cur(round_site(S)) {
    keys.reserve(static_cast<size_t>(4 * m));
    keys.push_back(S);
    walk.push_back(cur);
    arrive.push_back(0);
  }

  /// Walks the straight piece A -> B (A is the last key): one step at every
  /// crossing of a cell boundary, in order along the piece (ties by axis).
  void piece(const Vec3& A, const Vec3& B) {
    events.clear();
    for (int k = 0; k < 3; ++k) {
      const double a = A[k], b = B[k];
      if (a == b) continue;
      const long long ca = static_cast<long long>(std::floor(a + 0.5));
      const long long cb = static_cast<long long>(std::floor(b + 0.5));
      for (long long c = ca; c < cb; ++c)
        events.push_back({std::clamp((static_cast<double>(c) + 0.5 - a) / (b - a), 0.0, 1.0), k, +1});
      for (long long c = ca; c > cb; --c)
        events.push_back({std::clamp((static_cast<double>(c) - 0.5 - a) / (b - a), 0.0, 1.0), k, -1});
    }
    std::sort(events.begin(), events.end(),
              [](const Event& x, const Event& y) { return x.tau < y.tau || (x.tau == y.tau && x.axis < y.axis); });
    for (const Event& ev : events) {
      keys.push_back(A + ev.tau * (B - A));
      cur.p[ev.axis] += ev.dir;
      walk.push_back(cur);
      arrive.push_back(static_cast<int>(keys.size()) - 1);
    }
    keys.push_back(B);
  }

  /// [lattice units] largest distance from site s to the keys from .. to.
  double range_max(const Site& s, int from, int to) const {
    double d = 0.0;
    for (int q = from; q <= to; ++q) d = std::max(d, s.distance_to(keys[static_cast<size_t>(q)]));
    return d;
  }
};

/// Index j of the longest edge [Q_j, Q_{j+1}] (the first of equals).
int longest_edge(const Points& Q) {
  const int m = static_cast<int>(Q.rows());
  int j0 = 0;
  double lmax = -1.0;
  for (int i = 0; i < m; ++i) {
    const double l = (Q.row((i + 1) % m) - Q.row(i)).norm();
    if (l > lmax) lmax = l, j0 = i;
  }
  return j0;
}

/// The cell walk once around the closed polygon Q, from and back to the
/// point S on its edge j0.
CellWalk cell_walk(const Points& Q, int j0, const Vec3& S) {
  const int m = static_cast<int>(Q.rows());
  CellWalk w(S, m);
  w.piece(S, Q.row((j0 + 1) % m).transpose());
  for (int e = 1; e < m; ++e) {
    const int i = (j0 + e) % m;
    w.piece(Q.row(i).transpose(), Q.row((i + 1) % m).transpose());
  }
  w.piece(Q.row(j0).transpose(), S);
  return w;
}

/// The loop-erased walk: its sites and the key index at which each is entered.
struct ErasedWalk {
  std::vector<Site> path;
  std::vector<int> arrive;
  int loops_erased = 0;
};

/// Chronological loop erasure of w_0 .. w_{N-1} (w_N = w_0 closes the polygon).
ErasedWalk erase_loops(const CellWalk& w, int N) {
  ErasedWalk out;
  std::unordered_map<std::uint64_t, int> where;
  where.reserve(static_cast<size_t>(2 * N));
  for (int a = 0; a < N; ++a) {
    const Site& site = w.walk[static_cast<size_t>(a)];
    const auto it = where.find(site.key());
    if (it != where.end()) {
      const int q = it->second;
      while (static_cast<int>(out.path.size()) > q + 1) {
        where.erase(out.path.back().key());
        out.path.pop_back();
        out.arrive.pop_back();
      }
      ++out.loops_erased;
    } else {
      where.emplace(site.key(), static_cast<int>(out.path.size()));
      out.path.push_back(site);
      out.arrive.push_back(w.arrive[static_cast<size_t>(a)]);
    }
  }
  return out;
}

/// [lattice units] δ₀: the largest distance of a walk site to the keys of its
/// stretch, before loop erasure (w_0 also owns the tail from w_N back to S).
double walk_displacement(const CellWalk& w, int N) {
  const int K = static_cast<int>(w.keys.size());
  double d = 0.0;
  for (int a = 0; a < N; ++a)
    d = std::max(d, w.range_max(w.walk[static_cast<size_t>(a)], w.arrive[static_cast<size_t>(a)],
                                w.arrive[static_cast<size_t>(a) + 1]));
  return std::max(d, w.range_max(w.walk[0], w.arrive[static_cast<size_t>(N)], K - 1));
}

/// [lattice units] δ after loop erasure. Preimage of path entry q: keys
/// [arrive_q, arrive_{q+1}]; the last entry's ends where the walk returns to
/// w_0, and w_0 also owns the tail up to S.
double erased_displacement(const CellWalk& w, const ErasedWalk& e, int N) {
  const int K = static_cast<int>(w.keys.size());
  const int M = static_cast<int>(e.path.size());
  double d = 0.0;
  for (int q = 0; q < M; ++q) {
    const int to = q + 1 < M ? e.arrive[static_cast<size_t>(q) + 1] : w.arrive[static_cast<size_t>(N)];
    d = std::max(d, w.range_max(e.path[static_cast<size_t>(q)], e.arrive[static_cast<size_t>(q)], to));
  }
  return std::max(d, w.range_max(e.path[0], w.arrive[static_cast<size_t>(N)], K - 1));
}

}  // namespace

int monotone_window(const Points& P, int max_window, double min_direction_cosine) {
  const int m = static_cast<int>(P.rows());
  require(m >= 4, "monotone_window: need at least 4 vertices");
  require(max_window >= 1, "monotone_window: max_window must be >= 1");
  std::vector<Vec3> d(static_cast<size_t>(m));
  for (int i = 0; i < m; ++i) {
    const Vec3 e = (P.row((i + 1) % m) - P.row(i)).transpose();
    const double len = e.norm();
    if (!(len > 0.0)) return 0;
    d[static_cast<size_t>(i)] = e / len;
  }
  std::vector<int> best(static_cast<size_t>(m), 0);
  for (int k = 0; k < 3; ++k)
    for (int sign = -1; sign <= 1; sign += 2) {
      int run = 0;
      for (int i = 2 * m - 1; i >= 0; --i) {
        const bool marked = sign * d[static_cast<size_t>(i % m)][k] >= min_direction_cosine;
        run = marked ? std::min(run + 1, m) : 0;
        if (i < m) best[static_cast<size_t>(i)] = std::max(best[static_cast<size_t>(i)], run);
      }
    }
  int W = *std::min_element(best.begin(), best.end());
  return std::min({W, max_window, m / 2});
}

RoundingResult lattice_walk_of(const Points& P, double scale, const Mat3& rotation) {
  const int m = static_cast<int>(P.rows());
  require(m >= 4, "lattice walk: need at least 4 vertices");
  require(std::isfinite(scale) && scale > 0.0, "lattice walk: the scale must be positive");
  const Points Q = rotated(P, rotation) * scale;
  const int j0 = longest_edge(Q);
  const Vec3 S = 0.5 * (Q.row(j0) + Q.row((j0 + 1) % m)).transpose();
  const CellWalk w = cell_walk(Q, j0, S);
  const int N = static_cast<int>(w.walk.size()) - 1;  // w_N = w_0
  const int K = static_cast<int>(w.keys.size());
  if (w.walk[static_cast<size_t>(N)].key() != w.walk[0].key())
    throw std::logic_error("lattice walk: the cell walk does not close");

  RoundingResult res;
  res.scale = scale;
  res.rotation = rotation;
  res.walk_length = N;
  res.walk_displacement = walk_displacement(w, N);
  res.max_turning_angle = turning_angles(P).maxCoeff();
  if (N < 4) {  // the whole curve within a few cells: every point goes to w_0
    res.defect = "the cell walk has only " + std::to_string(N) + " steps";
    res.displacement = w.range_max(w.walk[0], 0, K - 1);
    res.points.resize(1, 3);
    for (int k = 0; k < 3; ++k) res.points(0, k) = w.walk[0].p[k];
    return res;
  }

  const ErasedWalk e = erase_loops(w, N);
  res.loops_erased = e.loops_erased;
  const int M = static_cast<int>(e.path.size());
  if (M >= kMaxLatticeLength)
    throw InputError("lattice rounding: the lattice polygon would have " + std::to_string(M) +
                     " vertices, more than the limit " + std::to_string(kMaxLatticeLength) +
                     "; the curve's clearance is too small for its length");
  res.displacement = erased_displacement(w, e, N);
  res.points.resize(M, 3);
  for (int q = 0; q < M; ++q)
    for (int k = 0; k < 3; ++k) res.points(q, k) = e.path[static_cast<size_t>(q)].p[k];
  const LatticePolygonCheck check = check_lattice_polygon(res.points);
  if (!check.ok) res.defect = "loop erasure left a defect: " + check.problem;
  return res;
}

RoundingResult round_to_lattice(const Points& P, const RoundingOptions& o,
                                const std::optional<AlexanderPolynomial>& expected) {
  require(std::isfinite(o.margin) && o.margin > 0.0, "lattice rounding: margin must be positive");
  require(o.max_window >= 2, "lattice rounding: max_window must be >= 2");
  require(o.min_direction_cosine > 0.0 && o.min_direction_cosine < 0.5,
          "lattice rounding: min_direction_cosine must be in (0, 0.5)");
  require(o.max_attempts >= 1 && o.rotation_attempts >= 0, "lattice rounding: attempt counts must be positive");
  validate_closed_curve(P, "lattice rounding");

  std::optional<AlexanderPolynomial> want = expected;
  if (o.verify && !want) want = alexander(P);

  // A rotation under which every corner has a common monotone coordinate.
  Mat3 R = Mat3::Identity();
  std::uint64_t rot_state = o.rotation_seed;
  int W = monotone_window(P, o.max_window, o.min_direction_cosine);
  for (int r = 0; W < 2 && r < o.rotation_attempts; ++r) {
    R = random_rotation_matrix(rot_state);
    W = monotone_window(rotated(P, R), o.max_window, o.min_direction_cosine);
  }
  if (W < 2) {
    const VecX theta = turning_angles(P);
    Eigen::Index at = 0;
    const double tmax = theta.maxCoeff(&at);
    throw InputError("lattice rounding: the corner at vertex " + std::to_string(at) + " turns by " +
                     std::to_string(tmax * 180.0 / M_PI) +
                     " degrees and no rotation gives its two edges a common monotone coordinate; "
                     "use a more finely sampled curve");
  }
  const double lmax = edge_lengths(P).maxCoeff();
  double cW = clearance(P, W).distance;  // rotation-invariant
  const double diagonal = (P.colwise().maxCoeff() - P.colwise().minCoeff()).norm();
  if (!(cW > 1e-9 * diagonal))
    throw InputError("lattice rounding: the curve intersects itself (clearance " + std::to_string(cW) + " at size " +
                     std::to_string(diagonal) + ")");
  // optimistic first scale (δ = δ₀'s bound); the certificate decides
  double s = (1.0 + o.margin) * 2.0 * kHalfDiagonal / cW;
  double l1_length = 0.0;  // the cell walk has about s·Σ|e_i|₁ steps
  for (Eigen::Index i = 0; i < P.rows(); ++i) l1_length += (P.row((i + 1) % P.rows()) - P.row(i)).lpNorm<1>();
  if (s * l1_length > kMaxWalkSteps)
    throw InputError("lattice rounding: the curve's clearance " + std::to_string(cW) +
                     " is too small for its length: the lattice polygon would have about " +
                     std::to_string(s * l1_length) + " edges");

  RoundingResult res;
  bool certified = false;
  int attempts = 0;
  for (; attempts < o.max_attempts && !certified; ++attempts) {
    if (W > 2 && attempts == o.max_attempts / 2) {
      // fall back to W = 2 and its a-priori scale (see the proof above)
      W = 2;
      cW = clearance(P, 2).distance;
      const double tmax = turning_angles(P).maxCoeff();
      const double apriori = 2.0 * kHalfDiagonal * (1.0 + std::tan(std::min(tmax, 0.5 * M_PI) / 2.0)) / cW;
      s = std::max(s, (1.0 + o.margin) * std::max(apriori, 4.0 * kHalfDiagonal / lmax));
    }
    res = lattice_walk_of(P, s, R);
    // strict inequality s·c_W > 2δ, with room for rounding errors of the measurement
    certified = s * cW > 2.0 * res.displacement * (1.0 + 1e-12) + 1e-12;
    if (certified && !res.defect.empty())  // excluded by the theorem: a bug, not bad input
      throw std::logic_error("lattice rounding: certified scale " + std::to_string(s) + " but " + res.defect);
    // A defect means a cut loop swallowed most of the curve at a scale far too
    // small; its δ measures that loop, not the walk, so only grow by 1.25x.
    if (!certified)
      s = res.defect.empty() ? std::max(1.25 * s, (1.0 + o.margin) * 2.0 * res.displacement / cW) : 1.25 * s;
    if (!certified && s * l1_length > kMaxWalkSteps) break;
  }
  if (!certified)
    throw InputError("lattice rounding: no certified scale found in " + std::to_string(o.max_attempts) +
                     " attempts (last scale " + std::to_string(s) + ", displacement " +
                     std::to_string(res.displacement) + ")");
  res.attempts = attempts;
  res.window = W;
  res.window_clearance = cW;
  res.certificate_ratio = res.scale * cW / (2.0 * res.displacement);

  if (want) {
    const AlexanderPolynomial got = alexander(to_points(res.points));
    if (got != *want)
      throw TopologyError("lattice rounding: Alexander polynomial " + got.to_string() + " of the lattice polygon (" +
                          std::to_string(res.points.rows()) + " vertices) differs from the expected " +
                          want->to_string());
  }
  return res;
}

std::vector<RoundingResult> round_link_to_lattice(const Link& link, const RoundingOptions& o) {
  require(o.max_attempts >= 1 && o.rotation_attempts >= 0, "lattice rounding: attempt counts must be positive");
  const double d = validate_link(link, "lattice rounding");
  // one rotation under which every corner of every component has a common monotone coordinate
  Mat3 R = Mat3::Identity();
  std::uint64_t rot_state = o.rotation_seed;
  auto windows = [&](const Mat3& rot) {
    std::vector<int> W;
    for (const Points& P : link) W.push_back(monotone_window(rotated(P, rot), o.max_window, o.min_direction_cosine));
    return W;
  };
  std::vector<int> W = windows(R);
  for (int r = 0; *std::min_element(W.begin(), W.end()) < 2 && r < o.rotation_attempts; ++r) {
    R = random_rotation_matrix(rot_state);
    W = windows(R);
  }
  if (*std::min_element(W.begin(), W.end()) < 2)
    throw InputError("lattice rounding: no rotation gives every corner of the link a common monotone coordinate; "
                     "use more finely sampled components");
  std::vector<double> cW;
  double c = d;  // the smallest clearance the certificate needs
  for (size_t k = 0; k < link.size(); ++k) {
    cW.push_back(clearance(link[k], W[k]).distance);
    c = std::min(c, cW.back());
  }
  double s = (1.0 + o.margin) * 2.0 * kHalfDiagonal / c;
  std::vector<RoundingResult> out(link.size());
  for (int attempt = 1; attempt <= o.max_attempts; ++attempt) {
    double delta = 0.0;
    bool certified = true;
    for (size_t k = 0; k < link.size(); ++k) {
      out[k] = lattice_walk_of(link[k], s, R);
      delta = std::max(delta, out[k].displacement);
      certified = certified && out[k].defect.empty() &&
                  s * cW[k] > 2.0 * out[k].displacement * (1.0 + 1e-12) + 1e-12;
    }
    // the components' δ-tubes stay disjoint: s·d > 2δ
    certified = certified && s * d > 2.0 * delta * (1.0 + 1e-12) + 1e-12;
    if (certified) {
      for (size_t k = 0; k < link.size(); ++k) {
        out[k].attempts = attempt;
        out[k].window = W[k];
        out[k].window_clearance = cW[k];
        out[k].certificate_ratio = s * std::min(cW[k], d) / (2.0 * delta);
      }
      return out;
    }
    s = std::max(1.25 * s, (1.0 + o.margin) * 2.0 * delta / c);
  }
  throw InputError("lattice rounding: no certified scale for the link in " + std::to_string(o.max_attempts) +
                   " attempts (last scale " + std::to_string(s) + ")");
}

}  // namespace ek
