#include "ek/geometry/polyline.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "ek/core/errors.hpp"
#include "ek/geometry/segment_distance.hpp"

namespace ek {

void require_closed_polygon(const Points& P, const char* who) {
  require(P.rows() >= 3, std::string(who) + ": a closed polygon needs at least 3 vertices");
  require(P.allFinite(), std::string(who) + ": non-finite coordinates");
}

Points edge_vectors(const Points& P) {
  const auto n = P.rows();
  Points E(n, 3);
  for (Eigen::Index i = 0; i < n; ++i) E.row(i) = P.row((i + 1) % n) - P.row(i);
  return E;
}

VecX edge_lengths(const Points& P) { return edge_vectors(P).rowwise().norm(); }

double curve_length(const Points& P) { return edge_lengths(P).sum(); }

VecX turning_angles(const Points& P) {
  const auto n = P.rows();
  const Points E = edge_vectors(P);
  VecX angles(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Vec3 a = E.row((i + n - 1) % n).transpose();
    const Vec3 b = E.row(i).transpose();
    angles(i) = std::atan2(a.cross(b).norm(), a.dot(b));
  }
  return angles;
}

double total_curvature(const Points& P) { return turning_angles(P).sum(); }

Vec3 centroid(const Points& P) { return P.colwise().mean().transpose(); }

Mat3 principal_axes(const Points& P) {
  require(P.rows() >= 1 && P.allFinite(), "principal_axes: finite points needed");
  const Vec3 c = centroid(P);
  Mat3 S = Mat3::Zero();
  for (Eigen::Index i = 0; i < P.rows(); ++i) {
    const Vec3 d = P.row(i).transpose() - c;
    S += d * d.transpose();
  }
  return Eigen::SelfAdjointEigenSolver<Mat3>(S).eigenvectors();
}

Clearance clearance(const Points& P, int min_index_gap) {
  const int n = static_cast<int>(P.rows());
  require(n >= 4, "clearance: a closed curve needs at least 4 vertices");
  require(min_index_gap >= 1, "clearance: min_index_gap must be >= 1");
  struct Box {
    double lo[3], hi[3];
  };
  std::vector<Box> boxes(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    for (int k = 0; k < 3; ++k) {
      boxes[static_cast<size_t>(i)].lo[k] = std::min(P(i, k), P(j, k));
      boxes[static_cast<size_t>(i)].hi[k] = std::max(P(i, k), P(j, k));
    }
  }
  std::vector<int> order(static_cast<size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return boxes[static_cast<size_t>(a)].lo[0] < boxes[static_cast<size_t>(b)].lo[0]; });
  Clearance best;
  double best_d2 = std::numeric_limits<double>::infinity();
  for (int oi = 0; oi < n; ++oi) {
    const int i = order[static_cast<size_t>(oi)];
    const Box& bi = boxes[static_cast<size_t>(i)];
    for (int oj = oi + 1; oj < n; ++oj) {
      const int j = order[static_cast<size_t>(oj)];
      const Box& bj = boxes[static_cast<size_t>(j)];
      const double gap_x = bj.lo[0] - bi.hi[0];
      if (gap_x > 0.0 && gap_x * gap_x >= best_d2) break;  // sorted by lo[0]: no later box is closer in x
      int gap = std::abs(i - j);
      gap = std::min(gap, n - gap);
      if (gap < min_index_gap) continue;
      double box_d2 = 0.0;
      for (int k = 0; k < 3; ++k) {
        double g = std::max(bi.lo[k] - bj.hi[k], bj.lo[k] - bi.hi[k]);
        if (g > 0.0) box_d2 += g * g;
      }
      if (box_d2 >= best_d2) continue;
      const double d2 = segment_segment_distance_squared(P.row(i).transpose(), P.row((i + 1) % n).transpose(),
                                                         P.row(j).transpose(), P.row((j + 1) % n).transpose());
      if (d2 < best_d2) {
        best_d2 = d2;
        best.edge_a = std::min(i, j);
        best.edge_b = std::max(i, j);
      }
    }
  }
  best.distance = std::sqrt(best_d2);
  return best;
}

}  // namespace ek
