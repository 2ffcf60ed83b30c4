#pragma once
/// \file
/// Differentiable squared distances between the closest features of two
/// segments (paper Section 6, "Contact Handling"; the distance types of
/// Li et al.\ 2020, "Incremental Potential Contact", Section 4 and supplement).
///
/// Every kernel is a trio of free functions with the same arguments: the value,
/// the gradient and the Hessian of a SQUARED distance s = d², on fixed-size
/// Eigen types (nothing allocates). The dof order of a gradient / Hessian is
/// the order of the arguments, each point contributing (x, y, z):
/// ~~~{.unparsed}
///   point_point (p, q)                 6 dofs
///   point_line  (p, e0, e1)            9 dofs
///   line_line   (ea0, ea1, eb0, eb1)  12 dofs
/// ~~~
///
/// Formulas. Each squared distance is s(x) = min_u g(x, u), g = |w(x, u)|²,
/// where w is the vector between the two closest points and u their free
/// parameters (none, t on the line, or (s, t) on two lines). At the unique
/// minimiser u*(x) (envelope theorem / implicit function theorem):
/// ~~~{.unparsed}
///   ∇s  = g_x = 2 Jᵀ w,                       J = ∂w/∂x (3 by dofs, u fixed)
///   ∇²s = g_xx − g_xu g_uu⁻¹ g_ux,            g_xx = 2 JᵀJ
/// ~~~
/// which is exact (it is the Hessian of the closed-form |(p−e0)×e|²/|e|² and
/// |(ea0−eb0)·(a×b)|²/|a×b|²) and avoids their cancellation-prone quotients.
///
/// Segment pairs. The squared distance between segments [ea0, ea1] and
/// [eb0, eb1] is the minimum over the unit square of g; its minimiser lies
/// either inside (edge-edge interior, type EA_EB: the line-line distance), or
/// on a side of the square (one endpoint against the other segment): a
/// point-line distance (EA0_EB, EA1_EB, EA_EB0, EA_EB1) or, when that point's
/// projection falls outside the segment, a point-point distance (EA0_EB0,
/// EA0_EB1, EA1_EB0, EA1_EB1). edge_edge_distance_type() picks the case;
/// the segment-pair trio evaluates the chosen case's formula and scatters it
/// into the 12 dofs (ea0, ea1, eb0, eb1). The result is the exact segment
/// distance, continuous everywhere and C1 wherever the closest pair of points
/// is unique, i.e. everywhere except for exactly parallel segments whose
/// projections overlap (there it has a concave kink; the barrier in
/// barrier.hpp removes it with a mollifier).
///
/// Nearly parallel segments: the interior case is used only when
/// sin²(angle) = |a×b|²/(|a|²|b|²) > kParallelSin2 (1e-10); below that the
/// interior minimiser is ill-conditioned and the minimum over the square is
/// taken over the four sides (for parallel segments a minimiser always lies on
/// a side, so the value stays exact up to O(kParallelSin2 · length²)).
#include <Eigen/Core>
#include <array>

#include "ek/geometry/types.hpp"

