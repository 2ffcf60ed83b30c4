// exp_loads: knots under load (paper Section 8.5 names "a quantitative
// analysis of the deformation of elastic knots under load" as future work;
// the method is ours: docs/models.md, "Knots under load"). The puzzle pairs
// whose barriers exp_transitions measured (the first rows of its
// puzzle_barriers.csv; curves from exp_puzzles): a state of the pair is
// loaded, in the model of its data set, by two plates along its axis of
// least extent closing to a gap of kPlatesTo wire radii, and by a pull
// across its diameter to kPullStretch times that diameter; the path goes on
// through every snap (load_knot() with stop_at_snap off). Each snap's state,
// relaxed without the load, is named: the start, the pair's other state (a
// flip) or neither, by the knot's similarity >= kReach.
//   ci:      the first pair, from its state A, plates only
//   default: the first 4 pairs, from both states, plates and pull
//   paper:   the first 12 pairs, as default
// Writes loads.csv (one row per run), snaps.csv (one row per snap),
// paths/run_<k>.csv (each run's force-displacement path), curves/ (each
// run's start and each snap's states: before it, fallen into under the load,
// released) and summary.json (docs/results.md).
#include <cmath>
#include <filesystem>
#include <iostream>

#include "ek/dataset/dataset_file.hpp"
#include "ek/geometry/curve_io.hpp"
#include "ek/mechanics/knot_loading.hpp"
#include "ek/transitions/run.hpp"
#include "experiment.hpp"
#include "loads_summary.hpp"

using namespace ek;
using namespace ek::exp;

