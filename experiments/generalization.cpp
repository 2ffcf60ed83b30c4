// exp_generalization: constructive generalization (paper Section 8.4, Fig. 15).
// 9_35 = P(3,3,3) has a 3D state made of three circles joined through crossings
// at their three touching regions. Its route here: the planar drawing of the
// table's PD code (ek::embed_pd), relaxed (the data set's model and solver);
// the braid coil under the slab, released, ends in another state (docs).
//  1. the pattern: that state, measured by a three-circle fit (ek::fit_circles);
//  2. search: the data set's equilibria closest to it (ek::search_dataset, as
//     `knots search`), their knot types, which of them are three-circle states;
//  3. generalize: pretzel knots P(p,q,r) with p, q, r crossings in the three
//     touching regions, P(3,3,3) (= 9_35, the control), P(3,3,5), P(3,5,5),
//     P(5,5,5), P(3,3,7) (13 and 15 crossings: beyond the table), with the
//     sign of 9_35's table chirality: the PD code generated for P(p,q,r)
//     (ek::pretzel_pd), drawn (ek::embed_pd, n = 400 unit edges, the data set's
//     wire), relaxed; each equilibrium's Alexander polynomial, the table knots
//     sharing it, energy, 3D-ness, similarity and alignment distance to the
//     pattern, three-circle fit (ek::relax_construction).
// Reads ../dataset/dataset.h5.
//   every scale: the same members; the search uses the scale's data set.
// Writes members.csv, search.csv, curves/ (pattern_9_35.obj, P_<p>_<q>_<r>.obj,
// hit<rank>.obj aligned onto the pattern) and summary.json (docs/results.md).
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <type_traits>

#include "ek/analysis/similarity.hpp"
#include "ek/core/parallel.hpp"
#include "ek/dataset/construction.hpp"
#include "ek/dataset/dataset_search.hpp"
#include "ek/geometry/curve_io.hpp"
#include "ek/knots/pretzel.hpp"
#include "ek/knots/table.hpp"
#include "experiment.hpp"
#include "generalization_summary.hpp"
#include "scales.hpp"

using namespace ek;
using namespace ek::exp;