namespace ek {

using Vec6 = Eigen::Matrix<double, 6, 1>;     ///< Gradient in the dofs of 2 points (x, y, z each).
using Vec9 = Eigen::Matrix<double, 9, 1>;     ///< Gradient in the dofs of 3 points (x, y, z each).
using Vec12 = Eigen::Matrix<double, 12, 1>;   ///< Gradient in the dofs of 4 points (x, y, z each).
using Mat6 = Eigen::Matrix<double, 6, 6>;     ///< Hessian in the dofs of 2 points.
using Mat9 = Eigen::Matrix<double, 9, 9>;     ///< Hessian in the dofs of 3 points.
using Mat12 = Eigen::Matrix<double, 12, 12>;  ///< Hessian in the dofs of 4 points.

/// Below this sin² of the angle between two segments the edge-edge interior
/// case is not used (see the file comment).
inline constexpr double kParallelSin2 = 1e-10;

// ---------------------------------------------------------------------------
// Point-point: s = |p − q|².

/// s = |p − q|² [length²].
double point_point_distance_squared(const Vec3& p, const Vec3& q);
Vec6 point_point_distance_squared_gradient(const Vec3& p, const Vec3& q);  ///< ∇s in the dofs (p, q).
Mat6 point_point_distance_squared_hessian(const Vec3& p, const Vec3& q);   ///< ∇²s in the dofs (p, q).

// ---------------------------------------------------------------------------
// Point-line: s = |(p − e0) × e|² / |e|², e = e1 − e0 (distance from p to the
// infinite line through e0 and e1; e0 != e1). Closest point e0 + t e with
// t = (p − e0)·e / |e|².

/// s = |(p − e0) × e|² / |e|² [length²], e = e1 − e0 (e0 != e1).
double point_line_distance_squared(const Vec3& p, const Vec3& e0, const Vec3& e1);
/// ∇s in the dofs (p, e0, e1).
Vec9 point_line_distance_squared_gradient(const Vec3& p, const Vec3& e0, const Vec3& e1);
/// ∇²s in the dofs (p, e0, e1).
Mat9 point_line_distance_squared_hessian(const Vec3& p, const Vec3& e0, const Vec3& e1);

// ---------------------------------------------------------------------------
// Line-line: s = ((ea0 − eb0)·n)² / |n|², n = a × b, a = ea1 − ea0,
// b = eb1 − eb0 (the lines must not be parallel). Closest points ea0 + s a and
// eb0 + t b with (s, t) solving [a·a, −a·b; −a·b, b·b] (s, t) = (−a·r, b·r),
// r = ea0 − eb0.

/// s = ((ea0 − eb0)·n)² / |n|² [length²], n = a × b (the lines not parallel).
double line_line_distance_squared(const Vec3& ea0, const Vec3& ea1, const Vec3& eb0, const Vec3& eb1);
/// ∇s in the dofs (ea0, ea1, eb0, eb1).
Vec12 line_line_distance_squared_gradient(const Vec3& ea0, const Vec3& ea1, const Vec3& eb0, const Vec3& eb1);
/// ∇²s in the dofs (ea0, ea1, eb0, eb1).
Mat12 line_line_distance_squared_hessian(const Vec3& ea0, const Vec3& ea1, const Vec3& eb0, const Vec3& eb1);

// ---------------------------------------------------------------------------
// Point-segment (point p against segment [e0, e1]).

/// Closest feature of segment [e0, e1] to p: the endpoint e0 (P_E0), e1
/// (P_E1), or the interior (P_E, point-line distance).
enum class PointEdgeDistanceType { P_E0, P_E1, P_E };

/// The closest feature of [e0, e1] to p.
PointEdgeDistanceType point_edge_distance_type(const Vec3& p, const Vec3& e0, const Vec3& e1);
/// The chosen case's squared distance (the exact point-segment distance when
/// `type` is point_edge_distance_type(p, e0, e1)); dofs (p, e0, e1).
double point_edge_distance_squared(const Vec3& p, const Vec3& e0, const Vec3& e1, PointEdgeDistanceType type);
/// Gradient (9) of the chosen case in the dofs (p, e0, e1).
Vec9 point_edge_distance_squared_gradient(const Vec3& p, const Vec3& e0, const Vec3& e1, PointEdgeDistanceType type);
/// Hessian (9 by 9) of the chosen case in the dofs (p, e0, e1).
Mat9 point_edge_distance_squared_hessian(const Vec3& p, const Vec3& e0, const Vec3& e1, PointEdgeDistanceType type);

// ---------------------------------------------------------------------------
// Segment-segment ([ea0, ea1] against [eb0, eb1]).

/// Closest features of two segments: interior-interior (EA_EB), an endpoint
/// against the other segment's interior (EA0_EB, ...), or two endpoints
/// (EA0_EB0, ...).
enum class EdgeEdgeDistanceType {
  EA_EB,    ///< Interior of a against interior of b (line-line distance).
  EA0_EB,   ///< Endpoint ea0 against the interior of b (point-line).
  EA1_EB,   ///< Endpoint ea1 against the interior of b (point-line).
  EA_EB0,   ///< Endpoint eb0 against the interior of a (point-line).
  EA_EB1,   ///< Endpoint eb1 against the interior of a (point-line).
  EA0_EB0,  ///< Endpoints ea0 and eb0 (point-point).
  EA0_EB1,  ///< Endpoints ea0 and eb1 (point-point).
  EA1_EB0,  ///< Endpoints ea1 and eb0 (point-point).
  EA1_EB1   ///< Endpoints ea1 and eb1 (point-point).
};

/// Short name of a type ("EA_EB", "EA0_EB1", ...).
const char* to_string(EdgeEdgeDistanceType type);

/// The case that realises the segment distance (ties go to the first case in
/// the order EA_EB, EA0_EB*, EA1_EB*, EA_EB0/EB0*, EA_EB1/EB1*).
EdgeEdgeDistanceType edge_edge_distance_type(const Vec3& ea0, const Vec3& ea1, const Vec3& eb0, const Vec3& eb1);

/// Classification and value in one pass (the squared segment distance).
struct EdgeEdgeClosest {
  EdgeEdgeDistanceType type = EdgeEdgeDistanceType::EA_EB;  ///< The closest features (edge_edge_distance_type()).
  double distance_squared = 0.0;  ///< [length²]
};
/// edge_edge_distance_type() and the squared distance of that case.
EdgeEdgeClosest edge_edge_closest(const Vec3& ea0, const Vec3& ea1, const Vec3& eb0, const Vec3& eb1);

/// Parameters (s, t) of the closest points ea0 + s (ea1 − ea0) and
/// eb0 + t (eb1 − eb0) for the case `type` (endpoint cases give 0 or 1).
void edge_edge_closest_parameters(const Vec3& ea0, const Vec3& ea1, const Vec3& eb0, const Vec3& eb1,
                                  EdgeEdgeDistanceType type, double* s, double* t);

/// The chosen case's squared distance, scattered into the dofs (ea0, ea1, eb0, eb1).
double edge_edge_distance_squared(const Vec3& ea0, const Vec3& ea1, const Vec3& eb0, const Vec3& eb1,
                                  EdgeEdgeDistanceType type);
/// Gradient (12) of the chosen case in the dofs (ea0, ea1, eb0, eb1).
Vec12 edge_edge_distance_squared_gradient(const Vec3& ea0, const Vec3& ea1, const Vec3& eb0, const Vec3& eb1,
                                          EdgeEdgeDistanceType type);
/// Hessian (12 by 12) of the chosen case in the dofs (ea0, ea1, eb0, eb1).
Mat12 edge_edge_distance_squared_hessian(const Vec3& ea0, const Vec3& ea1, const Vec3& eb0, const Vec3& eb1,
                                         EdgeEdgeDistanceType type);

/// Value, gradient and Hessian in one call (any of grad / hess may be null);
/// the same numbers as the trio. Used by the barrier assembly.
double edge_edge_distance_squared_derivatives(const Vec3& ea0, const Vec3& ea1, const Vec3& eb0, const Vec3& eb1,
                                              EdgeEdgeDistanceType type, Vec12* grad, Mat12* hess);

/// Point-segment value/gradient/Hessian in one call, in the 9 dofs (p, e0, e1).
double point_edge_distance_squared_derivatives(const Vec3& p, const Vec3& e0, const Vec3& e1,
                                               PointEdgeDistanceType type, Vec9* grad, Mat9* hess);

}  // namespace ek
