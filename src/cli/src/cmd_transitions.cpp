// knots transitions DATASET NAME [--cut C] [--modes K] [--states N] [--pair-gap G] [--max-pairs P] [--stages S]
//                   [--max-iter N] [--images M] -o FILE.h5 [--overwrite] [--quiet] [--json]
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include "args.hpp"
#include "commands.hpp"
#include "ek/core/atomic_file.hpp"
#include "ek/core/errors.hpp"
#include "ek/core/stopwatch.hpp"
#include "ek/dataset/dataset_file.hpp"
#include "ek/transitions/graph.hpp"
#include "ek/transitions/run.hpp"
#include "ek/transitions/transitions_file.hpp"
#include "output.hpp"
#include "transitions_json.hpp"

namespace ek::cli {
namespace {


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
  args.option("-o,--output", &c.out,
              "the transitions file (HDF5), written atomically (must not exist); a killed run resumes from FILE.h5.work/");
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

/// The checkpoint a killed run left in `work`, when it is of this run (same
/// options text); a checkpoint of other options is refused.
std::optional<TransitionResume> read_checkpoint(const std::string& work, const std::string& key) {
  const std::string file = work + "/checkpoint.h5";
  if (!std::filesystem::exists(file)) return std::nullopt;
  TransitionsFileInfo info;
  TransitionResume r;
  try {
    r.graph = read_transitions(file, info);
  } catch (const InputError& e) {
    throw InputError(std::string(e.what()) + "; remove '" + work + "' to start over");
  }
  if (info.options != key || info.states_searched < 0)
    throw InputError("'" + work + "' holds a checkpoint of a run with other options; remove it to start over");
  r.states_searched = info.states_searched;
  return r;
}

/// "progress: <what>, <done>/<total> units, <elapsed> s, ETA <s> s" on stderr;
/// the ETA extrapolates this process's units (resumed ones are not timed).
std::function<void(const std::string&, int, int)> progress_lines(bool show) {
  const Stopwatch t0;
  auto first = std::make_shared<int>(-1);
  return [show, t0, first](const std::string& what, int done, int total) {
    if (!show) return;
    if (*first < 0) *first = done;
    const double elapsed = t0.seconds();
    std::string eta = "ETA unknown";
    if (done > *first) eta = "ETA " + fmt(elapsed / (done - *first) * (total - done), 3) + " s";
    std::fprintf(stderr, "progress: %s, %d/%d units done, %.0f s, %s\n", what.c_str(), done, total, elapsed,
                 eta.c_str());
  };
}

}  // namespace

int cmd_transitions(int argc, char** argv) {
  TransitionsCommand c;
  if (!parse_transitions(argc, argv, c)) return 0;
  if (c.out.empty()) throw InputError("-o FILE.h5 is required");
  refuse_existing_output(c.out, c.overwrite);
  c.run.validate();
  check_writable(c.out);
  const Stopwatch t0;
  const DatasetReader reader(c.dataset);
  const KnotEntry entry = reader.read(c.name);
  const std::string key = transition_run_key(c.name, c.run, reader.metadata().edge_length.value_or(1.0));
  // a killed run's checkpoint is in OUT.work/, replaced after every unit of work
  const std::string work = c.out + ".work";
  const std::optional<TransitionResume> resume = read_checkpoint(work, key);
  std::error_code ec;
  std::filesystem::create_directories(work, ec);
  if (ec) throw InputError("cannot create work folder '" + work + "': " + ec.message());
  remove_stale_temporaries(work, "");
  int states_searched = resume ? resume->states_searched : 0;
  c.run.checkpoint = [&](const TransitionGraph& g, int states) {
    states_searched = states;
    write_transitions(work + "/checkpoint.h5", g, c.dataset, key, false, states);
  };
  c.run.progress = progress_lines(!c.quiet && !c.json);
  const TransitionGraph g = knot_transitions(entry, reader.metadata(), c.run, resume ? &*resume : nullptr);
  write_transitions(c.out, g, c.dataset, key, true, states_searched);
  std::filesystem::remove_all(work, ec);
  const double seconds = t0.seconds();
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
