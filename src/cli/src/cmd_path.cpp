// knots path TRANSITIONS NAME A B -o path.obj|path.h5 [--json]
#include <iostream>

#include "args.hpp"
#include "commands.hpp"
#include "ek/core/atomic_file.hpp"
#include "ek/core/errors.hpp"
#include "ek/transitions/graph.hpp"
#include "ek/transitions/transitions_file.hpp"
#include "output.hpp"
#include "transitions_json.hpp"

namespace ek::cli {
namespace {

/// The profile as an OBJ of images or an HDF5 path file.
void write_profile(const std::string& out, const TransitionGraph& g, const std::vector<Points>& images,
                   const std::vector<double>& energies, const std::vector<int>& saddles) {
  const bool h5 = out.size() > 3 && out.substr(out.size() - 3) == ".h5";
  if (h5) write_path_h5(out, g.knot, images, energies, saddles);
  else write_path_obj(out, images, energies);
}

}  // namespace

int cmd_path(int argc, char** argv) {
  std::string file, name, a_text, b_text, out;
  bool json = false;
  ArgParser args("path", "TRANSITIONS NAME A B -o path.obj|path.h5 [--json]");
  args.positional("TRANSITIONS", &file, "the transitions file of the knot (knots transitions DATASET NAME -o FILE)");
  args.positional("NAME", &name, "the knot (checked against the file)");
  args.positional("A", &a_text, "the first state (index in the graph; knots transitions lists them)");
  args.positional("B", &b_text, "the second state");
  args.option("-o,--output", &out, "the images of the path: .obj (one object per image) or .h5");
  args.flag("--json", &json, "print one JSON object");
  if (!args.parse(argc, argv)) return 0;
  if (out.empty()) throw InputError("-o path.obj or path.h5 is required");
  check_writable(out);
  const TransitionGraph g = read_transitions(file);
  require_input(g.knot == name, file + " holds the transitions of " + g.knot + ", not of " + name);
  const int a = parse_state(a_text, g, "A"), b = parse_state(b_text, g, "B");
  const auto edges = minimax_path(g, a, b);
  if (!edges) {
    if (json) {
      Json j;
      j["from"] = a;
      j["to"] = b;
      j["connected"] = false;
      print_json(j);
    } else {
      std::cout << "no chain of found saddles joins state " << a << " and state " << b << "\n";
    }
    return 1;
  }
  std::vector<Points> images;
  std::vector<double> energies;
  std::vector<int> saddles;
  chain_profile(g, a, *edges, images, energies, saddles);
  double highest = g.states[a].energy;
  for (const int k : *edges) highest = std::max(highest, g.edges[k].energy);
  if (!images.empty()) write_profile(out, g, images, energies, saddles);
  if (json) {
    Json j;
    j["from"] = a;
    j["to"] = b;
    j["connected"] = true;
    j["edges"] = *edges;
    j["highest_saddle"] = number(highest);
    j["barrier"] = number(highest - g.states[a].energy);
    j["barrier_scaled"] = number((highest - g.states[a].energy) / g.energy_scale);
    Json e = Json::array();
    for (const double x : energies) e.push_back(number(x));
    j["energies"] = e;
    j["saddle_images"] = saddles;
    j["output"] = out;
    print_json(j);
  } else {
    std::cout << "path " << a << " -> " << b << ": " << edges->size() << " saddles, highest " << fmt(highest)
              << ", barrier " << fmt(highest - g.states[a].energy, 6) << " (" << images.size() << " images)\n";
    for (size_t k = 0; k < energies.size(); ++k) std::cout << "  " << k << " " << fmt(energies[k]) << "\n";
    std::cout << "wrote " << out << "\n";
  }
  return 0;
}

}  // namespace ek::cli
