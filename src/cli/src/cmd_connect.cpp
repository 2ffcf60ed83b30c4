// knots connect TRANSITIONS NAME A B [--searches N] [--stages S] [--dataset FILE] -o OUT.h5 [--overwrite] [--json]
#include <filesystem>
#include <iostream>

#include "args.hpp"
#include "commands.hpp"
#include "ek/core/atomic_file.hpp"
#include "ek/core/errors.hpp"
#include "ek/dataset/dataset_file.hpp"
#include "ek/transitions/connect.hpp"
#include "ek/transitions/run.hpp"
#include "ek/transitions/transitions_file.hpp"
#include "output.hpp"
#include "transitions_json.hpp"

namespace ek::cli {
namespace {

struct ConnectCommand {
  std::string file, name, a_text, b_text, dataset, out;
  bool json = false, overwrite = false;
  ConnectOptions options;
};

bool parse_connect(int argc, char** argv, ConnectCommand& c) {
  ArgParser args("connect", "TRANSITIONS NAME A B [--searches N] [--stages S] [--dataset FILE] -o OUT.h5 "
                            "[--overwrite] [--json]");
  args.positional("TRANSITIONS", &c.file, "a transitions file of the knot (knots transitions)");
  args.positional("NAME", &c.name, "the knot (checked against the file)");
  args.positional("A", &c.a_text, "the first state (index in the graph)");
  args.positional("B", &c.b_text, "the second state");
  args.option("-o,--output", &c.out, "the grown graph (a transitions file), written atomically (must not exist)");
  args.flag("--overwrite", &c.overwrite, "replace an existing OUT.h5 (after the run; it may be TRANSITIONS itself)");
  args.option("--searches", &c.options.max_searches, "double-ended searches at most (default 6)");
  args.option("--stages", &c.options.search.max_stages, "steering stages of each search (default 60)");
  args.option("--dataset", &c.dataset, "the data set of the model (default: the one the file records)");
  args.flag("--json", &c.json, "print one JSON object");
  return args.parse(argc, argv);
}

Json result_json(const ConnectResult& r, int a, int b) {
  Json j;
  j["from"] = a;
  j["to"] = b;
  j["connected"] = r.connected;
  j["status"] = to_string(r.status);
  j["attempts"] = r.attempts;
  j["edges"] = r.chain;
  j["barrier_forward"] = r.connected ? number(r.barrier_forward) : Json(nullptr);
  j["barrier_backward"] = r.connected ? number(r.barrier_backward) : Json(nullptr);
  j["barrier_forward_scaled"] = r.connected ? number(r.barrier_forward_scaled) : Json(nullptr);
  j["barrier_backward_scaled"] = r.connected ? number(r.barrier_backward_scaled) : Json(nullptr);
  j["upper_bound_scaled"] = r.upper_bound_scaled ? number(*r.upper_bound_scaled) : Json(nullptr);
  Json list = Json::array();
  for (const ConnectAttempt& x : r.attempt_list) {
    Json t;
    t["u"] = x.u;
    t["v"] = x.v;
    t["status"] = to_string(x.status);
    t["reached"] = x.reached;
    t["edges_added"] = x.edges_added;
    t["states_added"] = x.states_added;
    t["seconds"] = number(x.seconds);
    list.push_back(t);
  }
  j["searches"] = list;
  return j;
}

}  // namespace

int cmd_connect(int argc, char** argv) {
  ConnectCommand c;
  if (!parse_connect(argc, argv, c)) return 0;
  if (c.out.empty()) throw InputError("-o OUT.h5 is required");
  refuse_existing_output(c.out, c.overwrite);
  check_writable(c.out);
  TransitionsFileInfo info;
  TransitionGraph g = read_transitions(c.file, info);
  require_input(g.knot == c.name, c.file + " holds the transitions of " + g.knot + ", not of " + c.name);
  const int a = parse_state(c.a_text, g, "A"), b = parse_state(c.b_text, g, "B");
  require_input(a != b, "A and B are the same state");
  const std::string dataset = c.dataset.empty() ? info.dataset : c.dataset;
  require_input(std::filesystem::exists(dataset),
                "the data set '" + dataset + "' does not exist (give it with --dataset)");
  const DatasetMetadata metadata = DatasetReader(dataset).metadata();
  c.options.search.saddle.relax = dataset_model(metadata);
  c.options.validate();
  const VecX rest = VecX::Constant(g.states[a].positions.rows(), metadata.edge_length.value_or(1.0));
  const ConnectResult r = connect_states(g, a, b, rest, c.options, knot_similarity(c.name), 1.0 - g.cut);
  write_transitions(c.out, g, dataset,
                    info.options + "; connect " + std::to_string(a) + " " + std::to_string(b) + " searches=" +
                        std::to_string(c.options.max_searches) + " stages=" + std::to_string(c.options.search.max_stages),
                    info.complete, info.states_searched);
  if (c.json) {
    Json j = result_json(r, a, b);
    j["output"] = c.out;
    j["seconds"] = number(r.seconds);
    print_json(j);
  } else {
    std::cout << "connect " << a << " -> " << b << ": " << to_string(r.status) << " after " << r.attempts
              << " searches";
    if (r.connected)
      std::cout << ", " << r.chain.size() << " saddles, barrier " << fmt(r.barrier_forward_scaled, 5) << " / "
                << fmt(r.barrier_backward_scaled, 5) << " EI/L";
    std::cout << "\nwrote " << c.out << "\n";
  }
  return r.connected ? 0 : 1;
}

}  // namespace ek::cli
