#pragma once
/// \file
/// Local kernels of the discrete elastic rod (Bergou et al.\ 2008, "Discrete
/// Elastic Rods"; Bergou et al.\ 2010, "Discrete Viscous Threads"; paper
/// Section 6). Each kernel is a trio value / gradient / Hessian of free
/// functions on fixed-size Eigen types; ElasticRod assembles them over the
/// closed curve.
///
/// Stencils and orderings:
///  - an edge kernel takes the edge vector e (3); gradient 3, Hessian 3 by 3;
///  - a vertex kernel takes the two edge vectors a = e_{i-1} = x_i - x_{i-1}
///    and b = e_i = x_{i+1} - x_i meeting at vertex i; gradients are 6-vectors
///    (∂/∂a, ∂/∂b) and Hessians 6 by 6 in that order. to_vertices() maps them
///    to the 9 coordinates (x_{i-1}, x_i, x_{i+1}).
#include <Eigen/Core>

#include "ek/geometry/types.hpp"

/// The rod's local kernels (value, gradient, Hessian of one stencil), which
/// ElasticRod assembles.
namespace ek::rod {

using Vec6 = Eigen::Matrix<double, 6, 1>;  ///< Gradient of a vertex kernel: (∂/∂a, ∂/∂b).
using Mat6 = Eigen::Matrix<double, 6, 6>;  ///< Hessian of a vertex kernel in the edge vectors (a, b).
using Vec9 = Eigen::Matrix<double, 9, 1>;  ///< Gradient in the coordinates of three vertices (x_{i-1}, x_i, x_{i+1}).
using Mat9 = Eigen::Matrix<double, 9, 9>;  ///< Hessian in the coordinates of three vertices (x_{i-1}, x_i, x_{i+1}).

// ---------------------------------------------------------------------------
// Stretching of one edge
// ---------------------------------------------------------------------------

/// E = EA/2 (|e|/l̄ - 1)² l̄ = EA (|e| - l̄)² / (2 l̄) for the edge vector e
/// with rest length l̄ > 0 and stretching stiffness EA (Bergou et al.\ 2010).
double stretch_energy(const Vec3& e, double rest_length, double EA);
/// ∂E/∂e = EA/l̄ (|e| - l̄) ê.
Vec3 stretch_gradient(const Vec3& e, double rest_length, double EA);
/// ∂²E/∂e² = EA/l̄ [ê êᵀ + (1 - l̄/|e|)(I - ê êᵀ)].
Mat3 stretch_hessian(const Vec3& e, double rest_length, double EA);
/// The nearest positive semidefinite matrix to stretch_hessian() (its
/// eigenvalues are EA/l̄ along ê and EA/l̄ (1 - l̄/|e|) twice across, negative
/// for a compressed edge |e| < l̄): EA/l̄ [ê êᵀ + max(0, 1 - l̄/|e|)(I - ê êᵀ)].
/// Equal to stretch_hessian() for |e| >= l̄. Used by solvers for descent
/// directions far from equilibrium (a per-element projection, as in IPC).
Mat3 stretch_hessian_projected(const Vec3& e, double rest_length, double EA);

// ---------------------------------------------------------------------------
// Curvature binormal and bending
// ---------------------------------------------------------------------------

/// Discrete curvature binormal (κb) = 2 a × b / (|a||b| + a·b) at the vertex
/// joining edges a and b (Bergou et al.\ 2008, eq.\ 1). |κb| = 2 tan(φ/2) for
/// the turning angle φ; dimensionless (an integrated curvature: the pointwise
/// curvature is |κb| / l̄ with the Voronoi length l̄).
Vec3 curvature_binormal(const Vec3& a, const Vec3& b);

/// |κb|² = 4 (|a||b| - a·b) / (|a||b| + a·b) = 4 tan²(φ/2). The bending
/// energy at the vertex is EI/(2 l̄_i) |κb|² (isotropic cross-section,
/// straight rest shape).
double kb_squared(const Vec3& a, const Vec3& b);
/// Gradient of |κb|² with respect to (a, b).
Vec6 kb_squared_gradient(const Vec3& a, const Vec3& b);
/// Hessian of |κb|² with respect to (a, b).
Mat6 kb_squared_hessian(const Vec3& a, const Vec3& b);
/// Adds `scale` times the same Hessian's blocks ∂²/∂a², ∂²/∂a∂b, ∂²/∂b²
/// (∂²/∂b∂a = H_abᵀ) to Haa, Hab, Hbb, without forming the 6 by 6 matrix
/// (assembly fast path).
void add_kb_squared_hessian_blocks(const Vec3& a, const Vec3& b, double scale, Mat3& Haa, Mat3& Hab, Mat3& Hbb);

// ---------------------------------------------------------------------------
// Spherical geometry of unit tangents
// ---------------------------------------------------------------------------

/// Parallel transport of v from the unit vector a to the unit vector b: the
/// rotation about a × b by the angle between them (the minimal rotation taking
/// a to b), P v = v - (b·v)/(1 + a·b) (a + b) for v ⟂ a. Undefined for b = -a.
Vec3 parallel_transport(const Vec3& a, const Vec3& b, const Vec3& v);

/// Signed angle in (-π, π] from u to v about the axis (u, v ⟂ axis).
double signed_angle(const Vec3& u, const Vec3& v, const Vec3& axis);

/// Signed area of the geodesic triangle (a, b, c) on the unit sphere (the
/// solid angle it subtends), positive when a, b, c turn counterclockwise seen
/// from outside: Ω = 2 atan2(a·(b×c), 1 + a·b + b·c + c·a) (Van Oosterom and
/// Strackee 1983). a, b, c unit vectors; Ω ∈ (-2π, 2π).
double solid_angle(const Vec3& a, const Vec3& b, const Vec3& c);
/// Gradient of Ω with respect to (b, c) (a held fixed), treating b, c as free
/// 3-vectors in the formula above (the caller applies the chain rule of
/// b = e/|e|).
Vec6 solid_angle_gradient(const Vec3& a, const Vec3& b, const Vec3& c);
/// Hessian of Ω with respect to (b, c).
Mat6 solid_angle_hessian(const Vec3& a, const Vec3& b, const Vec3& c);

// ---------------------------------------------------------------------------
// Reference twist
// ---------------------------------------------------------------------------

/// Change of the reference twist at a vertex when its edges move from the
/// source unit tangents (s_a, s_b) to the edge vectors (a, b) and the
/// reference directors follow by time-parallel transport (Bergou et al.\ 2010,
/// Section 4.2): m = m_source + Δm with
///   Δm = -[Ω(s_a, t_a, t_b) + Ω(s_a, t_b, s_b)],   t = e/|e|,
/// minus the signed area of the geodesic quadrilateral s_a → t_a → t_b → s_b:
/// by the holonomy of parallel transport on the unit sphere, transporting the
/// source director of edge a along s_a → t_a → t_b differs from transporting it
/// along s_a → s_b → t_b by a rotation about t_b through that area. The formula
/// is exact (not a linearisation) and smooth, so the reference twist never
/// jumps by 2π while the tangents stay away from antipodal configurations; it
/// is 0 at (t_a, t_b) = (s_a, s_b), and its gradient there is
/// (κb/(2|a|), κb/(2|b|)) (Bergou et al. 2010, eq. 9).
double reference_twist_change(const Vec3& sa, const Vec3& sb, const Vec3& a, const Vec3& b);
/// Gradient of Δm with respect to (a, b).
Vec6 reference_twist_change_gradient(const Vec3& sa, const Vec3& sb, const Vec3& a, const Vec3& b);
/// Hessian of Δm with respect to (a, b).
Mat6 reference_twist_change_hessian(const Vec3& sa, const Vec3& sb, const Vec3& a, const Vec3& b);
/// Gradient g and Hessian H of Δm in one pass (assembly fast path).
void reference_twist_change_derivatives(const Vec3& sa, const Vec3& sb, const Vec3& a, const Vec3& b, Vec6& g,
                                        Mat6& H);

// ---------------------------------------------------------------------------
// Edge to vertex coordinates
// ---------------------------------------------------------------------------

/// Gradient with respect to (x_{i-1}, x_i, x_{i+1}) of a function of
/// (a, b) = (x_i - x_{i-1}, x_{i+1} - x_i), from its gradient g = (∂/∂a, ∂/∂b).
Vec9 to_vertices(const Vec6& g);
/// Hessian with respect to (x_{i-1}, x_i, x_{i+1}) from the Hessian with
/// respect to (a, b): Mᵀ H M with M = [[-I, I, 0], [0, -I, I]].
Mat9 to_vertices(const Mat6& H);

}  // namespace ek::rod
