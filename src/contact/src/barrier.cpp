#include "ek/contact/barrier.hpp"

#include <Eigen/Eigenvalues>
#include <array>
#include <cmath>
#include <limits>

namespace ek {

double barrier(double d, double dhat) {
  if (d >= dhat) return 0.0;
  if (!(d > 0.0)) return std::numeric_limits<double>::infinity();
  const double u = d - dhat;
  return -u * u * std::log(d / dhat);
}

double barrier_first_derivative(double d, double dhat) {
  if (d >= dhat) return 0.0;
  const double u = d - dhat;
  return -2.0 * u * std::log(d / dhat) - u * u / d;
}

double barrier_second_derivative(double d, double dhat) {
  if (d >= dhat) return 0.0;
  const double u = d - dhat;
  return -2.0 * std::log(d / dhat) - 4.0 * u / d + u * u / (d * d);
}

double parallel_mollifier(double c, double eps) {
  if (c >= eps) return 1.0;
  const double q = c / eps;
  return q * (2.0 - q);
}
double parallel_mollifier_first_derivative(double c, double eps) {
  if (c >= eps) return 0.0;
  return 2.0 / eps - 2.0 * c / (eps * eps);
}
double parallel_mollifier_second_derivative(double c, double eps) {
  if (c >= eps) return 0.0;
  return -2.0 / (eps * eps);
}

double edge_edge_sin2(const Vec3& ea0, const Vec3& ea1, const Vec3& eb0, const Vec3& eb1, Vec12* grad,
                      Mat12* hess) {
  const Vec3 a = ea1 - ea0, b = eb1 - eb0;
  const double A = a.squaredNorm(), B = b.squaredNorm(), p = a.dot(b);
  const double AB = A * B;
  const double c = a.cross(b).squaredNorm() / AB;  // = 1 − cos²θ, without the cancellation
  if (!grad && !hess) return c;
  // k(p, A, B) = p²/(AB); derivatives in the 6 variables (a, b) first.
  const double kp = 2.0 * p / AB, kA = -p * p / (A * AB), kB = -p * p / (AB * B);
  Eigen::Matrix<double, 6, 1> dp, dA, dB;
  dp << b, a;
  dA << 2.0 * a, Vec3::Zero();
  dB << Vec3::Zero(), 2.0 * b;
  const Eigen::Matrix<double, 6, 1> gk = kp * dp + kA * dA + kB * dB;
  Eigen::Matrix<double, 6, 6> Hk;
  if (hess) {
    const double kpp = 2.0 / AB, kpA = -2.0 * p / (A * AB), kpB = -2.0 * p / (AB * B);
    const double kAA = 2.0 * p * p / (A * A * AB), kBB = 2.0 * p * p / (AB * B * B), kAB = p * p / (AB * AB);
    Hk.noalias() = kpp * dp * dp.transpose();
    Hk.noalias() += kpA * (dp * dA.transpose() + dA * dp.transpose());
    Hk.noalias() += kpB * (dp * dB.transpose() + dB * dp.transpose());
    Hk.noalias() += kAA * dA * dA.transpose() + kBB * dB * dB.transpose();
    Hk.noalias() += kAB * (dA * dB.transpose() + dB * dA.transpose());
    const Mat3 I = Mat3::Identity();
    Hk.block<3, 3>(0, 3) += kp * I;  // ∇²p = [0 I; I 0]
    Hk.block<3, 3>(3, 0) += kp * I;
    Hk.block<3, 3>(0, 0) += 2.0 * kA * I;  // ∇²A = [2I 0; 0 0]
    Hk.block<3, 3>(3, 3) += 2.0 * kB * I;  // ∇²B = [0 0; 0 2I]
  }
  // (a, b) -> (ea0, ea1, eb0, eb1): a = ea1 − ea0, b = eb1 − eb0; c = 1 − k.
  const int slot[2][2] = {{0, 1}, {2, 3}};  // [variable][−, +]
  if (grad)
    for (int v = 0; v < 2; ++v) {
      grad->segment<3>(3 * slot[v][0]) = gk.segment<3>(3 * v);
      grad->segment<3>(3 * slot[v][1]) = -gk.segment<3>(3 * v);
    }
  if (hess)
    for (int v = 0; v < 2; ++v)
      for (int w = 0; w < 2; ++w) {
        const Mat3 blk = Hk.block<3, 3>(3 * v, 3 * w);
        hess->block<3, 3>(3 * slot[v][0], 3 * slot[w][0]) = -blk;
        hess->block<3, 3>(3 * slot[v][0], 3 * slot[w][1]) = blk;
        hess->block<3, 3>(3 * slot[v][1], 3 * slot[w][0]) = blk;
        hess->block<3, 3>(3 * slot[v][1], 3 * slot[w][1]) = -blk;
      }
  return c;
}

namespace {

// B(s) = b(√s) with derivatives in s.
struct SquaredBarrier {
  double value = 0.0, first = 0.0, second = 0.0;
};
SquaredBarrier squared_barrier(double s, double dhat, bool derivatives) {
  SquaredBarrier r;
  const double d = std::sqrt(s);
  r.value = barrier(d, dhat);
  if (derivatives && d < dhat) {
    const double b1 = barrier_first_derivative(d, dhat);
    const double b2 = barrier_second_derivative(d, dhat);
    r.first = b1 / (2.0 * d);
    r.second = (b2 - b1 / d) / (4.0 * s);
  }
  return r;
}

// Adds w·B(s(x)) and its derivatives for the pair-distance case `type`.
double add_edge_edge_term(const Vec3* x, EdgeEdgeDistanceType type, double dhat, double weight, Vec12* grad,
                          Mat12* hess) {
  Vec12 gs;
  Mat12 Hs;
  const double s = edge_edge_distance_squared_derivatives(x[0], x[1], x[2], x[3], type, (grad || hess) ? &gs : nullptr,
                                                          hess ? &Hs : nullptr);
  const SquaredBarrier B = squared_barrier(s, dhat, grad || hess);
  if (grad) grad->noalias() += (weight * B.first) * gs;
  if (hess) {
    hess->noalias() += (weight * B.second) * gs * gs.transpose();
    hess->noalias() += (weight * B.first) * Hs;
  }
  return weight * B.value;
}

// Adds w·B(s_k) for the endpoint x[p] against the segment [x[e0], x[e1]].
double add_point_edge_term(const Vec3* x, int p, int e0, int e1, double dhat, double weight, Vec12* grad,
                           Mat12* hess) {
  const PointEdgeDistanceType type = point_edge_distance_type(x[p], x[e0], x[e1]);
  Vec9 gs;
  Mat9 Hs;
  const double s = point_edge_distance_squared_derivatives(x[p], x[e0], x[e1], type, (grad || hess) ? &gs : nullptr,
                                                           hess ? &Hs : nullptr);
  if (s >= dhat * dhat) return 0.0;
  const SquaredBarrier B = squared_barrier(s, dhat, grad || hess);
  const int slot[3] = {p, e0, e1};
  if (grad)
    for (int i = 0; i < 3; ++i) grad->segment<3>(3 * slot[i]) += (weight * B.first) * gs.segment<3>(3 * i);
  if (hess) {
    Mat9 H = (weight * B.second) * gs * gs.transpose();
    H.noalias() += (weight * B.first) * Hs;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) hess->block<3, 3>(3 * slot[i], 3 * slot[j]) += H.block<3, 3>(3 * i, 3 * j);
  }
  return weight * B.value;
}

// The squared distance of every closest-feature case has the structure
//   s = |w|²,  ∇s = 2 c ⊗ w,  ∇²s = 2 (c cᵀ) ⊗ I − G M Gᵀ,
// with c the coefficients of the four vertices in w (distance.cpp: J = c ⊗ I)
// and G M Gᵀ the envelope correction (none for point-point, rank 1 for
// point-line, rank 2 for line-line). The barrier Hessian
//   B'' ∇s ∇sᵀ + B' ∇²s = (c cᵀ) ⊗ (4 B'' w wᵀ + 2 B' I) − B' G M Gᵀ
// is then assembled in one pass (a Kronecker product plus a rank-2 update)
// instead of forming ∇²s first.
struct DistanceStructure {
  double s = 0.0;
  std::array<double, 4> c{};
  Vec3 w = Vec3::Zero();
  int rank = 0;
  Eigen::Matrix<double, 12, 2> G;
  Eigen::Matrix2d M;
};

DistanceStructure distance_structure(const Vec3* x, EdgeEdgeDistanceType type) {
  using T = EdgeEdgeDistanceType;
  DistanceStructure d;
  switch (type) {
    case T::EA_EB: {
      const Vec3 a = x[1] - x[0], b = x[3] - x[2], r = x[0] - x[2];
      const double A = a.squaredNorm(), B = b.squaredNorm(), C = a.dot(b), D = a.dot(r), F = b.dot(r);
      const double det = A * B - C * C;
      const double s = (C * F - D * B) / det, t = (A * F - C * D) / det;
      d.w = r + s * a - t * b;
      d.c = {1.0 - s, s, -(1.0 - t), -t};
      d.rank = 2;
      d.G.col(0) << -d.w + (1.0 - s) * a, d.w + s * a, -(1.0 - t) * a, -t * a;
      d.G.col(1) << -(1.0 - s) * b, -s * b, d.w + (1.0 - t) * b, -d.w + t * b;
      d.M << B, C, C, A;
      d.M *= 2.0 / det;
      break;
    }
    case T::EA0_EB:
    case T::EA1_EB:
    case T::EA_EB0:
    case T::EA_EB1: {
      int p, e0, e1;
      if (type == T::EA0_EB) p = 0, e0 = 2, e1 = 3;
      else if (type == T::EA1_EB) p = 1, e0 = 2, e1 = 3;
      else if (type == T::EA_EB0) p = 2, e0 = 0, e1 = 1;
      else p = 3, e0 = 0, e1 = 1;
      const Vec3 e = x[e1] - x[e0];
      const double E = e.squaredNorm();
      const double t = (x[p] - x[e0]).dot(e) / E;
      d.w = x[p] - x[e0] - t * e;
      d.c[static_cast<size_t>(p)] = 1.0;
      d.c[static_cast<size_t>(e0)] = -(1.0 - t);
      d.c[static_cast<size_t>(e1)] = -t;
      d.rank = 1;
      d.G.col(0).setZero();
      d.G.col(0).segment<3>(3 * p) = -e;
      d.G.col(0).segment<3>(3 * e0) = d.w + (1.0 - t) * e;
      d.G.col(0).segment<3>(3 * e1) = -d.w + t * e;
      d.M(0, 0) = 2.0 / E;
      break;
    }
    default: {
      int i, j;
      if (type == T::EA0_EB0) i = 0, j = 2;
      else if (type == T::EA0_EB1) i = 0, j = 3;
      else if (type == T::EA1_EB0) i = 1, j = 2;
      else i = 1, j = 3;
      d.w = x[i] - x[j];
      d.c[static_cast<size_t>(i)] = 1.0;
      d.c[static_cast<size_t>(j)] = -1.0;
      d.rank = 0;
    }
  }
  d.s = d.w.squaredNorm();
  return d;
}

/// The Hessian of structured_barrier() is U S Uᵀ with U = [c ⊗ e₁, c ⊗ e₂,
/// c ⊗ e₃, G] (12 by 3 + rank) and S = diag(K, −b1 M): its range has at most
/// 5 dimensions. Its nearest positive semidefinite matrix is Q P₊(R S Rᵀ) Qᵀ
/// for U = Q R (thin QR): a 5 by 5 eigen-decomposition instead of 12 by 12.
/// (Columns of U past 3 + rank are zero, and so are their rows of R.)
void projected_structured_hessian(const DistanceStructure& d, const Mat3& K, double b1, Mat12& hess) {
  using Mat5 = Eigen::Matrix<double, 5, 5>;
  Eigen::Matrix<double, 12, 5> U = Eigen::Matrix<double, 12, 5>::Zero();
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 3; ++k) U(3 * i + k, k) = d.c[static_cast<size_t>(i)];
  Mat5 S = Mat5::Zero();
  S.topLeftCorner<3, 3>() = K;
  if (d.rank >= 1) U.col(3) = d.G.col(0);
  if (d.rank == 2) U.col(4) = d.G.col(1);
  if (d.rank == 1) S(3, 3) = -b1 * d.M(0, 0);
  if (d.rank == 2) S.bottomRightCorner<2, 2>() = -b1 * d.M;
  // Thin QR by Gram-Schmidt: the columns c ⊗ e_k are orthogonal with norm |c|
  // (> 0: the weights of a closest-point pair sum to 1 on each edge); the G
  // columns are orthogonalised against them and each other (twice, for
  // round-off), a column that vanishes in the process is dropped (zero row
  // of R).
  Eigen::Matrix<double, 12, 5> Q = Eigen::Matrix<double, 12, 5>::Zero();
  Mat5 R = Mat5::Zero();
  const double cn = U.col(0).norm();
  for (int k = 0; k < 3; ++k) {
    Q.col(k) = U.col(k) / cn;
    R(k, k) = cn;
  }
  for (int j = 3; j < 3 + d.rank; ++j) {
    Vec12 q = U.col(j);
    const double scale = q.norm();
    for (int pass = 0; pass < 2; ++pass)
      for (int k = 0; k < j; ++k) {
        const double r = Q.col(k).dot(q);
        R(k, j) += r;
        q -= r * Q.col(k);
      }
    const double qn = q.norm();
    if (qn > 1e-12 * scale) {
      Q.col(j) = q / qn;
      R(j, j) = qn;
    }
  }
  const Mat5 T = R.lazyProduct(S).lazyProduct(R.transpose());
  const Eigen::SelfAdjointEigenSolver<Mat5> es(0.5 * (T + T.transpose()));
  const Eigen::Matrix<double, 5, 1> lambda = es.eigenvalues().cwiseMax(0.0);
  const Eigen::Matrix<double, 12, 5> V = Q.lazyProduct(es.eigenvectors());
  const Eigen::Matrix<double, 12, 5> VL = V * lambda.asDiagonal();
  hess = VL.lazyProduct(V.transpose());
}

