#pragma once
/// \file
/// The IPC barrier and the contact energy of one pair of segments (paper
/// Section 6, "Contact Handling"; Li et al.\ 2020, "Incremental Potential
/// Contact", eq.\ 6 and Section 4.3).
///
/// Barrier (in the distance d, not its square):
/// ~~~{.unparsed}
///   b(d) = −(d − d̂)² ln(d / d̂)   for 0 < d < d̂,      0 for d >= d̂,
///   b'(d)  = −2 (d − d̂) ln(d/d̂) − (d − d̂)²/d,
///   b''(d) = −2 ln(d/d̂) − 4 (d − d̂)/d + (d − d̂)²/d².
/// ~~~
/// b, b' and b'' vanish at d̂ (b is C2 there), b → +∞ as d → 0; units length².
/// The kernels work with the squared distance s = d² (distance.hpp) and the
/// chain rule B(s) = b(√s), B'(s) = b'(d)/(2d), B''(s) = (b''(d) − b'(d)/d)/(4d²).
///
/// Pair energy. For segments A = [ea0, ea1] and B = [eb0, eb1] with segment
/// distance f (distance.hpp, the exact minimum over both segments):
/// ~~~{.unparsed}
///   e(x) = b(f)                                     if sin²θ >= ε,
///   e(x) = m(c) b(f) + (1 − m(c)) · ½ Σ_k b(d_k)   if c = sin²θ < ε,
/// ~~~
/// where θ is the angle between the segments, c = sin²θ = 1 − (a·b)²/(|a|²|b|²),
/// m(c) = (c/ε)(2 − c/ε) the IPC mollifier (m(0) = 0, m(ε) = 1, m'(ε) = 0),
/// ε = parallel_threshold, and d_k the four endpoint-to-segment distances
/// (ea0 and ea1 against B, eb0 and eb1 against A; each exact, C1).
///
/// Why: f has a concave kink at exactly parallel segments with overlapping
/// projections (the closest pair jumps from one end of the overlap to the
/// other), so b(f) has a convex kink there, and nearly parallel contact is
/// common along strands that lie side by side. m vanishes quadratically in the
/// angle, which removes the kink (m·b(f) is C1), and the endpoint sum, C1 by
/// itself, carries the contact at and near parallel; for parallel segments the
/// two ends of the overlap are two of the d_k, hence the factor ½ so that the
/// blend changes the energy little across the band. The pair energy is C1
/// everywhere (C2 except where a closest-feature case or the band edge
/// switches) and still tends to +∞ whenever the two segments touch: a contact
/// at a parallel or nearly parallel pair is always at an endpoint of the
/// overlap (some d_k → 0) or m > 0. Zero whenever f >= d̂.
#include "ek/contact/distance.hpp"

