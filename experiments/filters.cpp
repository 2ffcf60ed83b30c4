// exp_filters: the filters of paper Section 7.3 (Fig. 7). For each attribute
// (energy, stiffness, maximum stress, total curvature, 3D-ness, sphericity,
// diameter) the equilibria of the whole data set with the smallest and the
// largest value (ek::attribute_extremes: what `knots query --sort ATTR` and
// `--sort ATTR:desc` list first). Reads ../dataset/dataset.h5.
//   every scale: the data set of that scale.
// Writes filters.csv, curves/<attribute>_<min|max>.obj and summary.json
// (docs/results.md).
#include <filesystem>
#include <iostream>

#include "ek/dataset/dataset_search.hpp"
#include "ek/geometry/curve_io.hpp"
#include "experiment.hpp"
#include "filters_summary.hpp"
#include "scales.hpp"

using namespace ek;
using namespace ek::exp;

int main(int argc, char** argv) {
  return run_experiment(argc, argv, "exp_filters", "Extremes of the filter attributes.", [](const Args& a) {
    announce(a, "exp_filters", "smallest and largest value of 7 attributes in the data set", 5.0);
    const std::string file = a.results + "/dataset/dataset.h5";
    const DatasetReader reader(file);
    results::FiltersSummary sum;
    sum.scale = a.scale_name;
    sum.dataset = "dataset/dataset.h5";
    sum.attributes = {"energy", "stiffness", "max_stress", "total_curvature", "threedim", "sphericity", "diameter"};
    for (const auto& name : reader.knot_names()) {
      ++sum.knots;
      sum.equilibria += static_cast<long>(reader.read(name).equilibria.size());
    }
    std::filesystem::create_directories(a.out + "/curves");
    Csv csv(a.out + "/filters.csv", {"attribute", "extreme", "knot", "index", "value", "curve"});
    for (const std::string& attribute : sum.attributes) {
      const auto [lo, hi] = attribute_extremes(reader, attribute);
      for (const auto& [extreme, x] : {std::pair{std::string("min"), lo}, std::pair{std::string("max"), hi}}) {
        const std::string curve = "curves/" + attribute + "_" + extreme + ".obj";
        write_curve(a.out + "/" + curve, reader.read(x.knot).equilibria[static_cast<size_t>(x.equilibrium)]);
        csv.row({attribute, extreme, x.knot, std::to_string(x.equilibrium), Csv::num(x.value), curve});
        sum.extremes.push_back({attribute, extreme, x.knot, x.equilibrium, x.value, curve});
        std::cout << "exp_filters: " << attribute << " " << extreme << ": " << x.knot << " #" << x.equilibrium
                  << " = " << x.value << std::endl;
      }
    }
    csv.commit();
    write_summary(a, sum);
  });
}
