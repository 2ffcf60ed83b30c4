// exp_saddles: transitions between stable states (paper Section 8.5: the
// paper finds many stable states per knot but cannot yet find the transitions
// between them nor their barriers). From 4_1's distinct states (the clusters
// of ../multistability/multistability.h5 at kClusterCut, by energy; the first
// few at the ci scale) find_knot_saddles() searches along the K softest
// non-rigid modes in both directions, with the data set's model and rest edge
// length. Writes states.csv (every start), searches.csv (every search),
// profile.csv (energy along each verified saddle's path), one folder per
// distinct verified saddle (state<k>_search<j>/: start.obj, saddle.obj,
// end.obj, path.obj) and summary.json (docs/results.md, "saddles").
#include <filesystem>
#include <iostream>

#include "ek/analysis/similarity.hpp"
#include "ek/dataset/dataset_file.hpp"
#include "ek/dataset/pipeline.hpp"
#include "ek/geometry/curve_io.hpp"
#include "ek/transitions/saddles.hpp"
#include "experiment.hpp"
#include "saddles_summary.hpp"
#include "scales.hpp"

using namespace ek;
using namespace ek::exp;

namespace {

struct Tables {
  Csv states, searches, profile;
};

Tables open_tables(const Args& a) {
  return {Csv(a.out + "/states.csv", {"state", "equilibrium", "energy", "searched", "error"}),
          Csv(a.out + "/searches.csv", {"state", "search", "mode", "direction", "status", "verified", "duplicate_of",
                                        "energy", "barrier", "other_energy", "start_similarity", "other_similarity", "index",
                                        "iterations", "seconds"}),
          Csv(a.out + "/profile.csv", {"state", "search", "image", "energy", "energy_scaled", "saddle"})};
}

double curve_similarity(const Points& x, const Points& y) {
  SimilarityOptions o;
  o.reversal = true;
  return similarity(x, y, o);
}

/// The files and the profile rows of one distinct verified saddle.
results::VerifiedSaddle store_saddle(const Args& a, const SaddleStart& s, const SaddleRecord& r, int state, int search,
                                     Csv& profile) {
  results::VerifiedSaddle v{state, search, r.energy, r.energy - s.energy, r.minima[1].energy,
                            (r.energy - s.energy) / s.energy_scale, r.negative_eigenvalue,
                            r.minima[0].start_similarity, r.minima[1].start_similarity, r.seconds,
                            "state" + std::to_string(state) + "_search" + std::to_string(search)};
  const std::string dir = a.out + "/" + v.folder;
  std::filesystem::create_directories(dir);
  std::vector<double> energies;
  int at = 0;
  const std::vector<Points> path = saddle_path(r, energies, at);
  write_curve(dir + "/start.obj", path.front());
  write_curve(dir + "/saddle.obj", r.saddle);
  write_curve(dir + "/end.obj", path.back());
  write_path_obj(dir + "/path.obj", path, energies);
  for (size_t k = 0; k < path.size(); ++k)
    profile.row({std::to_string(state), std::to_string(search), std::to_string(k), Csv::num(energies[k]),
                 Csv::num(energies[k] / s.energy_scale), Csv::flag(static_cast<int>(k) == at)});
  return v;
}

/// Every search from one state: the searches table, and the verified saddles.
void search_state(const Args& a, const Points& x, const VecX& rest, const KnotSaddleOptions& o, int state,
                  Tables& t, results::SaddlesSummary& sum, double& seconds) {
  const SaddleStart s = prepare_start(x, rest, o);
  sum.energy_scale = s.energy_scale;
  const std::vector<SaddleRecord> records = find_knot_saddles(s, rest, o, curve_similarity);
  for (size_t j = 0; j < records.size(); ++j) {
    const SaddleRecord& r = records[j];
    const bool descended = !r.minima[0].images.empty();
    t.searches.row({std::to_string(state), std::to_string(j), std::to_string(r.mode), std::to_string(r.direction),
                    to_string(r.status), Csv::flag(r.verified), std::to_string(r.duplicate_of), Csv::num(r.energy),
                    descended ? Csv::num(r.energy - s.energy) : "", descended ? Csv::num(r.minima[1].energy) : "",
                    descended ? Csv::num(r.minima[0].start_similarity) : "",
                    descended ? Csv::num(r.minima[1].start_similarity) : "", std::to_string(r.index),
                    std::to_string(r.iterations), Csv::num(r.seconds, 4)});
    ++sum.searches;
    sum.verified += r.verified;
    seconds += r.seconds;
    if (r.verified && r.duplicate_of < 0)
      sum.verified_saddles.push_back(store_saddle(a, s, r, state, static_cast<int>(j), t.profile));
  }
  std::cout << "  state " << state << ": " << records.size() << " searches, " << sum.verified_saddles.size()
            << " saddles so far" << std::endl;
}

void run(const Args& a) {
  const std::string input = a.results + "/multistability/multistability.h5";
  require_input(std::filesystem::exists(input), "exp_saddles: run the multistability experiment first (" + input + ")");
  const int max_states = by_scale(a, 3, 8, 1000);
  KnotSaddleOptions o;
  o.relax = base_options(a).relax;
  o.modes = by_scale(a, 2, 4, 6);
  announce(a, "exp_saddles", "saddle searches from 4_1's states (" + std::to_string(o.modes) + " modes each)",
           by_scale(a, 120.0, 600.0, 3600.0));
  const DatasetReader reader(input);
  const KnotEntry e = reader.read("4_1");
  const std::vector<StateCluster> clusters = clusters_at_cut(e, kClusterCut);
  const DatasetMetadata& meta = reader.metadata();
  require_input(meta.young.value_or(o.relax.material.young) == o.relax.material.young &&
                    meta.radius.value_or(o.relax.material.radius) == o.relax.material.radius,
                "exp_saddles: " + input + " was made with another material");
  results::SaddlesSummary sum;
  sum.scale = a.scale_name;
  sum.knot = "4_1";
  sum.cut = kClusterCut;
  sum.modes = o.modes;
  sum.edge_length = meta.edge_length.value_or(1.0);
  Tables t = open_tables(a);
  double seconds = 0.0;
  for (int k = 0; k < std::min<int>(max_states, static_cast<int>(clusters.size())); ++k) {
    const int eq = clusters[static_cast<size_t>(k)].representative;
    const Points& x = e.equilibria[static_cast<size_t>(eq)];
    const VecX rest = VecX::Constant(x.rows(), sum.edge_length);
    std::string error;
    try {
      search_state(a, x, rest, o, k, t, sum, seconds);
    } catch (const InputError& err) {
      error = err.what();
      ++sum.states_refused;
    }
    ++sum.states;
    t.states.row({std::to_string(k), std::to_string(eq), Csv::num(clusters[static_cast<size_t>(k)].energy_min),
                  Csv::flag(error.empty()), error});
  }
  t.states.commit();
  t.searches.commit();
  t.profile.commit();
  sum.saddles = static_cast<int>(sum.verified_saddles.size());
  for (const results::VerifiedSaddle& v : sum.verified_saddles) sum.saddles_to_other_states += v.other_similarity < 1.0 - kClusterCut;
  sum.seconds_per_search = sum.searches > 0 ? seconds / sum.searches : 0.0;
  sum.seconds_per_saddle = sum.saddles > 0 ? seconds / sum.saddles : 0.0;
  sum.seconds = elapsed_seconds();
  write_summary(a, sum);
  std::cout << "exp_saddles: 4_1, " << sum.states << " states, " << sum.verified << " of " << sum.searches
            << " searches verified, " << sum.saddles << " distinct saddles (" << sum.saddles_to_other_states
            << " to another state), " << sum.seconds_per_saddle
            << " s per saddle" << std::endl;
}

}  // namespace

int main(int argc, char** argv) {
  return run_experiment(argc, argv, "exp_saddles", "Saddles: verified index-1 saddles and barriers of 4_1.", run);
}
