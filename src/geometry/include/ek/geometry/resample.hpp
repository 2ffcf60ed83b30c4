#pragma once
/// \file
/// Resampling closed polygons.
#include "ek/geometry/types.hpp"

namespace ek {

/// m points at equal arc-length spacing L/m along the closed polygon P,
/// starting at vertex 0 (linear interpolation along the edges).
Points resample_arclength(const Points& P, int m);

/// Result of resample_equilateral().
struct EquilateralResult {
  Points points;               ///< m by 3
  double edge_length = 0.0;    ///< [length] the common chord length h
  double max_deviation = 0.0;  ///< [length] max over edges of |edge length - h|
};

/// m points on the closed polygon P, starting at vertex 0, such that every
/// chord between consecutive points (including the closing one) has the same
/// length h. Each point is the first point further along P at distance h from
/// the previous one; h is found by bracketing and bisection so that the m-th
/// point returns to the start. Needs m >= 4 and a curve that is not folded
/// back on itself within h. max_deviation reports how equal the result is
/// (typically 1e-12 relative).
EquilateralResult resample_equilateral(const Points& P, int m);

/// Subdivides every edge into pieces no longer than `max_edge` (each edge into
/// ceil(|e|/max_edge) equal parts). The polygon's shape is unchanged.
Points refine(const Points& P, double max_edge);

}  // namespace ek
