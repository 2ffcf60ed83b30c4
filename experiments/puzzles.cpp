// exp_puzzles: knot puzzles (paper Section 8.3, Fig. 14). The joined wire
// cannot change its link, and the data set's equilibria are twist-free
// (Lk = Wr), so a puzzle is a pair of distinct stable states (different
// clusters at kClusterCut, and their representatives themselves farther
// apart than the cut: complete linkage can keep two clusters apart whose
// lowest-energy members look alike) of one knot with the same writhe, within 0.1; its
// link is that writhe (the paper reports -3 and 1 for its two puzzles,
// rounded). Reads ../dataset/dataset.h5 and ../multistability/multistability.h5.
// Writes puzzles.csv (every pair), curves/ (the two states of the listed
// puzzles) and summary.json (docs/results.md). The pairs: ek::find_puzzles().
#include <cmath>
#include <filesystem>
#include <iostream>
#include <set>

#include "ek/dataset/pipeline.hpp"
#include "ek/dataset/states.hpp"
#include "ek/geometry/curve_io.hpp"
#include "experiment.hpp"
#include "puzzles_summary.hpp"
#include "scales.hpp"

using namespace ek;
using namespace ek::exp;

int main(int argc, char** argv) {
  return run_experiment(argc, argv, "exp_puzzles", "Puzzles: distinct stable states with equal writhe.", [](const Args& a) {
    announce(a, "exp_puzzles", "pairs of states with equal writhe in the data sets", 10.0);
    std::filesystem::create_directories(a.out + "/curves");
    Csv csv(a.out + "/puzzles.csv", {"knot", "state_a", "state_b", "energy_a", "energy_b", "writhe_a", "writhe_b",
                                     "link", "link_rounded", "similarity", "curve_a", "curve_b"});
    results::PuzzlesSummary sum;
    sum.scale = a.scale_name;
    sum.writhe_tolerance = kWritheTolerance;
    sum.cut = kClusterCut;
    std::set<std::string> done;
    for (const std::string& file : {a.results + "/multistability/multistability.h5", a.results + "/dataset/dataset.h5"}) {
      if (!std::filesystem::exists(file)) continue;
      DatasetReader reader(file);
      sum.radius = reader.metadata().radius.value();
      sum.dhat = reader.metadata().dhat.value();
      for (const auto& name : reader.knot_names()) {
        if (!done.insert(name).second) continue;
        const KnotEntry e = reader.read(name);
        const int ec = e.equilibria.empty() ? -1 : e.attribute_column("energy");
        const std::vector<Puzzle> found = find_puzzles(e, kClusterCut, kWritheTolerance);
        for (const Puzzle& z : found) {
          const int i = z.state_a, k = z.state_b;
          const std::string ca = "curves/" + name + "_" + std::to_string(i) + ".obj";
          const std::string cb = "curves/" + name + "_" + std::to_string(k) + ".obj";
          write_curve(a.out + "/" + ca, e.equilibria[static_cast<size_t>(i)]);
          write_curve(a.out + "/" + cb, e.equilibria[static_cast<size_t>(k)]);
          csv.row({name, std::to_string(i), std::to_string(k), Csv::num(e.attributes(i, ec)),
                   Csv::num(e.attributes(k, ec)), Csv::num(z.writhe_a), Csv::num(z.writhe_b), Csv::num(z.link),
                   std::to_string(static_cast<long>(std::lround(z.link))), Csv::num(z.similarity), ca, cb});
          sum.links.push_back({name, z.link});
        }
        sum.puzzles += static_cast<int>(found.size());
        sum.knots_with_puzzles += !found.empty();
      }
    }
    csv.commit();
    write_summary(a, sum);
    std::cout << "exp_puzzles: " << sum.puzzles << " puzzles in " << sum.knots_with_puzzles << " knots" << std::endl;
  });
}
