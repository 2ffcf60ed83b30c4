// exp_milnor: Milnor's bound (paper Section 8.2, Fig. 9). For each knot type
// of the data set, the equilibrium of smallest total curvature divided by
// 2π·bridge index. Writes milnor.csv (one row per knot) and summary.json with
// the measured quantities behind the paper's claims:
//  - every equilibrium has total curvature above 2π·bridge index (Milnor 1950);
//  - BB knots (bridge index = braid index) reach the bound (ratio within 3%)
//    with a multi-covered circle (3D-ness below the planarity threshold);
//  - the knots farthest from the bound are 2-bridge knots, decided at the
//    full sampling budget (ek/analysis/far_end.hpp): on an adaptive scale the
//    knots of full_budget/ (scripts/ledger_far_end.sh) replace their
//    adaptive entries, and the summary names the knots still to sample.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <optional>
#include <vector>

#include "ek/analysis/far_end.hpp"
#include "ek/dataset/ledger.hpp"
#include "experiment.hpp"
#include "milnor_summary.hpp"
#include "scales.hpp"

using namespace ek;
using namespace ek::exp;

namespace {

/// One knot of the data set: its smallest ratio and, for BB knots, its
/// smallest ratio among the multi-covered circles.
struct Row {
  std::string name;
  int crossings = 0, bridge = 0, braid = 0, equilibria = 0, violations = 0, planar = 0, samples = 0;
  double min_total_curvature = 0.0, ratio = 0.0, threedim = 0.0;
  std::optional<double> planar_ratio;
};

Row knot_row(const LedgerEntry& e) {
  const int tc = e.attribute_column("total_curvature"), td = e.attribute_column("threedim");
  const double bound = 2.0 * M_PI * e.bridge_index;
  Row r;
  r.name = e.name;
  r.crossings = e.crossing_number;
  r.bridge = e.bridge_index;
  r.braid = e.braid_index;
  r.equilibria = static_cast<int>(e.attributes.rows());
  r.samples = static_cast<int>(e.runs.size());
  Eigen::Index best = 0;
  r.min_total_curvature = e.attributes.col(tc).minCoeff(&best);
  r.ratio = r.min_total_curvature / bound;
  r.threedim = e.attributes(best, td);
  for (Eigen::Index i = 0; i < e.attributes.rows(); ++i) {
    const double ratio = e.attributes(i, tc) / bound;
    if (!(ratio > 1.0)) ++r.violations;
    if (e.attributes(i, td) >= kPlanarThreedim) continue;
    ++r.planar;
    if (!r.planar_ratio || ratio < *r.planar_ratio) r.planar_ratio = ratio;
  }
  return r;
}

/// The share of 2-bridge knots among the first `count` of `sorted` (0 if empty).
double two_bridge_share(const std::vector<Row>& sorted, size_t count) {
  if (sorted.empty()) return 0.0;
  int two_bridge = 0;
  for (size_t k = 0; k < count && k < sorted.size(); ++k) two_bridge += sorted[k].bridge == 2;
  return static_cast<double>(two_bridge) / static_cast<double>(count);
}

/// The far end at the full budget (far_end_certificate) into `sum`.
void certify_far_end(const std::vector<Row>& rows, results::MilnorSummary& sum) {
  if (rows.empty()) return;  // nothing to certify (budget 0)
  std::vector<KnotRatio> ratios;
  for (const Row& r : rows) ratios.push_back({r.name, r.ratio, r.bridge == 2, r.samples});
  const FarEndCertificate c = far_end_certificate(ratios, static_cast<int>(sum.far_end_size), static_cast<int>(sum.budget));
  sum.far_end_certified = c.certified;
  sum.far_end_other_max_ratio = c.other_max_ratio;
  sum.far_end_other_max_knot = c.other_max_knot;
  sum.far_end_certified_two_bridge = c.certified_two_bridge;
  sum.far_end_to_sample = c.to_sample;
}

void fill_summary(const std::vector<Row>& rows, results::MilnorSummary& sum) {
  for (const Row& r : rows) {
    sum.equilibria += r.equilibria;
    sum.milnor_violations += r.violations;
    if (r.bridge != r.braid) continue;
    sum.bb_knots.push_back({r.name, r.ratio, r.threedim, r.planar_ratio, r.planar, r.equilibria});
    sum.bb_max_ratio_deviation = std::max(sum.bb_max_ratio_deviation, std::fabs(r.ratio - 1.0));
    sum.bb_max_threedim = std::max(sum.bb_max_threedim, r.threedim);
  }
  std::vector<Row> sorted = rows;  // the top decile by ratio
  std::sort(sorted.begin(), sorted.end(), [](const Row& x, const Row& y) { return x.ratio > y.ratio; });
  const size_t decile = std::max<size_t>(1, sorted.size() / 10);
  // The far end: the top decile, or the top k when only k < a decile of the
  // knots are 2-bridge without being BB (a sample can hold fewer 2-bridge
  // knots than a decile; the (2, q) torus knots are 2-bridge and BB, so at
  // the bound).
  size_t far_candidates = 0;
  for (const Row& r : rows) far_candidates += r.bridge == 2 && r.braid != 2;
  const size_t far_end = std::max<size_t>(1, std::min(decile, far_candidates));
  sum.knots = static_cast<long>(rows.size());
  sum.planar_threshold = kPlanarThreedim;
  sum.top_decile_size = static_cast<long>(decile);
  sum.top_decile_two_bridge_share = two_bridge_share(sorted, decile);
  sum.far_end_size = static_cast<long>(far_end);
  sum.far_end_two_bridge_share = two_bridge_share(sorted, far_end);
  certify_far_end(rows, sum);
}

std::string comma_list(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ",") + n;
  return out;
}

