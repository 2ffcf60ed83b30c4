#include "ek/dataset/compare.hpp"

#include <algorithm>
#include <cmath>

#include "ek/analysis/similarity.hpp"
#include "ek/core/errors.hpp"
#include "ek/dataset/pipeline.hpp"
#include "ek/knots/table.hpp"

namespace ek {
namespace {

SimilarityOptions similarity_options(const std::string& knot) {
  SimilarityOptions o;
  o.reversal = true;
  const KnotRecord* record = KnotTable::global().find(knot);
  o.mirror = record && record->symmetry_type.find("amphicheiral") != std::string::npos;
  return o;
}

/// Each cluster of `from` with the best similarity of its representative to
/// an equilibrium of `to`.
std::vector<ClusterCounterpart> counterparts(const KnotEntry& from, const KnotEntry& to, const CompareOptions& o) {
  std::vector<ClusterCounterpart> out;
  const std::vector<StateCluster> clusters = clusters_at_cut(from, o.cut);
  const SimilarityOptions so = similarity_options(from.name);
  const int energy = from.attribute_column("energy");
  for (size_t c = 0; c < clusters.size(); ++c) {
    ClusterCounterpart cc;
    cc.cluster = static_cast<int>(c);
    cc.size = static_cast<int>(clusters[c].members.size());
    cc.share = static_cast<double>(cc.size) / static_cast<double>(from.equilibria.size());
    cc.energy = from.attributes(clusters[c].representative, energy);
    for (const Points& q : to.equilibria)
      cc.similarity = std::max(cc.similarity, similarity(from.equilibria[static_cast<size_t>(clusters[c].representative)], q, so));
    cc.needs_counterpart = cc.share >= o.min_share;
    cc.found = cc.similarity >= o.counterpart;
    out.push_back(cc);
  }
  return out;
}

bool all_found(const std::vector<ClusterCounterpart>& v) {
  return std::all_of(v.begin(), v.end(), [](const ClusterCounterpart& c) { return !c.needs_counterpart || c.found; });
}

double lowest_energy(const KnotEntry& e) {
  return e.attributes.rows() > 0 ? e.attributes.col(e.attribute_column("energy")).minCoeff() : 0.0;
}

KnotComparison compare_knot(const KnotEntry& a, const KnotEntry& b, const CompareOptions& o) {
  KnotComparison k;
  k.knot = a.name;
  k.equilibria_a = static_cast<int>(a.equilibria.size());
  k.equilibria_b = static_cast<int>(b.equilibria.size());
  if (k.equilibria_a == 0 || k.equilibria_b == 0) return k;  // nothing to compare: both flags stay false
  k.a_in_b = counterparts(a, b, o);
  k.b_in_a = counterparts(b, a, o);
  k.clusters_a = static_cast<int>(k.a_in_b.size());
  k.clusters_b = static_cast<int>(k.b_in_a.size());
  k.counterparts_ok = all_found(k.a_in_b) && all_found(k.b_in_a);
  k.lowest_a = lowest_energy(a);
  k.lowest_b = lowest_energy(b);
  k.energy_difference = std::fabs(k.lowest_a - k.lowest_b) / std::min(k.lowest_a, k.lowest_b);
  k.energy_ok = k.energy_difference <= o.energy_tolerance;
  return k;
}

/// Planar equilibria and all equilibria of an entry.
std::pair<int, int> planar_count(const KnotEntry& e, double threshold) {
  const int col = e.attribute_column("threedim");
  int planar = 0;
  for (Eigen::Index r = 0; r < e.attributes.rows(); ++r) planar += e.attributes(r, col) < threshold ? 1 : 0;
  return {planar, static_cast<int>(e.attributes.rows())};
}

}  // namespace

void CompareOptions::validate() const {
  require_input(cut > 0.0 && cut < 1.0, "compare: the cut must be in (0, 1)");
  require_input(min_share >= 0.0 && min_share <= 1.0, "compare: min_share must be in [0, 1]");
  require_input(counterpart > 0.0 && counterpart <= 1.0, "compare: the counterpart similarity must be in (0, 1]");
  require_input(energy_tolerance >= 0.0 && planar_tolerance >= 0.0, "compare: tolerances must be >= 0");
}

bool DatasetComparison::ok() const {
  if (!only_a.empty() || !only_b.empty() || knots.empty() || !planar_ok) return false;
  return std::all_of(knots.begin(), knots.end(),
                     [](const KnotComparison& k) { return k.counterparts_ok && k.energy_ok; });
}

DatasetComparison compare_datasets(const DatasetReader& a, const DatasetReader& b, const CompareOptions& o) {
  o.validate();
  DatasetComparison d;
  int planar_a = 0, all_a = 0, planar_b = 0, all_b = 0;
  for (const std::string& name : a.knot_names()) {
    if (!b.has_knot(name)) {
      d.only_a.push_back(name);
      continue;
    }
    const KnotEntry ea = a.read(name), eb = b.read(name);
    d.knots.push_back(compare_knot(ea, eb, o));
    const auto [pa, na] = planar_count(ea, o.planar_threshold);
    const auto [pb, nb] = planar_count(eb, o.planar_threshold);
    planar_a += pa, all_a += na, planar_b += pb, all_b += nb;
  }
  for (const std::string& name : b.knot_names())
    if (!a.has_knot(name)) d.only_b.push_back(name);
  d.planar_share_a = all_a ? static_cast<double>(planar_a) / all_a : 0.0;
  d.planar_share_b = all_b ? static_cast<double>(planar_b) / all_b : 0.0;
  d.planar_ok = all_a > 0 && all_b > 0 && std::fabs(d.planar_share_a - d.planar_share_b) <= o.planar_tolerance;
  return d;
}

}  // namespace ek
