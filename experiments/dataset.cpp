// exp_dataset: the data set of elastic-knot equilibria that the Milnor,
// planarity and cross-knot experiments analyse (paper Section 7.4).
//   ci:      every knot with 3..7 crossings, 12 lattice samples each
//   default: every knot with 3..8 crossings, 40 samples each
//   paper:   all 2,977 knots with up to 12 crossings, adaptive sampling (50 + 10, at most 500)
//   paper10: all 249 knots with up to 10 crossings, adaptive sampling as the paper
//   sample12: a stratified sample of the knots with 11 and 12 crossings (10% of
//            every stratum of crossing number, alternating, bridge index, and
//            every BB knot: ek::stratified_sample), adaptive sampling as the paper
// n = 400 unit edges, r = 0.2, E = 2000 (length/diameter 1000), seed 1.
// Writes dataset.h5 (docs/dataset-format.md) and summary.json (docs/results.md).
#include <iostream>

#include "dataset_summary.hpp"
#include "ek/dataset/run.hpp"
#include "ek/dataset/sampling_cost.hpp"
#include "ek/knots/selection.hpp"
#include "experiment.hpp"
#include "scales.hpp"

using namespace ek;
using namespace ek::exp;

namespace {

/// The adaptive rule's cost per crossing number: 3 to 10 in the paper10 run
/// (2026-12-02, commits ba085f0 and 61493b4; docs/reproducing.md), 11 and
/// 12 in the first two of 20 shards of the sample12 run (40 knots,
/// 2026-12-03, commit 49f243a), weighted by the table's shares of BB and
/// other knots (the sample holds every BB knot; they stop after 63–70
/// samples, the others after 234 (11) and 333 (12)): mean samples per knot
/// and seconds per relaxation (one thread; the paper10 runs up to 10_63
/// shared the 2 cores with builds and tests, which inflates their
/// seconds). The estimate printed before an adaptive run extrapolates it
/// with estimate_run(); the paper's median of 90 samples per knot had
/// underestimated the paper10 run 3.6-fold (the rule's cost is its mean).
SamplingCost reference_adaptive_cost() {
  struct Row {
    int crossings, knots;
    double mean_samples, seconds_per_run;
  };
  constexpr Row rows[] = {{3, 1, 60.0, 0.347},   {4, 1, 90.0, 0.151},   {5, 2, 75.0, 0.329},
                          {6, 3, 66.67, 0.523},  {7, 7, 75.71, 0.506},  {8, 21, 96.67, 0.726},
                          {9, 49, 158.16, 0.681}, {10, 165, 176.85, 0.505}, {11, 8, 229.2, 0.279},
                          {12, 32, 318.0, 0.316}};
  SamplingCost c;
  for (const Row& r : rows) {
    c.knots += r.knots;
    c.by_crossing_number.push_back({r.crossings, r.knots, r.mean_samples, r.mean_samples, r.seconds_per_run});
  }
  return c;
}

/// The paper's full table: every knot up to 12 crossings.
constexpr int kPaperMaxCrossings = 12;

std::vector<int> crossing_numbers(int max_crossings) {
  std::vector<int> c;
  for (const KnotRecord* k : KnotTable::global().up_to_crossings(max_crossings)) c.push_back(k->crossing_number);
  return c;
}

results::DatasetRunEstimate full_table(const SamplingCost& cost) {
  const RunEstimate e = estimate_run(cost, crossing_numbers(kPaperMaxCrossings));
  results::DatasetRunEstimate r;
  r.max_crossings = kPaperMaxCrossings;
  r.knots = e.knots;
  r.samples = e.samples;
  r.core_hours = e.core_seconds / 3600.0;
  r.hours_on_2_cores = r.core_hours / 2.0;
  r.hours_on_64_cores = r.core_hours / 64.0;
  return r;
}

/// [s] expected summed relaxation time of knots with these crossing numbers:
/// the reference run's cost for adaptive sampling, else the fixed samples at
/// kSecondsPerRelaxation each.
double estimated_core_seconds(const ExploreOptions& o, const std::vector<int>& crossings) {
  if (o.adaptive) return estimate_run(reference_adaptive_cost(), crossings).core_seconds;
  return static_cast<double>(crossings.size()) * o.samples * kSecondsPerRelaxation;
}

/// The sampling cost of the written data set, against 500 samples per knot.
void add_sampling_cost(const std::string& path, results::DatasetSummary& sum) {
  DatasetReader r(path);
  std::vector<KnotCost> knots;
  for (const auto& name : r.knot_names()) knots.push_back(knot_cost(r.read(name)));
  if (knots.empty()) return;
  const SamplingCost c = sampling_cost(knots, 500);
  sum.median_samples = c.median_samples;
  sum.max_samples = c.max_samples;
  sum.saving_vs_500 = c.saving_vs_budget;
  sum.run_core_seconds = c.run_seconds;
  std::vector<results::DatasetCrossingRow> rows;
  for (const CrossingCost& x : c.by_crossing_number)
    rows.push_back({x.crossing_number, x.knots, x.median_samples, x.mean_samples, x.seconds_per_run});
  sum.by_crossing_number = rows;
  if (c.by_crossing_number.size() >= 2) sum.full_table_estimate = full_table(c);
}

}  // namespace

