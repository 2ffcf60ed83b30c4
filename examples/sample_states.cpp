// The distinct stable states of a knot type (paper Section 7, Fig. 3):
// random lattice curves of its type are relaxed, compared by their
// curvature-torsion signatures, clustered, and listed by energy, with an
// estimate of the states the samples have not found yet.
//
//   sample_states [KNOT] [SAMPLES]      (default 5_2, 12 samples)
#include <iostream>
#include <string>

#include "ek/dataset/json.hpp"
#include "ek/dataset/pipeline.hpp"
#include "ek/knots/table.hpp"

int main(int argc, char** argv) {
  const std::string name = argc > 1 ? argv[1] : "5_2";
  ek::ExploreOptions o;
  o.samples = argc > 2 ? std::stoi(argv[2]) : 12;
  o.sampling.vertices = 100;  // small curves: the example runs in seconds
  o.stiffness = false;
  o.jobs = 2;
  const double cut = 0.05;  // the experiments' cut in 1 - similarity (docs/models.md)
  const ek::KnotEntry e = ek::explore_knot(ek::KnotTable::global().at(name), o);
  const auto states = ek::clusters_at_cut(e, cut);
  std::cout << name << ": " << e.runs.size() << " samples, " << e.equilibria.size() << " stable equilibria, "
            << states.size() << " distinct states\n";
  for (size_t s = 0; s < states.size(); ++s)
    std::cout << "  state " << s << ": energy " << states[s].energy_min << ", " << states[s].members.size()
              << " samples\n";
  std::cout << "  " << ek::entry_unseen_text(e, cut) << "\n";
  return states.empty() ? 1 : 0;
}
