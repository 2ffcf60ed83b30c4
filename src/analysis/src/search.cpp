#include "ek/analysis/search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ek/core/errors.hpp"
#include "ek/geometry/resample.hpp"
#include "ek/geometry/rigid.hpp"
#include "ek/geometry/nearest_segment.hpp"

namespace ek {

namespace {

Points centred(const Points& P) { return P.rowwise() - P.colwise().mean(); }

/// Symmetric RMS of point-to-polygon distances between two closed polygons.
double symmetric_rms(const Points& A, const Points& B) {
  auto one_way = [](const Points& X, const Points& P) {
    const NearestSegment segments(P);
    double sum = 0.0;
    for (Eigen::Index i = 0; i < X.rows(); ++i) sum += segments.nearest(X.row(i).transpose()).distance_squared;
    return sum;
  };
  return std::sqrt((one_way(A, B) + one_way(B, A)) / static_cast<double>(A.rows() + B.rows()));
  // (vertices of A to the polygon B and vertices of B to the polygon A)
}

/// Closest point on the closed polygon `segments` (of the vertices P) to x;
/// writes the unit direction of its segment.
Vec3 closest_on_polygon(const Vec3& x, const Points& P, const NearestSegment& segments, Vec3* tangent = nullptr) {
  const NearestSegmentHit hit = segments.nearest(x);
  const Vec3 a = P.row(hit.segment).transpose(), e = P.row((hit.segment + 1) % P.rows()).transpose() - a;
  if (tangent) *tangent = e.norm() > 0.0 ? Vec3(e.normalized()) : Vec3::Zero();
  return a + hit.t * e;
}

struct Start {
  double residual;
  int symmetry;  // bit 0: reversed, bit 1: mirrored
  int shift;
};

Points apply_symmetry(const Points& C, int symmetry) {
  Points S = C;
  if (symmetry & 1) S = C.colwise().reverse().eval();
  if (symmetry & 2) S.col(0) *= -1.0;
  return S;
}

/// The closed-form residual of every (symmetry, shift)
/// correspondence; the local minima over the shift, best first, at most
/// options.refine_starts of them.
std::vector<Start> closed_form_starts(const Points& Qc, const Points& C, const AlignmentOptions& options) {
  const int m = options.samples;
  const double q2 = Qc.squaredNorm();
  std::vector<int> symmetries = {0};
  if (options.reversal) symmetries.push_back(1);
  if (options.mirror) symmetries.push_back(2);
  if (options.reversal && options.mirror) symmetries.push_back(3);
  std::vector<Start> starts;
  for (int sym : symmetries) {
    const Points Cc = centred(apply_symmetry(C, sym));
    const double c2 = Cc.squaredNorm();
    std::vector<double> r(static_cast<size_t>(m));
    for (int s = 0; s < m; ++s) {
      Mat3 H = Mat3::Zero();
      for (int i = 0; i < m; ++i) H += Cc.row((i + s) % m).transpose() * Qc.row(i);
      r[static_cast<size_t>(s)] = std::max(0.0, rigid_residual(H, q2 + c2));
    }
    for (int s = 0; s < m; ++s) {
      const double v = r[static_cast<size_t>(s)];
      if (v <= r[static_cast<size_t>((s + m - 1) % m)] && v <= r[static_cast<size_t>((s + 1) % m)])
        starts.push_back({v, sym, s});
    }
  }
  std::stable_sort(starts.begin(), starts.end(), [](const Start& a, const Start& b) { return a.residual < b.residual; });
  if (static_cast<int>(starts.size()) > options.refine_starts) starts.resize(static_cast<size_t>(options.refine_starts));
  return starts;
}

/// Nearest neighbours both ways between two point sets of m points each
/// (brute force, O(m²)): squared distances and indices.
struct NearestPairs {
  std::vector<double> bq, by;  // Q_i to its nearest Y, Y_j to its nearest Q
  std::vector<int> iq, iy;
};

NearestPairs nearest_both_ways(const Points& Q, const Points& Y) {
  const int m = static_cast<int>(Q.rows());
  NearestPairs p;
  p.bq.assign(static_cast<size_t>(m), std::numeric_limits<double>::infinity());
  p.by = p.bq;
  p.iq.assign(static_cast<size_t>(m), 0);
  p.iy.assign(static_cast<size_t>(m), 0);
  for (int i = 0; i < m; ++i) {
    for (int j = 0; j < m; ++j) {
      const double d2 = (Q.row(i) - Y.row(j)).squaredNorm();
      if (d2 < p.bq[static_cast<size_t>(i)]) {
        p.bq[static_cast<size_t>(i)] = d2;
        p.iq[static_cast<size_t>(i)] = j;
      }
      if (d2 < p.by[static_cast<size_t>(j)]) {
        p.by[static_cast<size_t>(j)] = d2;
        p.iy[static_cast<size_t>(j)] = i;
      }
    }
  }
  return p;
}

/// One symmetric ICP refinement: the rigid motion (R, t) of the candidate and
/// the moved resampled candidate Y.
struct IcpResult {
  Mat3 R;
  Vec3 t;
  Points Y;
  int iterations = 0;
  AlignmentStatus status = AlignmentStatus::MaxIterations;
};

/// Symmetric point-to-point ICP of the resampled
/// candidate C (under the start's symmetry) onto Q, from the Kabsch motion of
/// the start's correspondence.
IcpResult icp_from_start(const Points& Q, const Points& C, const Start& st, const AlignmentOptions& options) {
  const int m = options.samples;
  Points src(2 * m, 3), dst(2 * m, 3);
  const Points S = apply_symmetry(C, st.symmetry);
  Points rolled(m, 3);
  for (int i = 0; i < m; ++i) rolled.row(i) = S.row((i + st.shift) % m);
  IcpResult out;
  const RigidMotion start = best_rigid_motion(rolled, Q);
  out.R = start.R;
  out.t = start.t;
  out.Y = start.apply(S);
  double prev = std::numeric_limits<double>::infinity();
  int& it = out.iterations;
  for (;; ++it) {
    const NearestPairs nn = nearest_both_ways(Q, out.Y);
    double mse = 0.0;
    for (int k = 0; k < m; ++k) mse += nn.bq[static_cast<size_t>(k)] + nn.by[static_cast<size_t>(k)];
    mse /= 2.0 * m;
    if (prev - mse <= options.relative_tolerance * mse) {
      out.status = AlignmentStatus::Converged;
      break;
    }
    if (it >= options.max_iterations) break;
    prev = mse;
    for (int k = 0; k < m; ++k) {
      src.row(k) = out.Y.row(nn.iq[static_cast<size_t>(k)]);
      dst.row(k) = Q.row(k);
      src.row(m + k) = out.Y.row(k);
      dst.row(m + k) = Q.row(nn.iy[static_cast<size_t>(k)]);
    }
    const RigidMotion step = best_rigid_motion(src, dst);
    const Mat3& G = step.R;
    const Vec3& g = step.t;
    out.Y = step.apply(out.Y);
    out.R = G * out.R;
    out.t = G * out.t + g;
  }
  return out;
}

/// Gauss-Newton normal equations of the point-to-line residuals, for the
/// small motion (ω, τ) about the centre c.
struct PointToLine {
  Vec3 c;
  Eigen::Matrix<double, 6, 6> A = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 1> b = Eigen::Matrix<double, 6, 1>::Zero();