namespace {

constexpr double kPlatesTo = 4.0;     ///< [r] the plates' final gap: two wires stacked, every crossing pressed
constexpr double kPullStretch = 1.25;  ///< [1] the pull's final distance over the start's diameter
constexpr double kReach = 0.99;       ///< [1] similarity naming a released state (as the transitions' reach)

/// One puzzle pair: its row of puzzle_barriers.csv with the curves of puzzles.csv.
struct Pair {
  CsvRow barrier;
  std::string curve_a, curve_b;
};

/// The first `count` rows of ../transitions/puzzle_barriers.csv with their curves.
std::vector<Pair> read_pairs(const Args& a, int count) {
  const std::vector<CsvRow> barriers =
      read_csv_rows(a.results + "/transitions/puzzle_barriers.csv", "exp_loads",
                    {"knot", "state_a", "state_b", "barrier_forward_scaled", "barrier_backward_scaled",
                     "upper_bound_scaled", "dataset"});
  const std::vector<CsvRow> puzzles = read_csv_rows(a.results + "/puzzles/puzzles.csv", "exp_loads",
                                                    {"knot", "state_a", "state_b", "curve_a", "curve_b"});
  std::vector<Pair> out;
  for (const CsvRow& b : barriers) {
    if (static_cast<int>(out.size()) >= count) break;
    for (const CsvRow& p : puzzles)
      if (p.at("knot") == b.at("knot") && p.at("state_a") == b.at("state_a") && p.at("state_b") == b.at("state_b")) {
        out.push_back({b, p.at("curve_a"), p.at("curve_b")});
        break;
      }
  }
  return out;
}

/// One load applied to one state of a pair.
struct Run {
  const Pair* pair = nullptr;
  bool from_b = false;  ///< loads state B (the other state is A)
  LoadKind kind = LoadKind::Plates;
};

/// What a run needs of its pair: the curves, the model, the rest lengths, EI/L.
struct Setup {
  Points start, other;
  KnotLoadOptions options;
  VecX rest;
  double energy_scale = 1.0;
  double radius = 0.0;
};

Setup setup(const Args& a, const Run& r) {
  const Pair& p = *r.pair;
  Setup s;
  const Points xa = read_curve(a.results + "/puzzles/" + p.curve_a);
  const Points xb = read_curve(a.results + "/puzzles/" + p.curve_b);
  s.start = r.from_b ? xb : xa;
  s.other = r.from_b ? xa : xb;
  const DatasetMetadata m = DatasetReader(a.results + "/" + p.barrier.at("dataset")).metadata();
  s.options.relax = dataset_model(m);
  s.radius = m.radius.value();
  s.rest = VecX::Constant(s.start.rows(), m.edge_length.value_or(1.0));
  s.energy_scale = s.options.relax.material.bending_stiffness() / s.rest.sum();
  s.options.kind = r.kind;
  s.options.stop_at_snap = false;
  if (r.kind == LoadKind::Plates) {
    s.options.to = kPlatesTo * s.radius;
  } else {
    const std::array<int, 2> v = diameter_pair(s.start);
    s.options.vertices = v;
    s.options.to = kPullStretch * (s.start.row(v[0]) - s.start.row(v[1])).norm();
  }
  return s;
}

/// "start", "other" or "neither": the released state named by similarity.
std::string name_state(const CurveSimilarity& sim, const Points& x, const Setup& s, double& to_start,
                       double& to_other) {
  to_start = sim(x, s.start);
  to_other = sim(x, s.other);
  if (to_other >= kReach && to_other > to_start) return "other";
  if (to_start >= kReach) return "start";
  return "neither";
}

/// The run's path as paths/run_<id>.csv.
void write_path(const Args& a, int id, const KnotLoadResult& res) {
  Csv csv(a.out + "/paths/run_" + std::to_string(id) + ".csv",
          {"point", "parameter", "displacement", "reaction", "energy", "event"});
  const auto& pts = res.path.points;
  for (size_t k = 0; k < pts.size(); ++k)
    csv.row({std::to_string(k), Csv::num(pts[k].parameter), Csv::num(pts[k].displacement), Csv::num(pts[k].reaction),
             Csv::num(pts[k].energy), to_string(pts[k].event)});
  csv.commit();
}

/// One run: its row of loads.csv, its snaps' rows of snaps.csv, its files.
void run_one(const Args& a, int id, const Run& r, Csv& loads, Csv& snaps, results::LoadsSummary& sum) {
  const Setup s = setup(a, r);
  const CsvRow& b = r.pair->barrier;
  const KnotLoadResult res = load_knot(s.start, s.rest, s.options);
  const CurveSimilarity sim = knot_similarity(b.at("knot"));
  const std::string tag = "curves/run_" + std::to_string(id);
  const bool started = !res.path.points.empty();  // no point: no equilibrium under the load at its start
  if (started) write_curve(a.out + "/" + tag + "_start.obj", as_points(res.path.points.front().dofs));
  int flip = -1;
  for (size_t k = 0; k < res.snaps.size(); ++k) {
    const Snap& z = res.snaps[k];
    double to_start = 0.0, to_other = 0.0;
    const std::string state = name_state(sim, z.released, s, to_start, to_other);
    if (state == "other" && flip < 0) flip = static_cast<int>(k);
    const std::string files = tag + "_snap_" + std::to_string(k);
    write_curve(a.out + "/" + files + "_before.obj", as_points(res.path.points[static_cast<size_t>(z.point) - 1].dofs));
    write_curve(a.out + "/" + files + "_loaded.obj", z.loaded);
    write_curve(a.out + "/" + files + "_released.obj", z.released);
    const PathPoint& before = res.path.points[static_cast<size_t>(z.point) - 1];
    snaps.row({std::to_string(id), std::to_string(k), std::to_string(z.point), Csv::num(z.parameter),
               Csv::num(z.reaction), Csv::num(z.jump), Csv::num(z.energy_drop / s.energy_scale), to_string(z.released_status),
               state, Csv::num(to_start), Csv::num(to_other), before.index >= 0 ? Csv::num(before.lowest_eigenvalue) : "",
               files + "_before.obj", files + "_loaded.obj", files + "_released.obj"});
    ++sum.snaps;
  }
  const Snap* f = flip >= 0 ? &res.snaps[static_cast<size_t>(flip)] : nullptr;
  const std::string barrier = b.at(r.from_b ? "barrier_backward_scaled" : "barrier_forward_scaled");
  loads.row({std::to_string(id), b.at("knot"), r.from_b ? b.at("state_b") : b.at("state_a"),
             r.from_b ? b.at("state_a") : b.at("state_b"), to_string(r.kind), res.parameter_name,
             Csv::num(res.from), Csv::num(s.options.to), to_string(res.path.status),
             std::to_string(res.path.points.size()), std::to_string(res.snaps.size()), std::to_string(res.branch_jumps),
             Csv::flag(f != nullptr),
             f ? std::to_string(flip) : "", f ? Csv::num(f->parameter) : "", f ? Csv::num(f->reaction) : "",
             f ? Csv::num(path_work(res.path, static_cast<size_t>(f->point)) / s.energy_scale) : "", barrier,
             r.from_b ? "" : b.at("upper_bound_scaled"), Csv::num(res.work / s.energy_scale),
             Csv::num(res.dissipated / s.energy_scale), Csv::flag(res.alexander_preserved),
             Csv::num(res.path.seconds, 4), started ? tag + "_start.obj" : ""});
  write_path(a, id, res);
  sum.runs_reached += res.path.status == PathStatus::Reached;
  sum.runs_with_snaps += !res.snaps.empty();
  sum.flips += f != nullptr;
  sum.branch_jumps += res.branch_jumps;
  sum.radius = s.radius;
  std::cout << "  run " << id << ": " << b.at("knot") << " " << (r.from_b ? "B" : "A") << " " << to_string(r.kind)
            << ": " << to_string(res.path.status) << ", " << res.snaps.size() << " snaps, " << res.branch_jumps
            << " branch jumps"
            << (f ? ", flips at force " + Csv::num(f->reaction, 4) : "") << " (" << res.path.seconds << " s)"
            << std::endl;
}

}  // namespace