int main(int argc, char** argv) {
  return run_experiment(argc, argv, "exp_dataset", "Builds the data set of equilibria for the scale.", [](const Args& a) {
    ExploreOptions o = base_options(a);
    const bool paper_sampling = a.scale == Scale::Paper || a.scale == Scale::Paper10 || a.scale == Scale::Sample12;
    const int max_crossings = a.scale == Scale::Paper10    ? 10
                              : a.scale == Scale::Sample12 ? kPaperMaxCrossings
                                                           : by_scale(a, 7, 8, kPaperMaxCrossings);
    o.samples = paper_sampling ? 500 : by_scale(a, 12, 40, 500);
    o.adaptive = paper_sampling;
    const auto knots = a.scale == Scale::Sample12 ? stratified_sample(KnotTable::global(), {})
                                                  : KnotTable::global().up_to_crossings(max_crossings);
    std::vector<int> crossings;
    for (const KnotRecord* k : knots) crossings.push_back(k->crossing_number);
    const double estimate = estimated_core_seconds(o, crossings) / a.jobs;
    announce(a, "exp_dataset",
             std::to_string(knots.size()) + " knots with up to " + std::to_string(max_crossings) + " crossings, " +
                 o.sampling_description() + " samples",
             estimate);
    if (max_crossings < kPaperMaxCrossings || a.scale == Scale::Sample12)
      std::cout << "exp_dataset: estimate before the run for every knot up to 12 crossings with this sampling: "
                << estimated_core_seconds(o, crossing_numbers(kPaperMaxCrossings)) / 3600.0 << " core-hours"
                << std::endl;
    DatasetRunOptions ro;
    ro.explore = o;
    ro.knots = knots;
    ro.output = a.out + "/dataset.h5";
    const DatasetRunSummary s = run_dataset(ro);
    results::DatasetSummary sum;
    sum.scale = a.scale_name;
    sum.knots = s.knots;
    sum.runs = s.runs;
    sum.equilibria = s.equilibria;
    sum.seconds = s.seconds;
    sum.jobs = a.jobs;
    sum.equilibria_per_second = s.seconds > 0 ? s.equilibria / s.seconds : 0.0;
    sum.sampling = o.sampling_description();
    sum.method = a.method;
    sum.estimated_seconds = estimate;
    sum.budget = o.samples;
    add_sampling_cost(ro.output, sum);
    write_summary(a, sum);
    std::cout << "exp_dataset: " << s.knots << " knots, " << s.runs << " runs, " << s.equilibria
              << " equilibria in " << s.seconds << " s (estimated " << estimate << " s)";
    if (sum.full_table_estimate)
      std::cout << "; every knot up to 12 crossings: " << sum.full_table_estimate->core_hours << " core-hours, "
                << sum.full_table_estimate->hours_on_2_cores << " h on 2 cores, "
                << sum.full_table_estimate->hours_on_64_cores << " h on 64";
    std::cout << std::endl;
  });
}
