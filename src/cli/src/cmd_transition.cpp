// knots transition A B [--link LK] [--rest-length L] [--stages N] [--seeds K] [--images M]
//                  [--max-iter N] -o DIR [--overwrite] [--json]
//
// The double-ended search between two stable states (ek/transitions/double_ended.hpp).
// DIR is written as a whole (folder_output.hpp): a.obj, b.obj (B aligned to
// A), chain.obj (the steered path's images, "o image_<k> E=<energy>"),
// summary.json, and when the saddle is verified saddle.obj and path.obj (A
// over the saddle to B).
#include <chrono>
#include <iostream>

#include "args.hpp"
#include "commands.hpp"
#include "ek/analysis/similarity.hpp"
#include "ek/core/atomic_file.hpp"
#include "ek/core/errors.hpp"
#include "ek/geometry/curve_io.hpp"
#include "ek/transitions/double_ended.hpp"
#include "folder_output.hpp"
#include "output.hpp"

namespace ek::cli {
namespace {

namespace fs = std::filesystem;

struct TransitionCommand {
  std::string a, b, out;
  double rest_length = 1.0;  // [length]
  bool json = false, overwrite = false;
  TransitionSearchOptions options;
};

bool parse_transition(int argc, char** argv, TransitionCommand& c) {
  TransitionSearchOptions& o = c.options;
  ArgParser args("transition", "A B [--link LK] [--rest-length L] [--stages N] [--seeds K] [--images M] "
                               "[--max-iter N] -o DIR [--overwrite] [--json]");
  args.positional("A", &c.a, "a stable equilibrium (.obj or .txt): the start");
  args.positional("B", &c.b, "another stable equilibrium of the same knot, with as many vertices: the goal");
  args.option("-o,--output", &c.out, "folder for the summary, the chain, the saddle and its path (must not exist)");
  args.flag("--overwrite", &c.overwrite, "replace an existing output folder (after the run, when complete)");
  args.option("--link", &o.saddle.relax.link, "prescribed link Lk (the full model with Theta fixed); default: Theta free");
  args.option("--rest-length", &c.rest_length, "rest length of every edge (default 1: the data sets' lattice edges)");
  args.option("--stages", &o.max_stages, "steering stages before not-reached (default 60; stiffness x1.5 each)");
  args.option("--seeds", &o.seeds, "highest local maxima of the energy along the chain that seed a saddle search (default 3)");
  args.option("--images", &o.max_images, "images kept in the chain (default 48)");
  args.option("--max-iter", &o.search_iterations, "iterations per saddle search (default 1500)");
  args.flag("--json", &c.json, "print the summary as one JSON object");
  return args.parse(argc, argv);
}

Json minimum_json(const SaddleMinimum& m, double to_b) {
  Json j;
  j["energy"] = number(m.energy);
  j["status"] = to_string(m.status);
  j["gradient_norm"] = number(m.gradient_norm);
  j["a_similarity"] = number(m.start_similarity);
  j["b_similarity"] = number(to_b);
  j["images"] = m.images.size();
  return j;
}

/// The seed's saddle search: null when none ran.
Json saddle_json(const TransitionSearch& t) {
  if (t.seeds_tried == 0) return nullptr;
  const SaddleRecord& r = t.saddle;
  Json j;
  j["status"] = to_string(r.status);
  j["verified"] = r.verified;
  j["energy"] = number(r.energy);
  const bool descended = !r.minima[0].images.empty();
  const auto barrier = [&](int k, double scale) {
    return descended ? number((r.energy - r.minima[k].energy) / scale) : Json(nullptr);
  };
  j["barrier_forward"] = barrier(0, 1.0);
  j["barrier_backward"] = barrier(1, 1.0);
  j["barrier_forward_scaled"] = barrier(0, t.energy_scale);
  j["barrier_backward_scaled"] = barrier(1, t.energy_scale);
  j["negative_eigenvalue"] = number(r.negative_eigenvalue);
  j["second_eigenvalue"] = number(r.second_eigenvalue);
  j["index"] = r.index;
  j["gradient_norm"] = number(r.gradient_norm);
  j["iterations"] = r.iterations;
  Json minima = Json::array();
  if (!r.minima[0].images.empty())
    for (int k = 0; k < 2; ++k) minima.push_back(minimum_json(r.minima[k], t.minima_to_b[k]));
  j["minima"] = minima;
  j["seconds"] = number(r.seconds);
  return j;
}

Json summary_json(const TransitionCommand& c, const TransitionSearch& t) {
  Json j;
  j["a"] = c.a;
  j["b"] = c.b;
  j["status"] = to_string(t.status);
  j["reached"] = t.reached;
  j["verified"] = t.verified;
  j["energy_a"] = number(t.energy_a);
  j["energy_b"] = number(t.energy_b);
  j["energy_scale"] = number(t.energy_scale);
  j["similarity_ab"] = number(t.similarity_ab);
  j["alignment_distance"] = number(t.alignment_distance);
  j["stages"] = t.stages;
  j["final_stiffness"] = number(t.final_stiffness);
  j["reached_similarity"] = number(t.reached_similarity);
  j["chain_images"] = t.chain.size();
  j["alexander_preserved"] = t.alexander_preserved;
  j["path_barrier"] = number(t.path_barrier);
  j["path_barrier_scaled"] = number(t.path_barrier / t.energy_scale);
  j["seeds_tried"] = t.seeds_tried;
  Json seeds = Json::array();
  for (const SearchStatus& s : t.seed_statuses) seeds.push_back(to_string(s));
  j["seed_statuses"] = seeds;
  j["saddle"] = saddle_json(t);
  j["output"] = c.out;
  j["seconds"] = number(t.seconds);
  return j;
}

void write_outputs(const TransitionCommand& c, const TransitionSearch& t, const Json& summary) {
  write_folder(c.out, [&](const fs::path& tmp) {
    write_curve((tmp / "a.obj").string(), t.a);
    write_curve((tmp / "b.obj").string(), t.b);
    if (!t.chain.empty()) write_path_obj((tmp / "chain.obj").string(), t.chain, t.chain_energies);
    if (t.verified) {
      write_curve((tmp / "saddle.obj").string(), t.saddle.saddle);
      std::vector<double> energies;
      int at = 0;
      const std::vector<Points> path = saddle_path(t.saddle, energies, at);
      write_path_obj((tmp / "path.obj").string(), path, energies);
    }
    write_summary_json(tmp, summary);
  });
}

void print_text(const TransitionSearch& t) {
  std::cout << "A: energy " << fmt(t.energy_a) << ", B: energy " << fmt(t.energy_b) << ", similarity "
            << fmt(t.similarity_ab, 4) << ", aligned distance " << fmt(t.alignment_distance, 4) << "\n";
  std::cout << "steering: " << t.stages << " stages, " << (t.reached ? "reached B" : "B not reached")
            << " (similarity " << fmt(t.reached_similarity, 4) << "), " << t.chain.size() << " images";
  if (t.reached) std::cout << ", highest image " << fmt(t.path_barrier / t.energy_scale, 5) << " EI/L above A";
  std::cout << "\n";
  if (t.seeds_tried > 0) {
    const SaddleRecord& r = t.saddle;
    std::cout << "saddle (" << t.seeds_tried << " seed(s)): " << to_string(r.status);
    if (r.verified)
      std::cout << ", energy " << fmt(r.energy) << ", barrier "
                << fmt((r.energy - r.minima[0].energy) / t.energy_scale, 5) << " / "
                << fmt((r.energy - r.minima[1].energy) / t.energy_scale, 5) << " EI/L, lambda "
                << fmt(r.negative_eigenvalue, 4);
    std::cout << "\n";
  }
  std::cout << "status: " << to_string(t.status) << ", " << fmt(t.seconds, 4) << " s\n";
}

}  // namespace

int cmd_transition(int argc, char** argv) {
  TransitionCommand c;
  if (!parse_transition(argc, argv, c)) return 0;
  require_input(c.rest_length > 0.0 && std::isfinite(c.rest_length), "--rest-length must be positive");
  c.options.validate();
  check_output_folder(c.out, c.overwrite);
  const Points a = read_curve(c.a);
  const Points b = read_curve(c.b);
  require_input(a.rows() == b.rows(), "A and B must have the same number of vertices (" + std::to_string(a.rows()) +
                                          " and " + std::to_string(b.rows()) + ")");
  const VecX rest = VecX::Constant(a.rows(), c.rest_length);
  SimilarityOptions so;
  so.reversal = true;
  const CurveSimilarity sim = [so](const Points& p, const Points& q) { return similarity(p, q, so); };
  const TransitionSearch t = transition_search(a, b, rest, c.options, sim);
  const Json summary = summary_json(c, t);
  write_outputs(c, t, summary);
  if (c.json) print_json(summary);
  else print_text(t);
  return 0;
}

}  // namespace ek::cli
