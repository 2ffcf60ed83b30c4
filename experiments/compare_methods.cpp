// exp_compare_methods: what the data sets of the default relaxation method
// and of the method before it ("hybrid": Newton at n from the lattice
// sample) say about the same knots, from the same samples (the equilibria a
// start reaches may differ; what a user learns must not):
//  - every cluster holding at least 3% of a knot's equilibria in one data set
//    has a counterpart (similarity >= 0.95) in the other;
//  - the lowest energy per knot agrees within 1e-4 relative;
//  - the planarity share agrees within 0.05.
// `make compare-methods` runs the dataset, milnor, planarity, multistability
// and puzzles experiments with each method into
// results/<scale>/compare_methods/<method>/, runs their paper checks on both,
// then this program with --out results/<scale>/compare_methods/comparison: it
// reads ../default and ../hybrid. Exit status 1 when they disagree.
// Writes comparison.csv (one row per data set and knot) and summary.json.
#include <algorithm>
#include <cstdio>
#include <iostream>

#include "compare_methods_summary.hpp"
#include "ek/dataset/compare.hpp"
#include "experiment.hpp"
#include "scales.hpp"

using namespace ek;
using namespace ek::exp;

namespace {

results::KnotMethodComparison knot_row(const KnotComparison& k, const CompareOptions& o) {
  results::KnotMethodComparison r;
  r.knot = k.knot;
  r.equilibria_a = k.equilibria_a;
  r.equilibria_b = k.equilibria_b;
  r.clusters_a = k.clusters_a;
  r.clusters_b = k.clusters_b;
  auto missing = [&](const std::vector<ClusterCounterpart>& v) {
    int m = 0;
    for (const ClusterCounterpart& c : v) {
      if (c.needs_counterpart) r.worst_counterpart = std::min(r.worst_counterpart, c.similarity);
      m += c.needs_counterpart && !c.found ? 1 : 0;
    }
    return m;
  };
  r.missing_a_in_b = missing(k.a_in_b);
  r.missing_b_in_a = missing(k.b_in_a);
  r.lowest_a = k.lowest_a;
  r.lowest_b = k.lowest_b;
  r.energy_difference = k.energy_difference;
  r.ok = k.counterparts_ok && k.energy_ok;
  (void)o;
  return r;
}

results::DatasetMethodComparison compare(const std::string& root, const std::string& experiment,
                                         const std::string& file, const CompareOptions& o, Csv& csv) {
  const DatasetReader a(root + "/default/" + experiment + "/" + file), b(root + "/hybrid/" + experiment + "/" + file);
  const DatasetComparison d = compare_datasets(a, b, o);
  results::DatasetMethodComparison out;
  out.experiment = experiment;
  for (const KnotComparison& k : d.knots) {
    out.knots.push_back(knot_row(k, o));
    const auto& r = out.knots.back();
    csv.row({experiment, r.knot, std::to_string(r.equilibria_a), std::to_string(r.equilibria_b),
             std::to_string(r.clusters_a), std::to_string(r.clusters_b), std::to_string(r.missing_a_in_b),
             std::to_string(r.missing_b_in_a), Csv::num(r.worst_counterpart), Csv::num(r.lowest_a),
             Csv::num(r.lowest_b), Csv::num(r.energy_difference), Csv::flag(r.ok)});
  }
  out.planar_share_a = d.planar_share_a;
  out.planar_share_b = d.planar_share_b;
  out.planar_ok = d.planar_ok;
  out.ok = d.ok();
  return out;
}

void print(const results::DatasetMethodComparison& d) {
  std::printf("%s: planar share %.3f (default) vs %.3f (hybrid)%s\n", d.experiment.c_str(), d.planar_share_a,
              d.planar_share_b, d.planar_ok ? "" : "  <- differs by more than the tolerance");
  std::printf("  %-10s %5s %5s %5s %5s %7s %7s %8s %12s %12s %9s\n", "knot", "eq A", "eq B", "cl A", "cl B", "miss AB",
              "miss BA", "worst", "lowest A", "lowest B", "rel diff");
  for (const auto& k : d.knots)
    std::printf("  %-10s %5d %5d %5d %5d %7d %7d %8.4f %12.8f %12.8f %9.2e%s\n", k.knot.c_str(), k.equilibria_a,
                k.equilibria_b, k.clusters_a, k.clusters_b, k.missing_a_in_b, k.missing_b_in_a, k.worst_counterpart,
                k.lowest_a, k.lowest_b, k.energy_difference, k.ok ? "" : "  <- differs");
}

}  // namespace

int main(int argc, char** argv) {
  bool ok = true;
  const int status = run_experiment(
      argc, argv, "exp_compare_methods",
      "Compares the data sets of the default and the hybrid method (make compare-methods).", [&](const Args& a) {
        const CompareOptions o;  // 0.05 cut, 3% share, 0.95 similarity, 1e-4 energy, 0.05 planar share
        Csv csv(a.out + "/comparison.csv", {"experiment", "knot", "equilibria_a", "equilibria_b", "clusters_a",
                                            "clusters_b", "missing_a_in_b", "missing_b_in_a", "worst_counterpart",
                                            "lowest_a", "lowest_b", "energy_difference", "ok"});
        results::CompareMethodsSummary sum;
        sum.scale = a.scale_name;
        sum.method_a = "default";
        sum.method_b = "hybrid";
        sum.cut = o.cut;
        sum.min_share = o.min_share;
        sum.counterpart = o.counterpart;
        sum.energy_tolerance = o.energy_tolerance;
        sum.planar_tolerance = o.planar_tolerance;
        sum.datasets.push_back(compare(a.results, "dataset", "dataset.h5", o, csv));
        sum.datasets.push_back(compare(a.results, "multistability", "multistability.h5", o, csv));
        for (const auto& d : sum.datasets) print(d);
        sum.ok = std::all_of(sum.datasets.begin(), sum.datasets.end(), [](const auto& d) { return d.ok; });
        ok = sum.ok;
        csv.commit();
        write_summary(a, sum);
        std::printf("exp_compare_methods: the two methods' data sets %s\n", sum.ok ? "agree" : "DISAGREE");
      });
  return status != 0 ? status : (ok ? 0 : 1);
}