namespace {

results::CircleMeasure measure(const CircleFit& f, const CircleCriterion& criterion) {
  results::CircleMeasure m;
  m.relative_rms = f.relative_rms();
  m.min_plane_angle = f.min_plane_angle;
  m.min_share = *std::min_element(f.share.begin(), f.share.end());
  m.mean_radius = f.mean_radius;
  m.three_circles = meets(f, criterion);
  return m;
}

results::CircleMeasure measure(const Points& P, const CircleCriterion& criterion) {
  return measure(fit_circles(P), criterion);
}

/// 1. The pattern: 9_35's table PD code drawn and relaxed.
Points pattern_state(const Args& a, const ConstructionOptions& o, const CircleCriterion& criterion,
                     results::GeneralizationSummary& sum) {
  const KnotRecord& k935 = KnotTable::global().at("9_35");
  const RelaxResult pr = relax(embed_pd(*k935.pd, o.drawing).points, o.relax);
  const GeometricAttributes pg = geometric_attributes(pr.positions);
  sum.pattern = {k935.name, "pd", to_string(pr.status()), pr.energy.total, pg.threedim, pg.total_curvature,
                 measure(pr.positions, criterion), "curves/pattern_9_35.obj"};
  write_curve(a.out + "/" + sum.pattern.curve, pr.positions);
  std::cout << "exp_generalization: 9_35 " << to_string(pr.status()) << ", E " << pr.energy.total << ", 3D-ness " << pg.threedim
            << ", circle fit " << sum.pattern.circles.relative_rms << std::endl;
  return pr.positions;
}

/// 2a. Every equilibrium of the data set: three-circle states, best fit, largest similarity to the pattern.
void scan_dataset(const DatasetReader& data, const Points& pattern, const CircleCriterion& criterion,
                  results::GeneralizationSummary& sum) {
  SimilarityOptions so;
  so.reversal = true;
  SimilarityEngine engine(static_cast<int>(pattern.rows()), so);
  const SignatureSpectrum pattern_spectrum = engine.spectrum(pattern);
  for (const auto& name : data.knot_names()) {
    const KnotEntry e = data.read(name);
    for (const Points& P : e.equilibria) {
      ++sum.dataset_equilibria;
      const results::CircleMeasure c = measure(P, criterion);
      sum.dataset_three_circle_states += c.three_circles;
      if (c.min_share >= criterion.min_share && c.min_plane_angle >= criterion.min_plane_angle &&
          (!sum.dataset_min_relative_rms || c.relative_rms < *sum.dataset_min_relative_rms)) {
        sum.dataset_min_relative_rms = c.relative_rms;
        sum.dataset_min_relative_rms_knot = name;
      }
      const double s = engine.similarity(pattern_spectrum, engine.spectrum(P));
      if (s > sum.dataset_max_similarity) {
        sum.dataset_max_similarity = s;
        sum.dataset_max_similarity_knot = name;
      }
    }
  }
}

/// 2b. The data set's equilibria closest to the pattern (the search of `knots search`).
void search_dataset_for(const Args& a, const DatasetReader& data, const Points& pattern,
                        const CircleCriterion& criterion, results::GeneralizationSummary& sum) {
  DatasetSearchOptions search;
  search.exclude_knots = {"9_35"};
  search.max_results = 8;
  search.jobs = a.jobs;
  Csv hits(a.out + "/search.csv", {"rank", "knot", "index", "distance", "threedim", "three_circles", "curve"});
  const DatasetSearchResult found = search_dataset(data, pattern, search);
  for (size_t q = 0; q < found.hits.size(); ++q) {
    const DatasetHit& h = found.hits[q];
    const KnotEntry e = data.read(h.knot);
    const Points& P = e.equilibria[static_cast<size_t>(h.equilibrium)];
    results::GeneralizationHit x{static_cast<int>(q) + 1, h.knot, h.equilibrium, h.distance,
                                 e.attributes(h.equilibrium, e.attribute_column("threedim")), measure(P, criterion),
                                 "curves/hit" + std::to_string(q + 1) + ".obj"};
    write_curve(a.out + "/" + x.curve, aligned_candidate(P, h.alignment));
    hits.row({std::to_string(x.rank), x.knot, std::to_string(x.index), Csv::num(x.distance), Csv::num(x.threedim),
              Csv::flag(x.circles.three_circles), x.curve});
    if (std::find(sum.search_knot_types.begin(), sum.search_knot_types.end(), h.knot) == sum.search_knot_types.end())
      sum.search_knot_types.push_back(h.knot);
    sum.search.push_back(x);
  }
  hits.commit();
}

/// 3. One pretzel knot built, relaxed and measured (ek::relax_construction).
results::GeneralizationMember member(const Args& a, const std::vector<int>& twists, const Points& pattern,
                                     const ConstructionOptions& o, const CircleCriterion& criterion) {
  const PDCode pd = pretzel_pd(twists);
  const ConstructedKnot k = relax_construction(pd, pattern, o);
  results::GeneralizationMember m;
  m.name = pretzel_name(twists);
  m.twists = twists;
  m.crossings = pd.size();
  m.alexander = k.alexander.coefficients;
  m.table_knots = k.table_knots;
  m.status = to_string(k.relaxed.status());
  m.alexander_preserved = k.alexander_preserved;
  m.energy = k.relaxed.energy.total;
  m.threedim = k.attributes.threedim;
  m.total_curvature = k.attributes.total_curvature;
  m.similarity = k.similarity;
  m.alignment_distance = k.alignment_distance;
  m.circles = measure(k.circles, criterion);
  std::string file = "P";  // P(3,3,5) -> P_3_3_5
  for (const int t : twists) file += "_" + std::to_string(t);
  m.curve = "curves/" + file + ".obj";
  write_curve(a.out + "/" + m.curve, k.relaxed.positions);
  return m;
}

template <class T>
std::string joined(const std::vector<T>& items, const std::string& separator) {
  std::string out;
  for (const T& x : items) {
    if (!out.empty()) out += separator;
    if constexpr (std::is_arithmetic_v<T>) out += std::to_string(x);
    else out += x;
  }
  return out;
}

void write_members(const Args& a, const std::vector<results::GeneralizationMember>& members) {
  Csv csv(a.out + "/members.csv", {"twists", "crossings", "alexander", "table_knots", "status", "alexander_preserved",
                                   "energy", "threedim", "total_curvature", "similarity", "alignment_distance",
                                   "circle_relative_rms", "circle_min_plane_angle", "three_circles", "curve"});
  for (const auto& m : members) {  // ';' and ' ' separated: the cells hold no commas
    const std::string tk = joined(m.table_knots, ";");
    csv.row({joined(m.twists, " "), std::to_string(m.crossings), joined(m.alexander, " "), tk, m.status,
             Csv::flag(m.alexander_preserved), Csv::num(m.energy), Csv::num(m.threedim), Csv::num(m.total_curvature),
             Csv::num(m.similarity), Csv::num(m.alignment_distance), Csv::num(m.circles.relative_rms),
             Csv::num(m.circles.min_plane_angle), Csv::flag(m.circles.three_circles), m.curve});
    std::cout << "exp_generalization: " << m.name << " (" << m.crossings << " crossings"
              << (m.table_knots.empty() ? ", no table knot with its polynomial" : ", table: " + tk) << "): " << m.status
              << ", E " << m.energy << ", 3D-ness " << m.threedim << ", similarity " << m.similarity << ", circles "
              << m.circles.relative_rms << (m.circles.three_circles ? " (three circles)" : "") << std::endl;
  }
  csv.commit();
}

}  // namespace

