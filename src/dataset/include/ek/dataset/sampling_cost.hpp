#pragma once
/// \file
/// What sampling a data set cost, and what sampling more knots the same way
/// would cost: the samples per knot of the adaptive rule (paper Section 7.4:
/// 50 samples, then batches of 10 while new low-energy states appear, at
/// most 500) and the measured seconds per relaxation, per crossing number.
/// Used by exp_dataset to report the run and to extrapolate it to the
/// paper's full table (2,977 knots up to 12 crossings).
#include <string>
#include <vector>

#include "ek/dataset/dataset_file.hpp"

namespace ek {

/// One knot of a data set.
struct KnotCost {
  std::string name;          ///< the knot's name
  int crossing_number = 0;   ///< [1] of the table
  int samples = 0;           ///< [1] relaxation runs stored (every sample, also failures)
  double run_seconds = 0.0;  ///< [s] sum of the runs' wall times (one thread each)
};

/// The cost of one knot of a data set: its runs and their summed seconds.
KnotCost knot_cost(const KnotEntry& entry);

/// The knots of one crossing number.
struct CrossingCost {
  int crossing_number = 0;        ///< [1] the crossing number of these knots
  int knots = 0;                  ///< [1]
  double median_samples = 0.0;    ///< [1] per knot
  double mean_samples = 0.0;      ///< [1] per knot
  double seconds_per_run = 0.0;   ///< [s] mean over the runs of these knots
};

/// A data set's sampling cost against a fixed budget per knot.
struct SamplingCost {
  int knots = 0;                  ///< [1]
  long samples = 0;               ///< [1] runs over all knots
  double median_samples = 0.0;    ///< [1] per knot (mean of the two middle values for an even count)
  int max_samples = 0;            ///< [1] per knot
  int knots_at_budget = 0;        ///< [1] knots whose samples reached the budget (the adaptive rule did not stop them)
  int budget = 0;                 ///< [1] samples per knot of the fixed rule it is compared to
  /// [1] 1 - samples / (knots · budget): the share of the fixed budget's
  /// relaxations the adaptive rule saved (the paper: about 70% at 500).
  double saving_vs_budget = 0.0;
  double run_seconds = 0.0;       ///< [s] summed over all runs (core-seconds)
  std::vector<CrossingCost> by_crossing_number;  ///< increasing crossing number
};

/// Summarises `knots` against `budget` samples per knot. Throws
/// std::invalid_argument for an empty list or budget < 1.
SamplingCost sampling_cost(const std::vector<KnotCost>& knots, int budget);

/// The expected cost of sampling more knots with the same rule on the same
/// machine.
struct RunEstimate {
  int knots = 0;              ///< [1]
  double samples = 0.0;       ///< [1] expected runs
  double core_seconds = 0.0;  ///< [s] expected summed run time; wall time on N cores ≈ core_seconds / N
};

/// Expected cost of knots with the given crossing numbers (one entry per
/// knot). A crossing number measured in `cost` uses its mean samples per
/// knot and seconds per run; a larger one extrapolates both by the
/// least-squares line in the crossing number through the measured crossing
/// numbers (weighted by their knot counts, floored at the largest measured
/// value: more crossings never cost less). Throws std::invalid_argument when
/// `cost` has fewer than two crossing numbers to fit a line through and an
/// unmeasured crossing number is asked for.
RunEstimate estimate_run(const SamplingCost& cost, const std::vector<int>& crossing_numbers);

/// The median of `values` (the mean of the two middle ones for an even count); 0 for none.
double median_of(std::vector<double> values);

}  // namespace ek