// weight · B(s(x)) with its gradient / Hessian written (not added) from the
// structure; the Hessian of the given kind (PairHessian).
double structured_barrier(const Vec3* x, EdgeEdgeDistanceType type, double dhat, double weight, Vec12* grad,
                          Mat12* hess, PairHessian kind) {
  const DistanceStructure d = distance_structure(x, type);
  const SquaredBarrier B = squared_barrier(d.s, dhat, grad || hess);
  const double b1 = weight * B.first, b2 = weight * B.second;
  if (grad)
    for (int i = 0; i < 4; ++i) grad->segment<3>(3 * i) = (2.0 * b1 * d.c[static_cast<size_t>(i)]) * d.w;
  if (!hess) return weight * B.value;
  Mat3 K = (4.0 * b2) * d.w * d.w.transpose();
  K.diagonal().array() += 2.0 * b1;
  if (kind == PairHessian::GaussNewton) {
    // b''(d) = nᵀ K n (K = 4B''wwᵀ + 2B'I, w = d n), times (c cᵀ) ⊗ (n nᵀ)
    const Mat3 N = (d.w.dot(K * d.w) / (d.s * d.s)) * d.w * d.w.transpose();
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        hess->block<3, 3>(3 * i, 3 * j) = (d.c[static_cast<size_t>(i)] * d.c[static_cast<size_t>(j)]) * N;
  } else if (kind == PairHessian::Projected) {
    projected_structured_hessian(d, K, b1, *hess);
  } else {
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        hess->block<3, 3>(3 * i, 3 * j) = (d.c[static_cast<size_t>(i)] * d.c[static_cast<size_t>(j)]) * K;
    // rank-1 updates as outer products (a 12x2 by 2x12 product would go
    // through Eigen's general matrix product)
    if (d.rank == 1) {
      const Vec12 g0 = (b1 * d.M(0, 0)) * d.G.col(0);
      for (int j = 0; j < 12; ++j) hess->col(j) -= d.G(j, 0) * g0;
    } else if (d.rank == 2) {
      const Eigen::Matrix<double, 12, 2> GM = d.G * (b1 * d.M);
      for (int j = 0; j < 12; ++j) hess->col(j) -= d.G(j, 0) * GM.col(0) + d.G(j, 1) * GM.col(1);
    }
  }
  return weight * B.value;
}

}  // namespace