int main(int argc, char** argv) {
  return run_experiment(argc, argv, "exp_generalization", "Three-circle knots beyond the table (Fig. 15).", [](const Args& a) {
    const std::vector<std::vector<int>> family = {{3, 3, 3}, {3, 3, 5}, {3, 5, 5}, {5, 5, 5}, {3, 3, 7}};
    announce(a, "exp_generalization", "9_35 and " + std::to_string(family.size()) + " pretzel knots, data-set search",
             (1.0 + family.size()) * 2.0 * kSecondsPerRelaxation / a.jobs + 60.0);
    std::filesystem::create_directories(a.out + "/curves");
    const CircleCriterion criterion;
    results::GeneralizationSummary sum;
    sum.scale = a.scale_name;
    sum.max_relative_rms = criterion.max_relative_rms;
    sum.min_share = criterion.min_share;
    sum.min_plane_angle = criterion.min_plane_angle;
    ConstructionOptions o;
    o.relax = base_options(a).relax;
    const Points pattern = pattern_state(a, o, criterion, sum);
    sum.dataset = "dataset/dataset.h5";
    const DatasetReader data(a.results + "/" + sum.dataset);
    scan_dataset(data, pattern, criterion, sum);
    search_dataset_for(a, data, pattern, criterion, sum);
    // the family, with the chirality of the table's 9_35 (P(3,3,3) has writhe -9 in ek::pretzel_pd's convention)
    const int sign = diagram_from_pd(*KnotTable::global().at("9_35").pd).writhe() < 0 ? 1 : -1;
    sum.members.resize(family.size());
    parallel_for(family.size(), a.jobs, [&](size_t q) {
      std::vector<int> twists = family[q];
      for (int& t : twists) t *= sign;
      sum.members[q] = member(a, twists, pattern, o, criterion);
    });
    write_members(a, sum.members);
    write_summary(a, sum);
  });
}
