#pragma once
/// \file
/// Material of the elastic wire: a homogeneous isotropic rod with a circular
/// cross-section (paper Section 6; data set defaults of Section 7.4).
namespace ek {

/// Homogeneous isotropic material with a circular cross-section of radius r.
/// The defaults are the paper's data set: unit rest edges, n = 400, so the
/// wire's length/diameter ratio is 400 / 0.4 = 1000; E = 2000, ν = 0.3.
/// Units are consistent but arbitrary ([length] of the curve file, [pressure]
/// = [energy]/[length]³).
struct RodMaterial {
  double young = 2000.0;   ///< [pressure] Young's modulus E
  double poisson = 0.3;    ///< [1] Poisson ratio ν, in (-1, 0.5]
  double radius = 0.2;     ///< [length] wire radius r (circular cross-section)

  /// Shear modulus G = E / (2 (1 + ν)) [pressure].
  double shear_modulus() const;
  /// Bending stiffness EI = E π r⁴ / 4 [energy·length].
  double bending_stiffness() const;
  /// Twisting stiffness GJ = G π r⁴ / 2 [energy·length] (J = π r⁴/2, polar moment).
  double twisting_stiffness() const;
  /// Stretching stiffness EA = E π r² [energy/length].
  double stretching_stiffness() const;
  /// Throws ek::InputError for a non-finite or non-positive E or r, or ν
  /// outside (-1, 0.5].
  void validate() const;
};

}  // namespace ek
