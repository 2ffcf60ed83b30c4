#pragma once
// summary.json of exp_compare_methods (docs/results.md, "compare_methods").
#include <string>
#include <vector>

#include "json_fields.hpp"

namespace ek::results {

/// One knot of one pair of data sets (compare_datasets, ek/dataset/compare.hpp).
struct KnotMethodComparison {
  std::string knot;
  int equilibria_a = 0, equilibria_b = 0;  ///< [1] stored equilibria (method a, method b)
  int clusters_a = 0, clusters_b = 0;      ///< [1] at the cut
  int missing_a_in_b = 0;  ///< [1] clusters of a with >= min_share of the equilibria and no counterpart in b
  int missing_b_in_a = 0;  ///< [1] the same the other way
  double worst_counterpart = 1.0;  ///< [1] lowest best-similarity of a cluster that needs a counterpart
  double lowest_a = 0.0, lowest_b = 0.0;  ///< [energy]
  double energy_difference = 0.0;         ///< [1] relative
  bool ok = false;                        ///< counterparts both ways and energies within tolerance
};
EK_JSON_FIELDS(KnotMethodComparison, knot, equilibria_a, equilibria_b, clusters_a, clusters_b, missing_a_in_b,
               missing_b_in_a, worst_counterpart, lowest_a, lowest_b, energy_difference, ok)

/// One experiment's data set compared between the two methods.
struct DatasetMethodComparison {
  std::string experiment;  ///< dataset or multistability
  std::vector<KnotMethodComparison> knots;
  double planar_share_a = 0.0, planar_share_b = 0.0;  ///< [1]
  bool planar_ok = false;
  bool ok = false;  ///< every knot ok, the planar shares within tolerance, the same knots
};
EK_JSON_FIELDS(DatasetMethodComparison, experiment, knots, planar_share_a, planar_share_b, planar_ok, ok)

struct CompareMethodsSummary {
  std::string scale;
  std::string method_a, method_b;  ///< the new default and the method before it
  double cut = 0.0, min_share = 0.0, counterpart = 0.0, energy_tolerance = 0.0, planar_tolerance = 0.0;  ///< [1]
  std::vector<DatasetMethodComparison> datasets;
  bool ok = false;  ///< every data set ok
};
EK_JSON_FIELDS(CompareMethodsSummary, scale, method_a, method_b, cut, min_share, counterpart, energy_tolerance,
               planar_tolerance, datasets, ok)

}  // namespace ek::results