  /// Pair (y moving with C, x fixed on Q, unit tangent tg of the segment of the closest point).
  void add_pair(const Vec3& y, const Vec3& x, const Vec3& tg) {
    const Mat3 Pp = Mat3::Identity() - tg * tg.transpose();
    Eigen::Matrix<double, 3, 6> J;
    const Vec3 r = y - c;
    J.leftCols<3>() << 0.0, r.z(), -r.y(), -r.z(), 0.0, r.x(), r.y(), -r.x(), 0.0;  // ω × r = -[r]× ω
    J.rightCols<3>() = Mat3::Identity();
    const Eigen::Matrix<double, 3, 6> PJ = Pp * J;
    A += PJ.transpose() * PJ;
    b -= PJ.transpose() * (Pp * (y - x));
  }
};

/// One point-to-line Gauss-Newton step of the polishing: Csym and
/// Cres are the original and the resampled candidate under the best
/// symmetry, `to_query` the segments of `query`. Updates best's motion;
/// returns false once the step is below rounding (relative to `scale`).
bool polish_step(const Points& query, const NearestSegment& to_query, const Points& Q, const Points& Csym,
                 const Points& Cres, double scale, Alignment& best) {
  const int m = static_cast<int>(Q.rows());
  const Points Corig = (Csym * best.rotation.transpose()).rowwise() + best.translation.transpose();
  const Points Cmoved = (Cres * best.rotation.transpose()).rowwise() + best.translation.transpose();
  PointToLine ne;
  ne.c = Q.colwise().mean().transpose();
  const Vec3& c = ne.c;
  const NearestSegment to_candidate(Corig);
  for (int k = 0; k < m; ++k) {
    Vec3 tg;
    const Vec3 y = closest_on_polygon(Q.row(k).transpose(), Corig, to_candidate, &tg);
    ne.add_pair(y, Q.row(k).transpose(), tg);
    const Vec3 x = closest_on_polygon(Cmoved.row(k).transpose(), query, to_query, &tg);
    ne.add_pair(Cmoved.row(k).transpose(), x, tg);
  }
  // damped solve: a circle's rotation about its axis is a free direction
  const double damping = 1e-12 * std::max(ne.A.diagonal().maxCoeff(), 1e-300);
  const Eigen::Matrix<double, 6, 1> d = (ne.A + damping * Eigen::Matrix<double, 6, 6>::Identity()).ldlt().solve(ne.b);
  const Vec3 w = d.head<3>(), tau = d.tail<3>();
  const double angle = w.norm();
  const Mat3 Rw = angle > 0.0 ? Mat3(Eigen::AngleAxisd(angle, w / angle)) : Mat3::Identity();
  best.rotation = Rw * best.rotation;
  best.translation = Rw * best.translation + c - Rw * c + tau;
  return !(angle + tau.norm() / scale < 1e-13);
}

}  // namespace

void AlignmentOptions::validate() const {
  require(samples >= 4, "AlignmentOptions: samples must be >= 4");
  require(refine_starts >= 1, "AlignmentOptions: refine_starts must be >= 1");
  require(max_iterations >= 0, "AlignmentOptions: max_iterations must be >= 0");
  require(polish_iterations >= 0, "AlignmentOptions: polish_iterations must be >= 0");
  require(relative_tolerance >= 0.0 && std::isfinite(relative_tolerance),
          "AlignmentOptions: relative_tolerance must be finite and >= 0");
}

Alignment align_curves(const Points& query, const Points& candidate, const AlignmentOptions& options) {
  options.validate();
  require(query.rows() >= 3 && candidate.rows() >= 3, "align_curves: closed polygons with >= 3 vertices expected");
  require(query.allFinite() && candidate.allFinite(), "align_curves: non-finite coordinates");
  const int m = options.samples;
  const Points Q = resample_arclength(query, m);
  const Points C = resample_arclength(candidate, m);
  const Points Qc = centred(Q);

  // 1. closed-form residual of every (symmetry, shift) correspondence
  const std::vector<Start> starts = closed_form_starts(Qc, C, options);

  // 2. ICP from each start
  Alignment best;
  best.distance = std::numeric_limits<double>::infinity();
  for (const Start& st : starts) {
    const IcpResult r = icp_from_start(Q, C, st, options);
    const double dist = symmetric_rms(Q, r.Y);
    if (dist < best.distance) {
      best.distance = dist;
      best.rotation = r.R;
      best.translation = r.t;
      best.shift = st.shift;
      best.reversed = st.symmetry & 1;
      best.mirrored = st.symmetry & 2;
      best.iterations = r.iterations;
      best.status = r.status;
    }
  }

  // 3. polish the best alignment with point-to-line (Gauss-Newton) steps on the
  //    original polygons: resampled points lie on them, so exact copies align exactly
  const int sym = (best.reversed ? 1 : 0) | (best.mirrored ? 2 : 0);
  const Points Csym = apply_symmetry(candidate, sym);
  const Points Cres = apply_symmetry(C, sym);
  const double scale = std::max(Qc.cwiseAbs().maxCoeff(), 1e-300);
  const NearestSegment to_query(query);
  for (int it = 0; it < options.polish_iterations; ++it)
    if (!polish_step(query, to_query, Q, Csym, Cres, scale, best)) break;

  // 4. the distance between the original polygons (vertices of each to the other)
  best.distance = symmetric_rms(query, aligned_candidate(candidate, best));
  return best;
}

Points aligned_candidate(const Points& candidate, const Alignment& alignment) {
  const int sym = (alignment.reversed ? 1 : 0) | (alignment.mirrored ? 2 : 0);
  return (apply_symmetry(candidate, sym) * alignment.rotation.transpose()).rowwise() + alignment.translation.transpose();
}

bool passes_filters(const Attributes& attributes, const std::vector<AttributeRange>& filters) {
  for (const AttributeRange& f : filters) {
    const std::optional<double> v = attribute_value(attributes, f.name);
    if (!v || !(*v >= f.min && *v <= f.max)) return false;
  }
  return true;
}

std::vector<AttributeRange> ranges_around(const Attributes& query, const std::vector<std::string>& names,
                                          double relative_width, double absolute_width) {
  require(relative_width >= 0.0 && absolute_width >= 0.0, "ranges_around: widths must be >= 0");
  std::vector<AttributeRange> out;
  for (const std::string& name : names) {
    const std::optional<double> v = attribute_value(query, name);
    require(v.has_value(), "ranges_around: the query has no value for '" + name + "'");
    const double w = std::max(relative_width * std::abs(*v), absolute_width);
    out.push_back({name, *v - w, *v + w});
  }
  return out;
}

std::vector<SearchHit> search_similar(const Points& query, const std::vector<Points>& candidates,
                                      const std::vector<Attributes>& candidate_attributes,
                                      const SearchOptions& options) {
  options.alignment.validate();
  require(options.max_results >= 0, "search_similar: max_results must be >= 0");
  require(candidate_attributes.empty() || candidate_attributes.size() == candidates.size(),
          "search_similar: candidate_attributes must be empty or have one entry per candidate");
  std::vector<SearchHit> hits;
  for (size_t k = 0; k < candidates.size(); ++k) {
    if (!options.filters.empty()) {
      const Attributes a = candidate_attributes.empty() ? compute_attributes(candidates[k]) : candidate_attributes[k];
      if (!passes_filters(a, options.filters)) continue;
    }
    SearchHit h;
    h.index = static_cast<int>(k);
    h.alignment = align_curves(query, candidates[k], options.alignment);
    h.distance = h.alignment.distance;
    hits.push_back(h);
  }
  std::stable_sort(hits.begin(), hits.end(), [](const SearchHit& a, const SearchHit& b) { return a.distance < b.distance; });
  if (options.max_results > 0 && static_cast<int>(hits.size()) > options.max_results)
    hits.resize(static_cast<size_t>(options.max_results));
  return hits;
}

}  // namespace ek
