#pragma once
/// \file
/// Basic array types.
///
/// A closed curve (polygon) with n vertices is a `Points` array, n by 3, one
/// vertex per row; edge i joins vertex i to vertex (i + 1) mod n. The storage
/// is row-major so that the coordinates form the flat vector
/// x = (x0, y0, z0, x1, y1, z1, ...) of length 3n used by the solvers
/// (see as_vector()).
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace ek {

using Vec3 = Eigen::Vector3d;  ///< A point or vector in space (3).
using Mat3 = Eigen::Matrix3d;  ///< A 3 by 3 matrix (rotations, frames, local Hessians).
using Vec2 = Eigen::Vector2d;  ///< A point in the plane (2).
using VecX = Eigen::VectorXd;  ///< A vector of any length (flat coordinates 3n, per-vertex or per-edge values).
/// n by 3, one point per row, row-major.
using Points = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

/// View of the n by 3 array as a flat vector of length 3n (no copy).
inline Eigen::Map<VecX> as_vector(Points& P) { return {P.data(), P.size()}; }
/// Read-only view of P as a flat vector of length 3n (no copy).
inline Eigen::Map<const VecX> as_vector(const Points& P) { return {P.data(), P.size()}; }

/// Copy of a flat vector of length 3n as an n by 3 array.
inline Points as_points(const Eigen::Ref<const VecX>& x) {
  Points P(x.size() / 3, 3);
  as_vector(P) = x;
  return P;
}

}  // namespace ek