namespace ek {

/// b(d) for distance d (> 0) and barrier distance dhat; 0 for d >= dhat, +∞ for d <= 0.
double barrier(double d, double dhat);
/// b'(d).
double barrier_first_derivative(double d, double dhat);
/// b''(d).
double barrier_second_derivative(double d, double dhat);

/// The mollifier m(c) = (c/ε)(2 − c/ε) for c < ε, 1 otherwise, and its first
/// and second derivatives in c.
double parallel_mollifier(double c, double eps);
double parallel_mollifier_first_derivative(double c, double eps);   ///< m'(c).
double parallel_mollifier_second_derivative(double c, double eps);  ///< m''(c).

/// sin² of the angle between a = ea1 − ea0 and b = eb1 − eb0,
/// c = 1 − (a·b)²/(|a|²|b|²), with gradient and Hessian in the dofs
/// (ea0, ea1, eb0, eb1) (grad / hess may be null). Needs a, b != 0.
double edge_edge_sin2(const Vec3& ea0, const Vec3& ea1, const Vec3& eb0, const Vec3& eb1, Vec12* grad = nullptr,
                      Mat12* hess = nullptr);

/// Parameters of the pair energy.
struct PairBarrierParams {
  double dhat = 0.4;                 ///< [length] barrier distance d̂
  double parallel_threshold = 1e-3;  ///< [1] ε: the mollifier acts where sin²θ < ε
};

/// Pair energy e(x) described above (not multiplied by the stiffness ω);
/// dofs (ea0, ea1, eb0, eb1). +∞ when the segments touch.
double edge_edge_barrier(const Vec3& ea0, const Vec3& ea1, const Vec3& eb0, const Vec3& eb1,
                         const PairBarrierParams& params);
/// Gradient (12) of edge_edge_barrier() in the dofs (ea0, ea1, eb0, eb1);
/// zero when the pair is farther than d̂.
Vec12 edge_edge_barrier_gradient(const Vec3& ea0, const Vec3& ea1, const Vec3& eb0, const Vec3& eb1,
                                 const PairBarrierParams& params);
/// Hessian (12 by 12) of edge_edge_barrier() in the dofs (ea0, ea1, eb0, eb1);
/// zero when the pair is farther than d̂.
Mat12 edge_edge_barrier_hessian(const Vec3& ea0, const Vec3& ea1, const Vec3& eb0, const Vec3& eb1,
                                const PairBarrierParams& params);

/// weight · e and its gradient and Hessian in one call (grad / hess may be
/// null; they are set to zero when the pair is farther than d̂).
double edge_edge_barrier_derivatives(const Vec3& ea0, const Vec3& ea1, const Vec3& eb0, const Vec3& eb1,
                                     const PairBarrierParams& params, Vec12* grad, Mat12* hess, double weight = 1.0);
/// The same with the Hessian projected to the nearest positive semidefinite
/// matrix when project_psd (equal to project_to_psd(hess) up to round-off).
/// Outside the nearly parallel band the Hessian is U S Uᵀ with U of at most 5
/// columns (the closest points' weights c ⊗ I₃ and the at most 2 directions
/// in which the closest-point parameters move), so the projection is a 5 by
/// 5 eigen-decomposition; in the band, project_translation_invariant_to_psd.
double edge_edge_barrier_derivatives(const Vec3& ea0, const Vec3& ea1, const Vec3& eb0, const Vec3& eb1,
                                     const PairBarrierParams& params, Vec12* grad, Mat12* hess, double weight,
                                     bool project_psd);

/// Which Hessian of the pair energy edge_edge_barrier_derivatives() gives.
enum class PairHessian {
  Exact,      ///< the exact Hessian (indefinite in general)
  Projected,  ///< the nearest positive semidefinite matrix (eigenvalues clamped at 0)
  /// Gauss–Newton: b''(f) ∇f ∇fᵀ, positive semidefinite by construction (b'' > 0
  /// on (0, d̂)), without the term b'(f) ∇²f of the distance's curvature, the
  /// only one that can be indefinite. ∇f = c ⊗ n for the closest points'
  /// weights c and the unit normal n between them, so it costs an outer
  /// product and no eigen-decomposition. In the nearly parallel band the
  /// projected Hessian is used instead.
  GaussNewton,
};

/// The same with the Hessian chosen by `kind` (Exact and Projected as
/// project_psd false and true).
double edge_edge_barrier_derivatives(const Vec3& ea0, const Vec3& ea1, const Vec3& eb0, const Vec3& eb1,
                                     const PairBarrierParams& params, Vec12* grad, Mat12* hess, double weight,
                                     PairHessian kind);

/// Projects a symmetric 12 by 12 matrix to the nearest positive semidefinite
/// one (eigenvalues clamped at 0), in place.
void project_to_psd(Mat12& H);

/// The same for a matrix that annihilates translations (H·(t, t, t, t) = 0
/// for every t ∈ R³), as every pair Hessian above does (the pair energy
/// depends on differences of the four points only): H = Q (Qᵀ H Q) Qᵀ with
/// Q = C ⊗ I₃ (12 by 9), C the 4 by 3 orthonormal Helmert contrasts, so the
/// eigenvalues are clamped in the 9 by 9 matrix Qᵀ H Q (about a third of the
/// cost of the 12 by 12 eigen-decomposition). Equal to project_to_psd(H)
/// up to round-off; the result annihilates translations too.
void project_translation_invariant_to_psd(Mat12& H);

}  // namespace ek