double edge_edge_barrier_derivatives(const Vec3& ea0, const Vec3& ea1, const Vec3& eb0, const Vec3& eb1,
                                     const PairBarrierParams& params, Vec12* grad, Mat12* hess, double weight) {
  return edge_edge_barrier_derivatives(ea0, ea1, eb0, eb1, params, grad, hess, weight, false);
}

double edge_edge_barrier_derivatives(const Vec3& ea0, const Vec3& ea1, const Vec3& eb0, const Vec3& eb1,
                                     const PairBarrierParams& params, Vec12* grad, Mat12* hess, double weight,
                                     bool project_psd) {
  return edge_edge_barrier_derivatives(ea0, ea1, eb0, eb1, params, grad, hess, weight,
                                       project_psd ? PairHessian::Projected : PairHessian::Exact);
}

double edge_edge_barrier_derivatives(const Vec3& ea0, const Vec3& ea1, const Vec3& eb0, const Vec3& eb1,
                                     const PairBarrierParams& params, Vec12* grad, Mat12* hess, double weight,
                                     PairHessian kind) {
  const bool project_psd = kind != PairHessian::Exact;
  const EdgeEdgeClosest closest = edge_edge_closest(ea0, ea1, eb0, eb1);
  const double dhat = params.dhat;
  if (closest.distance_squared >= dhat * dhat || !(closest.distance_squared > 0.0)) {
    if (grad) grad->setZero();
    if (hess) hess->setZero();
      return closest.distance_squared >= dhat * dhat ? 0.0 : std::numeric_limits<double>::infinity();
  }
  const Vec3 x[4] = {ea0, ea1, eb0, eb1};
  const double eps = params.parallel_threshold;
  const double A = (ea1 - ea0).squaredNorm(), B = (eb1 - eb0).squaredNorm();
  const double c = (A > 0.0 && B > 0.0 && eps > 0.0) ? edge_edge_sin2(ea0, ea1, eb0, eb1) : 1.0;
  if (c >= eps) return structured_barrier(x, closest.type, dhat, weight, grad, hess, kind);  // the common case: e = b(f)
  if (grad) grad->setZero();
  if (hess) hess->setZero();

  // Mollified band: e = P + m (T − P), T = b(f), P = ½ Σ_k b(d_k).
  Vec12 gT = Vec12::Zero(), gP = Vec12::Zero(), gc;
  Mat12 HT = Mat12::Zero(), HP = Mat12::Zero(), Hc;
  const bool d1 = grad || hess;
  const double T = add_edge_edge_term(x, closest.type, dhat, 1.0, d1 ? &gT : nullptr, hess ? &HT : nullptr);
  double P = 0.0;
  P += add_point_edge_term(x, 0, 2, 3, dhat, 0.5, d1 ? &gP : nullptr, hess ? &HP : nullptr);
  P += add_point_edge_term(x, 1, 2, 3, dhat, 0.5, d1 ? &gP : nullptr, hess ? &HP : nullptr);
  P += add_point_edge_term(x, 2, 0, 1, dhat, 0.5, d1 ? &gP : nullptr, hess ? &HP : nullptr);
  P += add_point_edge_term(x, 3, 0, 1, dhat, 0.5, d1 ? &gP : nullptr, hess ? &HP : nullptr);
  const double m = parallel_mollifier(c, eps);
  const double diff = T - P;
  if (d1) {
    edge_edge_sin2(ea0, ea1, eb0, eb1, &gc, hess ? &Hc : nullptr);
    const double m1 = parallel_mollifier_first_derivative(c, eps);
    const Vec12 gdiff = gT - gP;
    if (grad) *grad = weight * (gP + m * gdiff + (m1 * diff) * gc);
    if (hess) {
      const double m2 = parallel_mollifier_second_derivative(c, eps);
      *hess = HP + m * (HT - HP);
      hess->noalias() += m1 * (gc * gdiff.transpose() + gdiff * gc.transpose());
      hess->noalias() += (m2 * diff) * gc * gc.transpose();
      *hess += (m1 * diff) * Hc;
      *hess *= weight;
      if (project_psd) project_translation_invariant_to_psd(*hess);
    }
  }
  return weight * (P + m * diff);
}

