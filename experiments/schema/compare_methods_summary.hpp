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

/// The disagreements of one pair of data sets, counted.
struct ComparisonTally {
  std::string experiment;           ///< dataset or multistability
  int knots_differing = 0;          ///< [knots] not ok
  int clusters_missing = 0;         ///< [clusters] without counterpart, both ways
  int energies_differing = 0;       ///< [knots] lowest energies differ by more than the tolerance
  double planar_difference = 0.0;   ///< [1] |planar share a - planar share b|
};
EK_JSON_FIELDS(ComparisonTally, experiment, knots_differing, clusters_missing, energies_differing, planar_difference)

struct CompareMethodsSummary {
  std::string scale;
  std::string method_a, method_b;  ///< the new default and the method before it
  double cut = 0.0, min_share = 0.0, counterpart = 0.0, energy_tolerance = 0.0, planar_tolerance = 0.0;  ///< [1]
  std::vector<DatasetMethodComparison> datasets;
  bool ok = false;  ///< every data set ok
  /// The noise floor: the default method's data sets against the same
  /// method's from other lattice samples (run seed noise_seed instead of 1),
  /// compared by the same rules; empty when those data sets were not given.
  int noise_seed = 0;
  std::vector<DatasetMethodComparison> noise_floor;
  std::vector<ComparisonTally> tallies;        ///< of datasets
  std::vector<ComparisonTally> noise_tallies;  ///< of noise_floor
  /// Per data set, the methods disagree in no more knots, missing clusters and
  /// lowest energies than the two seeds of one method, and their planar shares
  /// differ by at most max(planar_tolerance, the seeds' difference).
  bool within_noise = false;
  bool agree = false;  ///< ok or within_noise: the exit status of exp_compare_methods
};
EK_JSON_FIELDS(CompareMethodsSummary, scale, method_a, method_b, cut, min_share, counterpart, energy_tolerance,
               planar_tolerance, datasets, ok, noise_seed, noise_floor, tallies, noise_tallies, within_noise, agree)

}  // namespace ek::results
