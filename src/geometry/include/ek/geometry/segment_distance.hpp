#pragma once
/// \file
/// Closest points between two segments in 3D (value only; the contact module
/// has the differentiable kernels).
#include "ek/geometry/types.hpp"

namespace ek {

/// Closest points of segments [p0, p1] and [q0, q1]: returns the squared
/// distance |p(s) - q(t)|² with p(s) = p0 + s (p1 - p0), q(t) = q0 + t (q1 - q0),
/// s, t in [0, 1], and writes the parameters of one closest pair. Handles
/// parallel and degenerate (zero-length) segments.
double segment_segment_distance_squared(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1,
                                        double* s = nullptr, double* t = nullptr);

/// Squared distance from point x to segment [a, b]; writes the parameter of the closest point.
double point_segment_distance_squared(const Vec3& x, const Vec3& a, const Vec3& b, double* t = nullptr);

}  // namespace ek
