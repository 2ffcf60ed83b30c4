#pragma once
/// \file
/// The best rigid motion between two point sets in correspondence (Kabsch,
/// Acta Cryst. A32, 1976; proper rotations only, as in Umeyama, IEEE PAMI
/// 13, 1991): with centred points y_c = y − ȳ, x_c = x − x̄ and the
/// cross-covariance H = Σ_k y_c,k x_c,kᵀ = U Σ Vᵀ (SVD),
///
/// ~~~{.unparsed}
///   R = V diag(1, 1, sign det(V Uᵀ)) Uᵀ,   t = x̄ − R ȳ,
/// ~~~
///
/// minimise Σ_k |R y_k + t − x_k|² over rotations (det R = +1) and
/// translations, and the minimum is |Y_c|² + |X_c|² − 2(σ1 + σ2 + sign(det H) σ3).
/// Used to align curves (the cross-topology search, Section 8.1) and states
/// (the double-ended saddle search).
#include "ek/geometry/types.hpp"

namespace ek {

/// x ↦ R x + t.
struct RigidMotion {
  Mat3 R = Mat3::Identity();  ///< [1] proper rotation
  Vec3 t = Vec3::Zero();      ///< [length]
  /// Y moved: rows R y_k + t (Y m by 3).
  Points apply(const Points& Y) const;
};

/// The motion of Y (m by 3) that best matches X (m by 3, row k with row k).
/// Throws std::invalid_argument for unequal shapes or no point.
RigidMotion best_rigid_motion(const Points& Y, const Points& X);

/// Y moved by best_rigid_motion(Y, X), computed as (y − ȳ) Rᵀ + x̄ (rows).
Points align_onto(const Points& Y, const Points& X);

/// The least Σ|R y + t − x|² from the centred cross-covariance H and the
/// centred squared norms |Y_c|² + |X_c|² (the formula above; it may come out
/// a rounding error below 0).
double rigid_residual(const Mat3& H, double centred_norms);

}  // namespace ek
