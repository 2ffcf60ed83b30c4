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

double median_of(std::vector<double> v) {
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(v.begin(), v.end());
  const size_t h = v.size() / 2;
  return v.size() % 2 ? v[h] : 0.5 * (v[h - 1] + v[h]);
}

/// For each equilibrium index (0 .. largest in `pairs`), its representative:
/// the smallest index joined to it by same-cluster pairs closer than `identical`.
std::vector<int> identical_representatives(const std::vector<StatePair>& pairs, double identical) {
  int m = 0;
  for (const auto& p : pairs) m = std::max(m, p.b + 1);
  std::vector<int> parent(static_cast<size_t>(m));  // a union-find forest whose roots are the smallest indices
  for (int i = 0; i < m; ++i) parent[static_cast<size_t>(i)] = i;
  const auto root = [&parent](int i) {
    while (parent[static_cast<size_t>(i)] != i) i = parent[static_cast<size_t>(i)];
    return i;
  };
  for (const auto& p : pairs)
    if (p.same_cluster() && p.hausdorff < identical) {
      const int ra = root(p.a), rb = root(p.b);
      parent[static_cast<size_t>(std::max(ra, rb))] = std::min(ra, rb);
    }
  std::vector<int> rep(static_cast<size_t>(m));
  for (int i = 0; i < m; ++i) rep[static_cast<size_t>(i)] = root(i);
  return rep;
}

}  // namespace

HausdorffSeparation hausdorff_separation(const std::vector<StatePair>& pairs, double cut, double identical) {
  require_input(identical >= 0.0, "hausdorff_separation: the identical distance must be >= 0");
  HausdorffSeparation out;
  const std::vector<int> rep = identical_representatives(pairs, identical);
  const auto unique = [&](const StatePair& p) {
    return rep[static_cast<size_t>(p.a)] == p.a && rep[static_cast<size_t>(p.b)] == p.b;
  };
  std::vector<double> same, same_unique;
  for (const auto& p : pairs) {
    if (p.same_cluster()) same.push_back(p.hausdorff);
    if (p.same_cluster() && unique(p)) same_unique.push_back(p.hausdorff);
    out.identical_pairs += p.same_cluster() && p.hausdorff < identical;
    out.different_cluster_pairs += !p.same_cluster();
    out.unique_different_cluster_pairs += !p.same_cluster() && unique(p);
    out.distinct_pairs += separated_by_similarity(p, cut);
  }
  for (size_t i = 0; i < rep.size(); ++i) out.unique_equilibria += rep[i] == static_cast<int>(i);
  out.same_cluster_pairs = static_cast<int>(same.size());
  out.unique_same_cluster_pairs = static_cast<int>(same_unique.size());
  out.median_same_cluster_hausdorff = median_of(std::move(same));
  out.median_unique_same_cluster_hausdorff = median_of(std::move(same_unique));
  for (const auto& p : pairs) {  // a comparison with NaN is false: nothing is below a missing median
    const bool below = p.hausdorff < out.median_same_cluster_hausdorff;
    out.below_median_pairs += !p.same_cluster() && below;
    out.separated_pairs += separated_by_similarity(p, cut) && below;
    const bool below_unique = unique(p) && p.hausdorff < out.median_unique_same_cluster_hausdorff;
    out.below_unique_median_pairs += !p.same_cluster() && below_unique;
    out.separated_below_unique_median += separated_by_similarity(p, cut) && below_unique;
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
