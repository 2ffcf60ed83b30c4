#pragma once
/// \file
/// Knots built from a PD code the project constructs (e.g.\ ek::pretzel_pd),
/// drawn, relaxed and compared with a pattern state (paper Section 8.4,
/// Fig.\ 15: "we can easily adapt the number of these crossings separately at
/// each of the three touching regions [...] and then run our simulation to
/// validate that these newly constructed knots indeed settle into a
/// geometrically similar equilibrium").
///
/// relax_construction(pd, pattern):
///  1. the code's Alexander polynomial, and the table knots with the same
///     polynomial (none: the knot is not in the table, or shares it with no
///     table knot);
///  2. the planar drawing of the code (ek::embed_pd, `drawing`), relaxed
///     (ek::relax, `relax`): status, energy, whether the equilibrium's own
///     polynomial is the code's;
///  3. the equilibrium's geometric attributes, its k-circle fit
///     (ek::fit_circles, `circles`), its similarity to the pattern
///     (curvature-torsion similarity with reversal) and its ICP alignment
///     distance to the pattern (no scaling: pattern and result have the
///     same length when drawn with the same n and edge length).
#include <string>
#include <vector>

#include "ek/analysis/attributes.hpp"
#include "ek/analysis/circles.hpp"
#include "ek/embedding/embedding.hpp"
#include "ek/knots/alexander.hpp"
#include "ek/knots/codes.hpp"
#include "ek/solver/relax.hpp"

namespace ek {

/// Options of relax_construction().
struct ConstructionOptions {
  EmbeddingOptions drawing;   ///< the planar drawing of the code (n = 400 unit edges by default)
  RelaxOptions relax;         ///< the relaxation (the data set's model by default)
  CircleFitOptions circles;   ///< the circle fit of the equilibrium (three circles by default)
};

/// One constructed knot, relaxed and measured.
struct ConstructedKnot {
  AlexanderPolynomial alexander;         ///< of the code
  std::vector<std::string> table_knots;  ///< table knots (KnotTable::global()) with the same polynomial
  RelaxResult relaxed;                   ///< the equilibrium (relaxed.positions: n by 3)
  bool alexander_preserved = false;      ///< the equilibrium's polynomial is the code's
  GeometricAttributes attributes;        ///< of the equilibrium
  CircleFit circles;                     ///< of the equilibrium
  double similarity = 0.0;               ///< [1] to the pattern (with reversal)
  double alignment_distance = 0.0;       ///< [length] ICP distance to the pattern
};

/// Relaxes and measures the knot of `pd` against `pattern` (closed polygon,
/// n by 3 with the n of options.drawing). Throws InputError for an invalid
/// code, std::invalid_argument for a pattern with another number of vertices.
ConstructedKnot relax_construction(const PDCode& pd, const Points& pattern, const ConstructionOptions& options = {});

/// The table knots whose PD code has the polynomial p (table order).
std::vector<std::string> table_knots_with_polynomial(const AlexanderPolynomial& p);

}  // namespace ek
