// exp_puzzles: knot puzzles (paper Section 8.3, Fig. 14). The joined wire
// cannot change its link, and the data set's equilibria are twist-free
// (Lk = Wr), so a puzzle is a pair of distinct stable states (different
// clusters at kClusterCut, and their representatives themselves farther
// apart than the cut: complete linkage can keep two clusters apart whose
// lowest-energy members look alike) of one knot with the same writhe, within 0.1; its
// link is that writhe (the paper reports -3 and 1 for its two puzzles,
// rounded). Reads ../dataset/dataset.h5 and ../multistability/multistability.h5.
// Writes puzzles.csv (every pair), curves/ (the two states of the listed
// puzzles) and summary.json.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>

#include "ek/dataset/pipeline.hpp"
#include "ek/geometry/curve_io.hpp"
#include "experiment.hpp"
#include "scales.hpp"

using namespace ek;
using namespace ek::exp;

constexpr double kWritheTolerance = 0.1;

int main(int argc, char** argv) {
  return run_experiment(argc, argv, "exp_puzzles", "Puzzles: distinct stable states with equal writhe.", [](const Args& a) {
    announce(a, "exp_puzzles", "pairs of states with equal writhe in the data sets", 10.0);
    std::filesystem::create_directories(a.out + "/curves");
    Csv csv(a.out + "/puzzles.csv", {"knot", "state_a", "state_b", "energy_a", "energy_b", "writhe_a", "writhe_b",
                                     "link", "link_rounded", "similarity", "curve_a", "curve_b"});
    int pairs = 0, knots_with = 0;
    nlohmann::ordered_json links = nlohmann::ordered_json::array();
    std::set<std::string> done;
    for (const std::string& file : {a.results + "/multistability/multistability.h5", a.results + "/dataset/dataset.h5"}) {
      if (!std::filesystem::exists(file)) continue;
      DatasetReader reader(file);
      for (const auto& name : reader.knot_names()) {
        if (!done.insert(name).second) continue;
        const KnotEntry e = reader.read(name);
        const int m = static_cast<int>(e.equilibria.size());
        if (m < 2) continue;
        const int ec = e.attribute_column("energy"), wc = e.attribute_column("writhe");
        std::vector<int> reps;  // lowest-energy member of each cluster, by energy
        for (const auto& c : clusters_at_cut(e, kClusterCut)) reps.push_back(c.representative);
        int found = 0;
        for (size_t x = 0; x < reps.size(); ++x)
          for (size_t y = x + 1; y < reps.size(); ++y) {
            const int i = reps[x], k = reps[y];
            const double wi = e.attributes(i, wc), wk = e.attributes(k, wc);
            if (std::fabs(wi - wk) > kWritheTolerance) continue;
            if (1.0 - e.similarity(i, k) <= kClusterCut) continue;  // the two states must differ visibly
            const double link = 0.5 * (wi + wk);
            const std::string ca = "curves/" + name + "_" + std::to_string(i) + ".obj";
            const std::string cb = "curves/" + name + "_" + std::to_string(k) + ".obj";
            write_curve(a.out + "/" + ca, e.equilibria[static_cast<size_t>(i)]);
            write_curve(a.out + "/" + cb, e.equilibria[static_cast<size_t>(k)]);
            csv.row({name, std::to_string(i), std::to_string(k), Csv::num(e.attributes(i, ec)),
                     Csv::num(e.attributes(k, ec)), Csv::num(wi), Csv::num(wk), Csv::num(link),
                     std::to_string(static_cast<long>(std::lround(link))), Csv::num(e.similarity(i, k)), ca, cb});
            links.push_back({{"knot", name}, {"link", link}});
            ++found;
          }
        pairs += found;
        knots_with += found > 0;
      }
    }
    csv.commit();
    nlohmann::ordered_json j;
    j["scale"] = a.scale_name;
    j["writhe_tolerance"] = kWritheTolerance;
    j["cut"] = kClusterCut;
    j["puzzles"] = pairs;
    j["knots_with_puzzles"] = knots_with;
    j["links"] = links;
    write_json(a.out + "/summary.json", j);
    std::cout << "exp_puzzles: " << pairs << " puzzles in " << knots_with << " knots" << std::endl;
  });
}
