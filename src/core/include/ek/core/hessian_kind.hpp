#pragma once
/// \file
/// Which Hessian an energy term assembles.
#include <string>

namespace ek {

/// Which Hessian an energy term assembles: the exact one or a positive
/// semidefinite approximation of it.
enum class HessianKind {
  /// The exact second derivative (the stability test at convergence, eigen-analysis, saddles).
  Exact,
  /// A positive semidefinite modification of the strongly indefinite parts
  /// (per-element projections: compressed edges' stretching, each contact
  /// pair's barrier), for better Newton directions far from equilibrium.
  Projected,
};
/// "exact" or "projected".
inline std::string to_string(HessianKind kind) { return kind == HessianKind::Exact ? "exact" : "projected"; }

}  // namespace ek
