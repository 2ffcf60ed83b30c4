#pragma once
/// \file
/// The energy of a closed curve as the elastic rod with self-contact (paper
/// Section 6, eq.\ 1), as `knots energy` reports it (and the Python module's
/// energy()): the rod's parts, the contact barrier with d̂ = 2r and ω scaled
/// with E and r exactly as relax() does, the gradient norm, twist, writhe and
/// link.
///
/// Without a link: the twist-free model (Θ free, Tw = 0, Lk = Wr). With a
/// link: the full model with Θ fixed so that Tw + Wr = Lk and the material
/// frame at uniform twist density (the twisting energy's minimiser for this
/// centerline).
#include <optional>
#include <string>

#include "ek/geometry/types.hpp"
#include "ek/rod/material.hpp"
#include "ek/solver/relax.hpp"

namespace ek {

/// The model of curve_energy(): the material, and the link and rest length when
/// prescribed.
struct CurveEnergyOptions {
  RodMaterial material;              ///< E, ν, r (paper defaults)
  std::optional<double> link;        ///< [1] prescribed link Lk (full model, Θ fixed); none: twist-free
  /// [length] rest length of every edge (> 0); none: the curve's own edge
  /// lengths (no stretching).
  std::optional<double> rest_length;
  /// Throws InputError for an impossible material, link or rest length.
  void validate() const;
};

/// What curve_energy() reports: the energy's parts, the gradient norm, the
/// contacts, and twist, writhe and link.
struct CurveEnergy {
  int vertices = 0;                  ///< [1] n
  TwistModel model = TwistModel::TwistFree;  ///< twist-free, or fixed-link with a prescribed link
  /// [energy] total = stretch + bend + twist + contact (slab 0).
  EnergyParts energy;
  double gradient_norm = 0.0;        ///< [energy/length] ‖∇E‖₂ over every unknown of the model
  int contacts = 0;                  ///< [1] edge pairs within d̂
  double twist = 0.0;                ///< [1] Tw
  double writhe = 0.0;               ///< [1] Wr
  double link = 0.0;                 ///< [1] Lk = Tw + Wr
};

/// The energy of P (n by 3, a valid closed curve).
CurveEnergy curve_energy(const Points& P, const CurveEnergyOptions& options = {});

}  // namespace ek
