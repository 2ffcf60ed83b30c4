#pragma once
// summary.json of exp_dataset (docs/results.md, "dataset").
#include <optional>
#include <string>
#include <vector>

#include "json_fields.hpp"

namespace ek::results {

/// The sampling cost of the knots of one crossing number (ek::CrossingCost).
struct DatasetCrossingRow {
  int crossing_number = 0;
  int knots = 0;                 ///< [1]
  double median_samples = 0.0;   ///< [1] runs per knot
  double mean_samples = 0.0;     ///< [1] runs per knot
  double seconds_per_run = 0.0;  ///< [s] mean wall time of one relaxation (one thread)
};
EK_JSON_FIELDS(DatasetCrossingRow, crossing_number, knots, median_samples, mean_samples, seconds_per_run)

/// The expected cost of a run of every knot up to max_crossings with this
/// run's sampling rule, from this run's measured costs (ek::estimate_run).
struct DatasetRunEstimate {
  int max_crossings = 0;
  int knots = 0;                ///< [1]
  double samples = 0.0;         ///< [1] expected relaxations
  double core_hours = 0.0;      ///< [h] summed relaxation time
  double hours_on_2_cores = 0.0;   ///< [h] core_hours / 2
  double hours_on_64_cores = 0.0;  ///< [h] core_hours / 64 (the paper's workstation)
};
EK_JSON_FIELDS(DatasetRunEstimate, max_crossings, knots, samples, core_hours, hours_on_2_cores, hours_on_64_cores)

struct DatasetSummary {
  std::string scale;                   ///< ci, default or paper
  long knots = 0;                      ///< [1] knot types in dataset.h5
  long runs = 0;                       ///< [1] relaxations
  long equilibria = 0;                 ///< [1] stored stable equilibria
  double seconds = 0.0;                ///< [s] wall time
  int jobs = 0;                        ///< [1] parallel relaxations
  double equilibria_per_second = 0.0;  ///< [1/s]
  std::string sampling;                ///< ExploreOptions::sampling_description()
  /// the relaxation method (--method: default, gauss-newton, eigen-projected, hybrid, exact, paper)
  std::string method;
  double estimated_seconds = 0.0;  ///< [s] the estimate printed before the run (wall, on `jobs`)
  int budget = 0;                  ///< [1] the most samples per knot (500 when adaptive)
  // The sampling cost: null when the data set holds no knot.
  std::optional<double> median_samples;     ///< [1] runs per knot (the paper: 90)
  std::optional<int> max_samples;           ///< [1] runs of the knot that took most
  /// [1] 1 - runs / (knots · 500): relaxations saved against 500 samples per
  /// knot (the paper: about 70%); 0 for a fixed budget of 500
  std::optional<double> saving_vs_500;
  std::optional<double> run_core_seconds;   ///< [s] summed wall time of the relaxations
  std::optional<std::vector<DatasetCrossingRow>> by_crossing_number;
  /// every knot up to 12 crossings (the paper's table) from this run's costs
  std::optional<DatasetRunEstimate> full_table_estimate;
};
EK_JSON_FIELDS(DatasetSummary, scale, knots, runs, equilibria, seconds, jobs, equilibria_per_second, sampling, method,
               estimated_seconds, budget, median_samples, max_samples, saving_vs_500, run_core_seconds,
               by_crossing_number, full_table_estimate)

}  // namespace ek::results