/// The full-budget knots into `sum`: their count, and those whose ratio rose.
void note_full_budget(const ResultsKnots& knots, results::MilnorSummary& sum) {
  sum.full_budget_knots = static_cast<long>(knots.replaced.size());
  for (const LedgerEntry& own : knots.replaced) {
    const auto full = std::find_if(knots.entries.begin(), knots.entries.end(),
                                   [&](const LedgerEntry& x) { return x.name == own.name; });
    if (own.equilibria() == 0 || full->equilibria() == 0) continue;
    if (knot_row(*full).ratio > knot_row(own).ratio * (1 + 1e-9)) sum.full_budget_raised.push_back(own.name);
  }
}

}  // namespace

int main(int argc, char** argv) {
  return run_experiment(argc, argv, "exp_milnor",
                        "Milnor-bound ratios of the data set (reads ../dataset/dataset.h5, else the ledgers ../ledgers/).",
                        [](const Args& a) {
    const ResultsKnots knots = read_results_knots(a.results, kClusterCut, true);
    announce(a, "exp_milnor", "analyse " + knots.source, 5.0);
    Csv csv(a.out + "/milnor.csv", {"knot", "crossing_number", "bridge_index", "braid_index", "bb", "two_bridge",
                                    "equilibria", "min_total_curvature", "ratio", "threedim_at_min", "violations",
                                    "planar_ratio", "samples", "full_budget"});
    std::vector<Row> rows;
    for (const LedgerEntry& e : knots.entries) {
      if (e.equilibria() == 0 || e.bridge_index < 1) continue;
      const Row r = rows.emplace_back(knot_row(e));
      const bool full = std::any_of(knots.replaced.begin(), knots.replaced.end(),
                                    [&](const LedgerEntry& x) { return x.name == e.name; });
      csv.row({e.name, std::to_string(r.crossings), std::to_string(r.bridge), std::to_string(r.braid),
               Csv::flag(r.bridge == r.braid), Csv::flag(r.bridge == 2), std::to_string(r.equilibria),
               Csv::num(r.min_total_curvature), Csv::num(r.ratio), Csv::num(r.threedim), std::to_string(r.violations),
               r.planar_ratio ? Csv::num(*r.planar_ratio) : "", std::to_string(r.samples), Csv::flag(full)});
    }
    csv.commit();
    results::MilnorSummary sum;
    sum.scale = a.scale_name;
    sum.budget = knots.budget;
    note_full_budget(knots, sum);
    fill_summary(rows, sum);
    write_summary(a, sum);
    std::cout << "exp_milnor: " << rows.size() << " knots, " << sum.milnor_violations << " violations, BB max |ratio-1| "
              << sum.bb_max_ratio_deviation << ", top-decile 2-bridge share " << sum.top_decile_two_bridge_share
              << "; far end " << (sum.far_end_certified ? "certified" : "not certified") << " at " << sum.budget
              << " samples" << (sum.far_end_to_sample.empty() ? "" : ", to sample: " + comma_list(sum.far_end_to_sample))
              << std::endl;
  });
}
