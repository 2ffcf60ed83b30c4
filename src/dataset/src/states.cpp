#include "ek/dataset/states.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ek/core/errors.hpp"
#include "ek/core/hash.hpp"
#include "ek/core/parallel.hpp"
#include "ek/geometry/hausdorff.hpp"

namespace ek {

int count_3d_states(const KnotEntry& e, const std::vector<StateCluster>& clusters, double planar_threshold) {
  if (clusters.empty()) return 0;
  const int td = e.attribute_column("threedim");
  int n = 0;
  for (const auto& c : clusters) n += e.attributes(c.representative, td) >= planar_threshold;
  return n;
}

std::set<int> clusters_seen(const KnotEntry& e, const std::vector<int>& rank, int samples) {
  std::set<int> seen;
  for (const auto& run : e.runs)
    if (run.equilibrium >= 0 && run.sample < samples) {
      require(static_cast<size_t>(run.equilibrium) < rank.size(), "clusters_seen: rank has too few entries");
      seen.insert(rank[static_cast<size_t>(run.equilibrium)]);
    }
  return seen;
}

KnotEntry shuffled_runs(const KnotEntry& e, std::uint64_t& state) {
  KnotEntry out = e;
  for (size_t i = out.runs.size(); i > 1; --i) {
    const size_t j = static_cast<size_t>(splitmix64_uniform(state) * static_cast<double>(i));
    std::swap(out.runs[i - 1], out.runs[std::min(j, i - 1)]);
  }
  for (size_t k = 0; k < out.runs.size(); ++k) out.runs[k].sample = static_cast<int>(k);
  return out;
}

PrefixUnseen prefix_unseen(const KnotEntry& e, int samples, double cut, double energy_factor) {
  std::vector<int> members;  // equilibrium of each stable run in the prefix
  for (const RunRecord& r : e.runs)
    if (r.sample < samples && r.equilibrium >= 0) {
      require(r.equilibrium < static_cast<int>(e.equilibria.size()) &&
                  r.equilibrium < static_cast<int>(e.similarity.rows()),
              "prefix_unseen: a run names an equilibrium the entry does not have");
      members.push_back(r.equilibrium);
    }
  PrefixUnseen out;
  if (members.empty()) return out;
  const int ec = e.attribute_column("energy");
  const auto m = static_cast<Eigen::Index>(members.size());
  Eigen::MatrixXd sim(m, m);
  std::vector<double> energies;
  for (Eigen::Index i = 0; i < m; ++i) {
    energies.push_back(e.attributes(members[static_cast<size_t>(i)], ec));
    for (Eigen::Index j = 0; j < m; ++j)
      sim(i, j) = e.similarity(members[static_cast<size_t>(i)], members[static_cast<size_t>(j)]);
  }
  const StateCounts s = state_counts(sim, energies, cut);
  const double lowest = *std::min_element(energies.begin(), energies.end());
  std::vector<int> low;
  for (size_t c = 0; c < s.counts.size(); ++c)
    if (s.lowest[c] <= energy_factor * lowest) low.push_back(s.counts[c]);
  out.all = estimate_unseen(s.counts);
  out.low_energy = estimate_unseen(low);
  return out;
}

LowEnergyCoverage low_energy_coverage(const KnotEntry& e, const std::vector<StateCluster>& clusters,
                                      const std::vector<int>& rank, const std::set<int>& seen,
                                      double energy_factor) {
  LowEnergyCoverage out;
  if (clusters.empty()) return out;
  const double limit = energy_factor * clusters.front().energy_min;
  for (size_t c = 0; c < clusters.size(); ++c) {
    if (clusters[c].energy_min > limit) continue;
    ++out.clusters;
    if (seen.count(static_cast<int>(c))) {
      ++out.found;
      continue;
    }
    LowEnergyCoverage::Missed m{static_cast<int>(c), 0};
    for (const auto& run : e.runs)
      if (run.equilibrium >= 0 && rank.at(static_cast<size_t>(run.equilibrium)) == m.rank) ++m.samples;
    out.missed.push_back(m);
    out.missed_samples += m.samples;
  }
  return out;
}

std::vector<Puzzle> find_puzzles(const KnotEntry& e, double cut, double writhe_tolerance) {
  std::vector<Puzzle> out;
  if (e.equilibria.size() < 2) return out;
  const int wc = e.attribute_column("writhe");
  std::vector<int> reps;  // lowest-energy member of each cluster, by energy
  for (const auto& c : clusters_at_cut(e, cut)) reps.push_back(c.representative);
  for (size_t x = 0; x < reps.size(); ++x)
    for (size_t y = x + 1; y < reps.size(); ++y) {
      const int i = reps[x], k = reps[y];
      const double wi = e.attributes(i, wc), wk = e.attributes(k, wc);
      if (std::fabs(wi - wk) > writhe_tolerance) continue;
      if (1.0 - e.similarity(i, k) <= cut) continue;  // the two states must differ visibly
      out.push_back({i, k, wi, wk, 0.5 * (wi + wk), e.similarity(i, k)});
    }
  return out;
}

std::vector<StatePair> pairwise_shape_distances(const KnotEntry& e, double cut, const AlignmentOptions& alignment,
                                                int jobs) {
  require(jobs >= 1, "pairwise_shape_distances: jobs must be >= 1");
  alignment.validate();
  std::vector<int> rank;
  clusters_at_cut(e, cut, &rank);
  const int m = static_cast<int>(e.equilibria.size());
  std::vector<StatePair> pairs;
  for (int a = 0; a < m; ++a)
    for (int b = a + 1; b < m; ++b)
      pairs.push_back({a, b, rank[static_cast<size_t>(a)], rank[static_cast<size_t>(b)], 1.0 - e.similarity(a, b), 0.0, 0.0});
  parallel_for(pairs.size(), jobs, [&](size_t q) {
    StatePair& p = pairs[q];
    const Points& A = e.equilibria[static_cast<size_t>(p.a)];
    const Points& B = e.equilibria[static_cast<size_t>(p.b)];
    const Alignment al = align_curves(A, B, alignment);
    p.icp_distance = al.distance;
    p.hausdorff = hausdorff_distance(A, aligned_candidate(B, al)).distance;
  });
  return pairs;
}

namespace {
bool separated_by_similarity(const StatePair& p, double cut) { return !p.same_cluster() && p.similarity_distance > cut; }
}  // namespace

HausdorffSeparation hausdorff_separation(const std::vector<StatePair>& pairs, double cut) {
  HausdorffSeparation out;
  std::vector<double> same;
  for (const auto& p : pairs) {
    if (p.same_cluster()) same.push_back(p.hausdorff);
    out.different_cluster_pairs += !p.same_cluster();
    out.distinct_pairs += separated_by_similarity(p, cut);
  }
  out.same_cluster_pairs = static_cast<int>(same.size());
  if (same.empty()) {
    out.median_same_cluster_hausdorff = std::numeric_limits<double>::quiet_NaN();
    return out;
  }
  std::sort(same.begin(), same.end());
  const size_t h = same.size() / 2;
  out.median_same_cluster_hausdorff = same.size() % 2 ? same[h] : 0.5 * (same[h - 1] + same[h]);
  for (const auto& p : pairs) {
    const bool below = p.hausdorff < out.median_same_cluster_hausdorff;
    out.below_median_pairs += !p.same_cluster() && below;
    out.separated_pairs += separated_by_similarity(p, cut) && below;
  }
  return out;
}

std::vector<StatePair> closest_distinct_pairs(const std::vector<StatePair>& pairs, double cut, int count) {
  std::vector<StatePair> distinct;
  for (const auto& p : pairs)
    if (separated_by_similarity(p, cut)) distinct.push_back(p);
  std::stable_sort(distinct.begin(), distinct.end(),
                   [](const StatePair& x, const StatePair& y) { return x.hausdorff < y.hausdorff; });
  std::vector<StatePair> out;
  std::set<std::pair<int, int>> used;
  for (const auto& p : distinct) {
    if (static_cast<int>(out.size()) >= count) break;
    const auto key = std::minmax(p.cluster_a, p.cluster_b);
    if (used.insert({key.first, key.second}).second) out.push_back(p);
  }
  return out;
}

}  // namespace ek
