// exp_dataset: the data set of elastic-knot equilibria that the Milnor,
// planarity and cross-knot experiments analyse (paper Section 7.4).
//   ci:      every knot with 3..7 crossings, 12 lattice samples each
//   default: every knot with 3..8 crossings, 40 samples each
//   paper:   all 2,977 knots with up to 12 crossings, adaptive sampling (50 + 10, at most 500)
// n = 400 unit edges, r = 0.2, E = 2000 (length/diameter 1000), seed 1.
// Writes dataset.h5 (docs/dataset-format.md) and summary.json (docs/results.md).
#include <iostream>

#include "dataset_summary.hpp"
#include "ek/dataset/run.hpp"
#include "experiment.hpp"
#include "scales.hpp"

using namespace ek;
using namespace ek::exp;

int main(int argc, char** argv) {
  return run_experiment(argc, argv, "exp_dataset", "Builds the data set of equilibria for the scale.", [](const Args& a) {
    ExploreOptions o = base_options(a);
    const int max_crossings = by_scale(a, 7, 8, 12);
    o.samples = by_scale(a, 12, 40, 500);
    o.adaptive = a.scale == Scale::Paper;
    const auto knots = KnotTable::global().up_to_crossings(max_crossings);
    const double runs = static_cast<double>(knots.size()) * (o.adaptive ? 90.0 : o.samples);
    announce(a, "exp_dataset",
             std::to_string(knots.size()) + " knots with up to " + std::to_string(max_crossings) + " crossings, " +
                 o.sampling_description() + " samples",
             runs * kSecondsPerRelaxation / a.jobs);
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
    write_summary(a, sum);
    std::cout << "exp_dataset: " << s.knots << " knots, " << s.runs << " runs, " << s.equilibria
              << " equilibria in " << s.seconds << " s" << std::endl;
  });
}
