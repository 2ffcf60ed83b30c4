#pragma once
/// \file
/// Planarity slab: a barrier that keeps every vertex between the planes
/// z = -h and z = +h (used to flatten multi-covered circles for jumping knots,
/// paper Section 8.3, "relax under the planarity slab").
///
/// E_slab = κ Σ_i [ b(h - z_i) + b(h + z_i) ],
/// b(d) = -(d - d̂)² ln(d / d̂) for 0 < d < d̂, 0 for d >= d̂ (the IPC barrier
/// of Li et al. 2020 on the distance to each plane, ek::barrier of the contact
/// module), d̂ = `activation` · h.
/// It is C² at d = d̂ and → ∞ as a vertex reaches a plane; max_step() keeps
/// every vertex strictly inside.
#include "ek/core/sparse_assembler.hpp"
#include "ek/geometry/types.hpp"

namespace ek {

/// The slab's thickness and barrier (E_slab above).
struct SlabOptions {
  double half_thickness = 0.5;  ///< [length] h: vertices stay in |z| < h
  double activation = 0.5;      ///< [1] the barrier acts within activation·h of a plane
  double stiffness = 1.0;       ///< [energy] κ
  double separation = 0.1;      ///< [1] max_step keeps at least this fraction of the current distance to a plane
  void validate() const;        ///< std::invalid_argument unless h > 0, activation ∈ (0, 1], κ > 0, separation ∈ (0, 1)
};

/// The barrier E_slab that keeps every vertex in |z| < h, with its gradient,
/// Hessian and step bound.
class PlanaritySlab {
 public:
  explicit PlanaritySlab(SlabOptions options);       ///< Validates `options` (SlabOptions::validate()).
  const SlabOptions& options() const { return o_; }  ///< The options as given.
  /// +infinity when a vertex is on or outside a plane.
  double energy(const Points& x) const;
  /// Gradient with respect to the positions (3n).
  VecX gradient(const Points& x) const;
  /// Diagonal Hessian entries on the z dofs (3i + 2), into A (structure: the n z-dofs).
  void add_hessian(const Points& x, SparseAssembler& A) const;
  /// Largest t in (0, 1] with every vertex keeping at least `separation` of its
  /// current distance to each plane along x + s·dx, s <= t.
  double max_step(const Points& x, const Points& dx) const;
  /// Whether every vertex is strictly inside.
  bool inside(const Points& x) const;

 private:
  SlabOptions o_;
};

}  // namespace ek