double edge_edge_barrier(const Vec3& ea0, const Vec3& ea1, const Vec3& eb0, const Vec3& eb1,
                         const PairBarrierParams& params) {
  return edge_edge_barrier_derivatives(ea0, ea1, eb0, eb1, params, nullptr, nullptr);
}
Vec12 edge_edge_barrier_gradient(const Vec3& ea0, const Vec3& ea1, const Vec3& eb0, const Vec3& eb1,
                                 const PairBarrierParams& params) {
  Vec12 g;
  edge_edge_barrier_derivatives(ea0, ea1, eb0, eb1, params, &g, nullptr);
  return g;
}
Mat12 edge_edge_barrier_hessian(const Vec3& ea0, const Vec3& ea1, const Vec3& eb0, const Vec3& eb1,
                                const PairBarrierParams& params) {
  Mat12 H;
  edge_edge_barrier_derivatives(ea0, ea1, eb0, eb1, params, nullptr, &H);
  return H;
}

namespace {

/// Q = C ⊗ I₃: an orthonormal basis (12 by 9) of the complement of the
/// translations (t, t, t, t), from the Helmert contrasts of four points
/// (1, −1, 0, 0)/√2, (1, 1, −2, 0)/√6, (1, 1, 1, −3)/√12.
const Eigen::Matrix<double, 12, 9>& translation_complement() {
  static const Eigen::Matrix<double, 12, 9> Q = [] {
    Eigen::Matrix<double, 4, 3> C;
    C << 1, 1, 1, -1, 1, 1, 0, -2, 1, 0, 0, -3;
    C.col(0) /= std::sqrt(2.0);
    C.col(1) /= std::sqrt(6.0);
    C.col(2) /= std::sqrt(12.0);
    Eigen::Matrix<double, 12, 9> M = Eigen::Matrix<double, 12, 9>::Zero();
    for (int p = 0; p < 4; ++p)
      for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 3; ++k) M(3 * p + k, 3 * c + k) = C(p, c);
    return M;
  }();
  return Q;
}

}  // namespace

void project_translation_invariant_to_psd(Mat12& H) {
  const Eigen::Matrix<double, 12, 9>& Q = translation_complement();
  // (coefficient-based lazy products: the GEMM kernel is slower at these sizes)
  const Eigen::Matrix<double, 9, 12> QtH = Q.transpose().lazyProduct(H);
  const Mat9 R = QtH.lazyProduct(Q);
  Eigen::SelfAdjointEigenSolver<Mat9> es(R);
  const Eigen::Matrix<double, 9, 1> lambda = es.eigenvalues().cwiseMax(0.0);
  const Eigen::Matrix<double, 12, 9> V = Q.lazyProduct(es.eigenvectors());
  const Eigen::Matrix<double, 12, 9> VL = V * lambda.asDiagonal();
  H = VL.lazyProduct(V.transpose());
}

void project_to_psd(Mat12& H) {
  Eigen::SelfAdjointEigenSolver<Mat12> es(H);
  Vec12 lambda = es.eigenvalues();
  if (lambda.minCoeff() >= 0.0) return;
  lambda = lambda.cwiseMax(0.0);
  H = es.eigenvectors() * lambda.asDiagonal() * es.eigenvectors().transpose();
}

}  // namespace ek
