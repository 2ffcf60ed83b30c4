#include "ek/dataset/states.hpp"

#include <algorithm>
#include <cmath>

#include "ek/core/errors.hpp"
#include "ek/core/hash.hpp"

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

}  // namespace ek
