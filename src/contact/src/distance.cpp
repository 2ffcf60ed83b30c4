#include "ek/contact/distance.hpp"

#include <algorithm>
#include <limits>

namespace ek {

namespace {

// Adds 2 c cᵀ ⊗ I (the Gauss-Newton part 2 JᵀJ when every block of J is a
// multiple of the identity: J = [c_0 I, c_1 I, ...]) to H.
template <int K, class Mat>
inline void add_block_outer(const std::array<double, K>& c, Mat& H) {
  for (int i = 0; i < K; ++i)
    for (int j = 0; j < K; ++j) {
      const double v = 2.0 * c[i] * c[j];
      H(3 * i, 3 * j) += v;
      H(3 * i + 1, 3 * j + 1) += v;
      H(3 * i + 2, 3 * j + 2) += v;
    }
}

// Scatters a local vector / matrix over the vertex slots `slot` (0..3) of the
// 12 segment-pair dofs.
template <int K, class Vec>
inline void scatter(const Vec& g, const std::array<int, K>& slot, Vec12& out) {
  out.setZero();
  for (int i = 0; i < K; ++i) out.template segment<3>(3 * slot[i]) = g.template segment<3>(3 * i);
}
template <int K, class Mat>
inline void scatter(const Mat& H, const std::array<int, K>& slot, Mat12& out) {
  out.setZero();
  for (int i = 0; i < K; ++i)
    for (int j = 0; j < K; ++j) out.template block<3, 3>(3 * slot[i], 3 * slot[j]) = H.template block<3, 3>(3 * i, 3 * j);
}

double point_line_derivatives(const Vec3& p, const Vec3& e0, const Vec3& e1, Vec9* grad, Mat9* hess) {
  const Vec3 e = e1 - e0;
  const double E = e.squaredNorm();
  const double t = (p - e0).dot(e) / E;
  const Vec3 w = p - e0 - t * e;
  const std::array<double, 3> c = {1.0, -(1.0 - t), -t};
  if (grad)
    for (int i = 0; i < 3; ++i) grad->segment<3>(3 * i) = 2.0 * c[i] * w;
  if (hess) {
    hess->setZero();
    add_block_outer<3>(c, *hess);
    // − g_xt g_xtᵀ / g_tt with g_xt = 2h, g_tt = 2E
    Vec9 h;
    h << -e, w + (1.0 - t) * e, -w + t * e;
    hess->noalias() -= (2.0 / E) * h * h.transpose();
  }
  return w.squaredNorm();
}

double line_line_derivatives(const Vec3& ea0, const Vec3& ea1, const Vec3& eb0, const Vec3& eb1, Vec12* grad,
                             Mat12* hess) {
  const Vec3 a = ea1 - ea0, b = eb1 - eb0, r = ea0 - eb0;
  const double A = a.squaredNorm(), B = b.squaredNorm(), C = a.dot(b), D = a.dot(r), F = b.dot(r);
  const double det = A * B - C * C;
  const double s = (C * F - D * B) / det;
  const double t = (A * F - C * D) / det;
  const Vec3 w = r + s * a - t * b;
  const std::array<double, 4> c = {1.0 - s, s, -(1.0 - t), -t};
  if (grad)
    for (int i = 0; i < 4; ++i) grad->segment<3>(3 * i) = 2.0 * c[i] * w;
  if (hess) {
    hess->setZero();
    add_block_outer<4>(c, *hess);
    // − G g_uu⁻¹ Gᵀ with G = 2 [hs ht], g_uu = 2 [A −C; −C B]
    Eigen::Matrix<double, 12, 2> G;
    G.col(0) << -w + (1.0 - s) * a, w + s * a, -(1.0 - t) * a, -t * a;
    G.col(1) << -(1.0 - s) * b, -s * b, w + (1.0 - t) * b, -w + t * b;
    Eigen::Matrix2d M;
    M << B, C, C, A;
    M *= 2.0 / det;
    hess->noalias() -= G * M * G.transpose();
  }
  return w.squaredNorm();
}

double point_point_derivatives(const Vec3& p, const Vec3& q, Vec6* grad, Mat6* hess) {
  const Vec3 w = p - q;
  if (grad) *grad << 2.0 * w, -2.0 * w;
  if (hess) {
    hess->setZero();
    add_block_outer<2>({1.0, -1.0}, *hess);
  }
  return w.squaredNorm();
}

}  // namespace

// --- point-point -------------------------------------------------------------

double point_point_distance_squared(const Vec3& p, const Vec3& q) { return (p - q).squaredNorm(); }
Vec6 point_point_distance_squared_gradient(const Vec3& p, const Vec3& q) {
  Vec6 g;
  point_point_derivatives(p, q, &g, nullptr);
  return g;
}
Mat6 point_point_distance_squared_hessian(const Vec3& p, const Vec3& q) {
  Mat6 H;
  point_point_derivatives(p, q, nullptr, &H);
  return H;
}

// --- point-line --------------------------------------------------------------

double point_line_distance_squared(const Vec3& p, const Vec3& e0, const Vec3& e1) {
  return point_line_derivatives(p, e0, e1, nullptr, nullptr);
}
Vec9 point_line_distance_squared_gradient(const Vec3& p, const Vec3& e0, const Vec3& e1) {
  Vec9 g;
  point_line_derivatives(p, e0, e1, &g, nullptr);
  return g;
}
Mat9 point_line_distance_squared_hessian(const Vec3& p, const Vec3& e0, const Vec3& e1) {
  Mat9 H;
  point_line_derivatives(p, e0, e1, nullptr, &H);
  return H;
}

// --- line-line ---------------------------------------------------------------

double line_line_distance_squared(const Vec3& ea0, const Vec3& ea1, const Vec3& eb0, const Vec3& eb1) {
  return line_line_derivatives(ea0, ea1, eb0, eb1, nullptr, nullptr);
}
Vec12 line_line_distance_squared_gradient(const Vec3& ea0, const Vec3& ea1, const Vec3& eb0, const Vec3& eb1) {
  Vec12 g;
  line_line_derivatives(ea0, ea1, eb0, eb1, &g, nullptr);
  return g;
}
Mat12 line_line_distance_squared_hessian(const Vec3& ea0, const Vec3& ea1, const Vec3& eb0, const Vec3& eb1) {
  Mat12 H;
  line_line_derivatives(ea0, ea1, eb0, eb1, nullptr, &H);
  return H;
}

// --- point-segment -----------------------------------------------------------

PointEdgeDistanceType point_edge_distance_type(const Vec3& p, const Vec3& e0, const Vec3& e1) {
  const Vec3 e = e1 - e0;
  const double E = e.squaredNorm();
  if (!(E > 0.0)) return PointEdgeDistanceType::P_E0;
  const double t = (p - e0).dot(e);
  if (t <= 0.0) return PointEdgeDistanceType::P_E0;
  if (t >= E) return PointEdgeDistanceType::P_E1;
  return PointEdgeDistanceType::P_E;
}

double point_edge_distance_squared_derivatives(const Vec3& p, const Vec3& e0, const Vec3& e1,
                                               PointEdgeDistanceType type, Vec9* grad, Mat9* hess) {
  switch (type) {
    case PointEdgeDistanceType::P_E:
      return point_line_derivatives(p, e0, e1, grad, hess);
    case PointEdgeDistanceType::P_E0:
    case PointEdgeDistanceType::P_E1: {
      const int k = (type == PointEdgeDistanceType::P_E0) ? 1 : 2;
      const Vec3& q = (k == 1) ? e0 : e1;
      Vec6 g6;
      Mat6 H6;
      const double v = point_point_derivatives(p, q, grad ? &g6 : nullptr, hess ? &H6 : nullptr);
      if (grad) {
        grad->setZero();
        grad->segment<3>(0) = g6.segment<3>(0);
        grad->segment<3>(3 * k) = g6.segment<3>(3);
      }
      if (hess) {
        hess->setZero();
        const int s[2] = {0, k};
        for (int i = 0; i < 2; ++i)
          for (int j = 0; j < 2; ++j) hess->block<3, 3>(3 * s[i], 3 * s[j]) = H6.block<3, 3>(3 * i, 3 * j);
      }
      return v;
    }
  }
  return 0.0;
}

double point_edge_distance_squared(const Vec3& p, const Vec3& e0, const Vec3& e1, PointEdgeDistanceType type) {
  return point_edge_distance_squared_derivatives(p, e0, e1, type, nullptr, nullptr);
}
Vec9 point_edge_distance_squared_gradient(const Vec3& p, const Vec3& e0, const Vec3& e1, PointEdgeDistanceType type) {
  Vec9 g;
  point_edge_distance_squared_derivatives(p, e0, e1, type, &g, nullptr);
  return g;
}
Mat9 point_edge_distance_squared_hessian(const Vec3& p, const Vec3& e0, const Vec3& e1, PointEdgeDistanceType type) {
  Mat9 H;
  point_edge_distance_squared_derivatives(p, e0, e1, type, nullptr, &H);
  return H;
}

// --- segment-segment ---------------------------------------------------------

const char* to_string(EdgeEdgeDistanceType type) {
  switch (type) {
    case EdgeEdgeDistanceType::EA_EB: return "EA_EB";
    case EdgeEdgeDistanceType::EA0_EB: return "EA0_EB";
    case EdgeEdgeDistanceType::EA1_EB: return "EA1_EB";
    case EdgeEdgeDistanceType::EA_EB0: return "EA_EB0";
    case EdgeEdgeDistanceType::EA_EB1: return "EA_EB1";
    case EdgeEdgeDistanceType::EA0_EB0: return "EA0_EB0";
    case EdgeEdgeDistanceType::EA0_EB1: return "EA0_EB1";
    case EdgeEdgeDistanceType::EA1_EB0: return "EA1_EB0";
    case EdgeEdgeDistanceType::EA1_EB1: return "EA1_EB1";
  }
  return "?";
}

EdgeEdgeClosest edge_edge_closest(const Vec3& ea0, const Vec3& ea1, const Vec3& eb0, const Vec3& eb1) {
  using T = EdgeEdgeDistanceType;
  const Vec3 a = ea1 - ea0, b = eb1 - eb0, r = ea0 - eb0;
  const double A = a.squaredNorm(), B = b.squaredNorm(), C = a.dot(b), D = a.dot(r), F = b.dot(r);
  const double det = A * B - C * C;
  if (A > 0.0 && B > 0.0 && det > kParallelSin2 * A * B) {
    const double s = (C * F - D * B) / det;
    const double t = (A * F - C * D) / det;
    if (s >= 0.0 && s <= 1.0 && t >= 0.0 && t <= 1.0)
      return {T::EA_EB, line_line_derivatives(ea0, ea1, eb0, eb1, nullptr, nullptr)};
  }
  // The minimum lies on a side of the parameter square: one endpoint against
  // the other segment. Each is evaluated with the formula of its own case
  // (the same operations as point_edge_distance_squared(type)), so that the
  // value equals edge_edge_distance_squared(type) exactly.
  EdgeEdgeClosest best{T::EA0_EB0, std::numeric_limits<double>::infinity()};
  auto consider = [&](const Vec3& p, const Vec3& e0, const Vec3& e1, const Vec3& e, double E, T interior, T at0,
                      T at1) {
    double v;
    T type;
    const double dot = (p - e0).dot(e);
    if (!(E > 0.0) || dot <= 0.0) {
      v = (p - e0).squaredNorm();
      type = at0;
    } else if (dot >= E) {
      v = (p - e1).squaredNorm();
      type = at1;
    } else {
      const double t = (p - e0).dot(e) / E;
      v = (p - e0 - t * e).squaredNorm();
      type = interior;
    }
    if (v < best.distance_squared) {
      best.distance_squared = v;
      best.type = type;
    }
  };
  consider(ea0, eb0, eb1, b, B, T::EA0_EB, T::EA0_EB0, T::EA0_EB1);
  consider(ea1, eb0, eb1, b, B, T::EA1_EB, T::EA1_EB0, T::EA1_EB1);
  consider(eb0, ea0, ea1, a, A, T::EA_EB0, T::EA0_EB0, T::EA1_EB0);
  consider(eb1, ea0, ea1, a, A, T::EA_EB1, T::EA0_EB1, T::EA1_EB1);
  return best;
}

void edge_edge_closest_parameters(const Vec3& ea0, const Vec3& ea1, const Vec3& eb0, const Vec3& eb1,
                                  EdgeEdgeDistanceType type, double* s_out, double* t_out) {
  using T = EdgeEdgeDistanceType;
  const Vec3 a = ea1 - ea0, b = eb1 - eb0;
  double s = 0.0, t = 0.0;
  switch (type) {
    case T::EA_EB: {
      const Vec3 r = ea0 - eb0;
      const double A = a.squaredNorm(), B = b.squaredNorm(), C = a.dot(b), D = a.dot(r), F = b.dot(r);
      const double det = A * B - C * C;
      s = (C * F - D * B) / det;
      t = (A * F - C * D) / det;
      break;
    }
    case T::EA0_EB: s = 0.0; t = (ea0 - eb0).dot(b) / b.squaredNorm(); break;
    case T::EA1_EB: s = 1.0; t = (ea1 - eb0).dot(b) / b.squaredNorm(); break;
    case T::EA_EB0: t = 0.0; s = (eb0 - ea0).dot(a) / a.squaredNorm(); break;
    case T::EA_EB1: t = 1.0; s = (eb1 - ea0).dot(a) / a.squaredNorm(); break;
    case T::EA0_EB0: s = 0.0; t = 0.0; break;
    case T::EA0_EB1: s = 0.0; t = 1.0; break;
    case T::EA1_EB0: s = 1.0; t = 0.0; break;
    case T::EA1_EB1: s = 1.0; t = 1.0; break;
  }
  if (s_out) *s_out = s;
  if (t_out) *t_out = t;
}

EdgeEdgeDistanceType edge_edge_distance_type(const Vec3& ea0, const Vec3& ea1, const Vec3& eb0, const Vec3& eb1) {
  return edge_edge_closest(ea0, ea1, eb0, eb1).type;
}

double edge_edge_distance_squared_derivatives(const Vec3& ea0, const Vec3& ea1, const Vec3& eb0, const Vec3& eb1,
                                              EdgeEdgeDistanceType type, Vec12* grad, Mat12* hess) {
  using T = EdgeEdgeDistanceType;
  const Vec3* x[4] = {&ea0, &ea1, &eb0, &eb1};
  switch (type) {
    case T::EA_EB:
      return line_line_derivatives(ea0, ea1, eb0, eb1, grad, hess);
    case T::EA0_EB:
    case T::EA1_EB:
    case T::EA_EB0:
    case T::EA_EB1: {
      std::array<int, 3> slot;
      if (type == T::EA0_EB) slot = {0, 2, 3};
      else if (type == T::EA1_EB) slot = {1, 2, 3};
      else if (type == T::EA_EB0) slot = {2, 0, 1};
      else slot = {3, 0, 1};
      Vec9 g;
      Mat9 H;
      const double v = point_line_derivatives(*x[slot[0]], *x[slot[1]], *x[slot[2]], grad ? &g : nullptr,
                                              hess ? &H : nullptr);
      if (grad) scatter<3>(g, slot, *grad);
      if (hess) scatter<3>(H, slot, *hess);
      return v;
    }
    default: {
      std::array<int, 2> slot;
      if (type == T::EA0_EB0) slot = {0, 2};
      else if (type == T::EA0_EB1) slot = {0, 3};
      else if (type == T::EA1_EB0) slot = {1, 2};
      else slot = {1, 3};
      Vec6 g;
      Mat6 H;
      const double v = point_point_derivatives(*x[slot[0]], *x[slot[1]], grad ? &g : nullptr, hess ? &H : nullptr);
      if (grad) scatter<2>(g, slot, *grad);
      if (hess) scatter<2>(H, slot, *hess);
      return v;
    }
  }
}

double edge_edge_distance_squared(const Vec3& ea0, const Vec3& ea1, const Vec3& eb0, const Vec3& eb1,
                                  EdgeEdgeDistanceType type) {
  return edge_edge_distance_squared_derivatives(ea0, ea1, eb0, eb1, type, nullptr, nullptr);
}
Vec12 edge_edge_distance_squared_gradient(const Vec3& ea0, const Vec3& ea1, const Vec3& eb0, const Vec3& eb1,
                                          EdgeEdgeDistanceType type) {
  Vec12 g;
  edge_edge_distance_squared_derivatives(ea0, ea1, eb0, eb1, type, &g, nullptr);
  return g;
}
Mat12 edge_edge_distance_squared_hessian(const Vec3& ea0, const Vec3& ea1, const Vec3& eb0, const Vec3& eb1,
                                         EdgeEdgeDistanceType type) {
  Mat12 H;
  edge_edge_distance_squared_derivatives(ea0, ea1, eb0, eb1, type, nullptr, &H);
  return H;
}

}  // namespace ek
