#pragma once
/// \file
/// Smallest eigenpairs of a sparse symmetric Hessian (stability, stiffness,
/// negative-curvature directions) with Spectra's Lanczos solver on the
/// shift-inverted operator P (H + sI)⁻¹ P, using a CHOLMOD factor of H + sI:
/// an eigenvalue μ of the operator gives λ = 1/μ - s of H. P projects out the
/// rigid-motion modes (translations and infinitesimal rotations of the
/// positions, and the uniform shift of the material angles when present),
/// which are zero modes of the elastic energy (paper Section 7.3, "Stiffness":
/// smallest positive eigenvalue with rigid motions excluded).
#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <vector>

#include "ek/core/types.hpp"

namespace ek {

/// How many eigenpairs smallest_eigenpairs() computes, and the Lanczos settings.
struct EigenOptions {
  int count = 1;               ///< [1] number of smallest eigenpairs wanted
  bool exclude_rigid = true;   ///< project out rigid-motion modes
  int subspace = 24;           ///< [1] Lanczos subspace size (ncv), > count
  int max_iterations = 2000;   ///< [1]
  double tolerance = 1e-10;    ///< [1] relative tolerance of the Ritz values
};

/// The smallest eigenpairs of H with rigid motions excluded.
struct EigenResult {
  /// Whether the pairs were computed: false when no shift up to 60 tries made
  /// H + sI factorise, the subspace left too few dofs, or Lanczos did not
  /// converge (values and vectors are then empty).
  bool converged = false;
  VecX values;                 ///< ascending eigenvalues of H
  Eigen::MatrixXd vectors;     ///< dofs by count, unit columns
  double shift = 0.0;          ///< s used for the shift-invert
};

/// Orthonormal basis (dofs by k) of the rigid-motion modes: three
/// translations and three rotations about the centroid acting on the
/// position dofs 0..3n-1 (n = positions.rows()), plus, when
/// `theta_begin` >= 0, the uniform shift of the n material angles stored at
/// dofs theta_begin .. theta_begin + n - 1; then a rotation ω also moves each
/// material angle by ω·t_j (t_j the unit tangent of edge j), which makes it an
/// exact zero mode of the twisting energy.
/// With `planar_slab` only the motions that also leave the planarity slab
/// |z| < h (slab.hpp) invariant are returned: the translations along x and y
/// and the rotation about the z axis (plus the θ shift). The slab's energy
/// changes to second order under the other three wherever a vertex is within
/// its activation distance of a plane, so removing them from a Newton step
/// removes real curvature (measured: the flat coil of 12a_1019 stalled at
/// ||g|| ≈ 2e-2 with them; it converges in 186 iterations without).
Eigen::MatrixXd rigid_modes(const Points& positions, int dofs, int theta_begin = -1, bool planar_slab = false);

/// The `options.count` smallest eigenpairs of the symmetric matrix given by
/// its upper triangle. `base_shift` > 0 is the first shift tried for
/// positive definiteness (raised ×10 until H + sI factorises).
EigenResult smallest_eigenpairs(const Eigen::SparseMatrix<double, Eigen::ColMajor, int>& upper,
                                const Eigen::MatrixXd& excluded_modes, double base_shift,
                                const EigenOptions& options = {});

}  // namespace ek
