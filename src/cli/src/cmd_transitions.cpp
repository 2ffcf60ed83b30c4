// knots transitions DATASET NAME [--cut C] [--modes K] [--states N] [--pair-gap G] [--max-pairs P] [--stages S]
//                   [--max-iter N] [--images M] -o FILE.h5 [--overwrite] [--quiet] [--json]
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "args.hpp"
#include "commands.hpp"
#include "ek/core/atomic_file.hpp"
#include "ek/core/errors.hpp"
#include "ek/dataset/dataset_file.hpp"
#include "ek/transitions/graph.hpp"
#include "ek/transitions/run.hpp"
#include "ek/transitions/transitions_file.hpp"
#include "output.hpp"
#include "transitions_json.hpp"

namespace ek::cli {
namespace {

using Clock = std::chrono::steady_clock;

struct TransitionsCommand {
  std::string dataset, name, out;
  bool json = false, quiet = false, overwrite = false;
  TransitionRunOptions run;
};

bool parse_transitions(int argc, char** argv, TransitionsCommand& c) {
  TransitionRunOptions& r = c.run;
  ArgParser args("transitions", "DATASET NAME [--cut C] [--modes K] [--states N] [--pair-gap G] [--max-pairs P] "
                                "[--stages S] [--max-iter N] [--images M] -o FILE.h5 [--overwrite] [--quiet] [--json]");
  args.positional("DATASET", &c.dataset, "a data set (knots explore, knots dataset, an experiment's dataset.h5)");
  args.positional("NAME", &c.name, "the knot, e.g. 4_1");
  args.option("-o,--output", &c.out, "the transitions file (HDF5), written atomically (must not exist)");
  args.flag("--overwrite", &c.overwrite, "replace an existing transitions file (after the run)");
  args.option("--cut", &r.cut, "clustering cut of the states (default 0.05, the experiments' cut)");
  args.option("--modes", &r.saddles.modes, "softest non-rigid modes searched per state, both directions (default 4)");
  args.option("--states", &r.max_states, "states searched from, lowest energy first (default 0: every state)");
  args.option("--pair-gap", &r.pair_gap,
              "double-ended searches between states whose energy ranks differ by at most G (default 1; 0: none)");
  args.option("--max-pairs", &r.max_pairs, "double-ended searches at most (default 8)");
  args.option("--stages", &r.pair.max_stages, "steering stages of a double-ended search (default 60)");
  args.option("--max-iter", &r.saddles.search.max_iterations, "iterations per single-ended saddle search (default 400)");
  args.option("--images", &r.saddles.max_images, "images kept per descent (default 24)");
  args.flag("--quiet", &c.quiet, "no progress lines");
  args.flag("--json", &c.json, "print one JSON object");
  return args.parse(argc, argv);
}

}  // namespace

int cmd_transitions(int argc, char** argv) {
  TransitionsCommand c;
  if (!parse_transitions(argc, argv, c)) return 0;
  if (c.out.empty()) throw InputError("-o FILE.h5 is required");
  if (std::filesystem::exists(c.out) && !c.overwrite)
    throw InputError("output " + c.out + " exists (use --overwrite to replace it)");
  c.run.validate();
  check_writable(c.out);
  const auto t0 = Clock::now();
  const DatasetReader reader(c.dataset);
  const KnotEntry entry = reader.read(c.name);
  const bool show = !c.quiet && !c.json;
  c.run.progress = [show, t0](const std::string& what) {
    if (show)
      std::fprintf(stderr, "progress: %s, %.0f s\n", what.c_str(),
                   std::chrono::duration<double>(Clock::now() - t0).count());
  };
  const TransitionGraph g = knot_transitions(entry, reader.metadata(), c.run);
  const std::string key = transition_run_key(c.name, c.run, reader.metadata().edge_length.value_or(1.0));
  write_transitions(c.out, g, c.dataset, key, true);
  const double seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  if (c.json) {
    Json j = graph_json(g);
    j["output"] = c.out;
    j["seconds"] = number(seconds);
    print_json(j);
  } else {
    print_graph(g, seconds);
    std::cout << "wrote " << c.out << "\n";
  }
  return 0;
}

}  // namespace ek::cli
