#pragma once
// summary.json of exp_dataset (docs/results.md, "dataset").
#include <string>

#include "json_fields.hpp"

namespace ek::results {

struct DatasetSummary {
  std::string scale;                   ///< ci, default or paper
  long knots = 0;                      ///< [1] knot types in dataset.h5
  long runs = 0;                       ///< [1] relaxations
  long equilibria = 0;                 ///< [1] stored stable equilibria
  double seconds = 0.0;                ///< [s] wall time
  int jobs = 0;                        ///< [1] parallel relaxations
  double equilibria_per_second = 0.0;  ///< [1/s]
  std::string sampling;                ///< ExploreOptions::sampling_description()
  /// The relaxation method (--method: default, hybrid, exact, paper); null
  /// in summaries written before it was recorded (they relaxed by hybrid).
  std::optional<std::string> method;
};
EK_JSON_FIELDS(DatasetSummary, scale, knots, runs, equilibria, seconds, jobs, equilibria_per_second, sampling, method)

}  // namespace ek::results