int main(int argc, char** argv) {
  return run_experiment(argc, argv, "exp_loads", "Knots under load: the puzzle pairs pressed and pulled.",
                        [](const Args& a) {
    announce(a, "exp_loads", "the puzzle pairs pressed between plates and pulled", by_scale(a, 40.0, 900.0, 2700.0));
    std::filesystem::create_directories(a.out + "/curves");
    std::filesystem::create_directories(a.out + "/paths");
    const std::vector<Pair> pairs = read_pairs(a, by_scale(a, 1, 4, 12));
    Csv loads(a.out + "/loads.csv",
              {"run", "knot", "state_from", "state_to", "load", "parameter", "from", "to", "status", "points",
               "snaps", "branch_jumps", "flip", "flip_snap", "flip_parameter", "flip_reaction", "flip_work_scaled", "barrier_scaled",
               "upper_bound_scaled", "work_scaled", "dissipated_scaled", "alexander_preserved", "seconds",
               "curve_start"});
    Csv snaps(a.out + "/snaps.csv",
              {"run", "snap", "point", "parameter", "reaction", "jump", "energy_drop_scaled", "released_status",
               "released_state", "similarity_start", "similarity_other", "lowest_eigenvalue_before", "curve_before",
               "curve_loaded", "curve_released"});
    results::LoadsSummary sum;
    sum.scale = a.scale_name;
    sum.plates_to = kPlatesTo;
    sum.pull_stretch = kPullStretch;
    sum.reach = kReach;
    sum.pairs = static_cast<int>(pairs.size());
    std::vector<Run> runs;
    for (const Pair& p : pairs)
      for (const bool from_b : {false, true})
        for (const LoadKind kind : {LoadKind::Plates, LoadKind::Pull})
          if (a.scale != Scale::CI || (!from_b && kind == LoadKind::Plates)) runs.push_back({&p, from_b, kind});
    for (size_t k = 0; k < runs.size(); ++k) run_one(a, static_cast<int>(k), runs[k], loads, snaps, sum);
    sum.runs = static_cast<int>(runs.size());
    sum.seconds = elapsed_seconds();
    loads.commit();
    snaps.commit();
    write_summary(a, sum);
    std::cout << "exp_loads: " << sum.runs << " runs on " << sum.pairs << " pairs, " << sum.snaps << " snaps, "
              << sum.flips << " flips" << std::endl;
  });
}
