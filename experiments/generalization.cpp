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
//     pattern, three-circle fit.
// Reads ../dataset/dataset.h5.
//   every scale: the same members; the search uses the scale's data set.
// Writes members.csv, search.csv, curves/ (pattern_9_35.obj, P_<p>_<q>_<r>.obj,
// hit<rank>.obj aligned onto the pattern) and summary.json (docs/results.md).
#include <atomic>
#include <filesystem>
#include <iostream>
#include <map>
#include <thread>

#include "ek/analysis/circles.hpp"
#include "ek/analysis/similarity.hpp"
#include "ek/dataset/dataset_search.hpp"
#include "ek/embedding/embedding.hpp"
#include "ek/geometry/curve_io.hpp"
#include "ek/knots/alexander.hpp"
#include "ek/knots/pretzel.hpp"
#include "experiment.hpp"
#include "generalization_summary.hpp"
#include "scales.hpp"

using namespace ek;
using namespace ek::exp;

namespace {

results::CircleMeasure measure_circles(const Points& P, const CircleCriterion& criterion) {
  const CircleFit f = fit_circles(P);
  results::CircleMeasure m;
  m.relative_rms = f.relative_rms();
  m.min_plane_angle = f.min_plane_angle;
  m.min_share = *std::min_element(f.share.begin(), f.share.end());
  m.mean_radius = f.mean_radius;
  m.three_circles = meets(f, criterion);
  return m;
}

/// Table knots by Alexander polynomial (from their PD codes).
std::map<std::vector<std::int64_t>, std::vector<std::string>> table_polynomials() {
  std::map<std::vector<std::int64_t>, std::vector<std::string>> out;
  for (const KnotRecord& k : KnotTable::global().records())
    if (k.pd) out[alexander(*k.pd).coefficients].push_back(k.name);
  return out;
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
    const RelaxOptions relax_options = base_options(a).relax;
    EmbeddingOptions drawing;
    drawing.vertices = 400;
    // 1. the pattern
    const KnotRecord& k935 = KnotTable::global().at("9_35");
    const RelaxResult pr = relax(embed_pd(*k935.pd, drawing).points, relax_options);
    const Points& pattern = pr.positions;
    const GeometricAttributes pg = geometric_attributes(pattern);
    sum.pattern = {k935.name, "pd", pr.status(), pr.energy.total, pg.threedim, pg.total_curvature,
                   measure_circles(pattern, criterion), "curves/pattern_9_35.obj"};
    write_curve(a.out + "/" + sum.pattern.curve, pattern);
    std::cout << "exp_generalization: 9_35 " << pr.status() << ", E " << pr.energy.total << ", 3D-ness "
              << pg.threedim << ", circle fit " << sum.pattern.circles.relative_rms << std::endl;
    // 2. the data set: the closest equilibria, the three-circle states, the similarity to the pattern
    sum.dataset = "dataset/dataset.h5";
    const DatasetReader data(a.results + "/" + sum.dataset);
    SimilarityOptions so;
    so.reversal = true;
    SimilarityEngine engine(static_cast<int>(pattern.rows()), so);
    const SignatureSpectrum pattern_spectrum = engine.spectrum(pattern);
    for (const auto& name : data.knot_names()) {
      const KnotEntry e = data.read(name);
      for (const Points& P : e.equilibria) {
        ++sum.dataset_equilibria;
        const results::CircleMeasure c = measure_circles(P, criterion);
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
    DatasetSearchOptions search;
    search.exclude_knots = {k935.name};
    search.max_results = 8;
    search.jobs = a.jobs;
    Csv hits(a.out + "/search.csv", {"rank", "knot", "index", "distance", "threedim", "three_circles", "curve"});
    const DatasetSearchResult found = search_dataset(data, pattern, search);
    for (size_t q = 0; q < found.hits.size(); ++q) {
      const DatasetHit& h = found.hits[q];
      const KnotEntry e = data.read(h.knot);
      const Points& P = e.equilibria[static_cast<size_t>(h.equilibrium)];
      results::GeneralizationHit x{static_cast<int>(q) + 1, h.knot, h.equilibrium, h.distance,
                                   e.attributes(h.equilibrium, e.attribute_column("threedim")),
                                   measure_circles(P, criterion), "curves/hit" + std::to_string(q + 1) + ".obj"};
      write_curve(a.out + "/" + x.curve, aligned_candidate(P, h.alignment));
      hits.row({std::to_string(x.rank), x.knot, std::to_string(x.index), Csv::num(x.distance), Csv::num(x.threedim),
                Csv::flag(x.circles.three_circles), x.curve});
      if (std::find(sum.search_knot_types.begin(), sum.search_knot_types.end(), h.knot) == sum.search_knot_types.end())
        sum.search_knot_types.push_back(h.knot);
      sum.search.push_back(x);
    }
    hits.commit();
    // 3. the family, with the chirality of the table's 9_35 (P(3,3,3) has writhe -9 in ek::pretzel_pd's convention)
    const int sign = diagram_from_pd(*k935.pd).writhe() < 0 ? 1 : -1;
    const auto polynomials = table_polynomials();
    std::vector<results::GeneralizationMember> members(family.size());
    std::atomic<size_t> next{0};
    auto worker = [&] {
      for (size_t q = next++; q < family.size(); q = next++) {
        std::vector<int> twists = family[q];
        for (int& t : twists) t *= sign;
        const PDCode pd = pretzel_pd(twists);
        const AlexanderPolynomial poly = alexander(pd);
        const RelaxResult r = relax(embed_pd(pd, drawing).points, relax_options);
        const GeometricAttributes g = geometric_attributes(r.positions);
        results::GeneralizationMember& m = members[q];
        m.name = pretzel_name(twists);
        m.twists = twists;
        m.crossings = pd.size();
        m.alexander = poly.coefficients;
        if (const auto it = polynomials.find(poly.coefficients); it != polynomials.end()) m.table_knots = it->second;
        m.status = r.status();
        m.alexander_preserved = r.alexander_preserved && alexander(r.positions) == poly;
        m.energy = r.energy.total;
        m.threedim = g.threedim;
        m.total_curvature = g.total_curvature;
        m.similarity = compare_curves(pattern, r.positions, so).similarity;
        m.alignment_distance = align_curves(pattern, r.positions).distance;
        m.circles = measure_circles(r.positions, criterion);
        std::string file = "P";  // P(3,3,5) -> P_3_3_5
        for (const int t : twists) file += "_" + std::to_string(t);
        m.curve = "curves/" + file + ".obj";
        write_curve(a.out + "/" + m.curve, r.positions);
      }
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < std::min<int>(a.jobs, static_cast<int>(family.size())); ++t) pool.emplace_back(worker);
    worker();
    for (auto& t : pool) t.join();
    Csv csv(a.out + "/members.csv", {"twists", "crossings", "alexander", "table_knots", "status", "alexander_preserved",
                                     "energy", "threedim", "total_curvature", "similarity", "alignment_distance",
                                     "circle_relative_rms", "circle_min_plane_angle", "three_circles", "curve"});
    for (const auto& m : members) {
      std::string tk, poly;  // ';' and ' ' separated: the cells hold no commas
      for (const auto& n : m.table_knots) tk += (tk.empty() ? "" : ";") + n;
      for (const auto c : m.alexander) poly += (poly.empty() ? "" : " ") + std::to_string(c);
      std::string tw;
      for (const int t : m.twists) tw += (tw.empty() ? "" : " ") + std::to_string(t);
      csv.row({tw, std::to_string(m.crossings), poly, tk, m.status,
               Csv::flag(m.alexander_preserved), Csv::num(m.energy), Csv::num(m.threedim), Csv::num(m.total_curvature),
               Csv::num(m.similarity), Csv::num(m.alignment_distance), Csv::num(m.circles.relative_rms),
               Csv::num(m.circles.min_plane_angle), Csv::flag(m.circles.three_circles), m.curve});
      std::cout << "exp_generalization: " << m.name << " (" << m.crossings << " crossings"
                << (m.table_knots.empty() ? ", not in the table" : ", table: " + tk) << "): " << m.status << ", E "
                << m.energy << ", 3D-ness " << m.threedim << ", similarity " << m.similarity << ", circles "
                << m.circles.relative_rms << (m.circles.three_circles ? " (three circles)" : "") << std::endl;
    }
    csv.commit();
    sum.members = members;
    write_summary(a, sum);
  });
}
