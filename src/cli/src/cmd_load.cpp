// knots load STATE (--pull I,J | --plates | --force I,J) --to X [--from X] [--normal X,Y,Z] [--steps N]
//            [--max-points N] [--go-on] [--rest-length L] [--dataset FILE] -o DIR [--overwrite] [--json]
//
// A knot under load (ek/mechanics/knot_loading.hpp): the stable equilibria
// along the load path, the device's force against its displacement, and the
// snaps. DIR is written as a whole (folder_output.hpp).
#include <cmath>
#include <iostream>
#include <sstream>

#include "args.hpp"
#include "commands.hpp"
#include "ek/core/atomic_file.hpp"
#include "ek/core/errors.hpp"
#include "ek/dataset/dataset_file.hpp"
#include "ek/dataset/json.hpp"
#include "ek/geometry/curve_io.hpp"
#include "ek/geometry/polyline.hpp"
#include "ek/mechanics/json.hpp"
#include "ek/mechanics/knot_loading.hpp"
#include "folder_output.hpp"
#include "output.hpp"

namespace ek::cli {
namespace {

namespace fs = std::filesystem;

struct LoadCommand {
  std::string file, out, dataset;
  std::optional<std::string> pull, force, normal;
  bool plates = false, go_on = false, json = false, overwrite = false, as_is = false;
  std::optional<double> rest_length;  // [length]
  KnotLoadOptions options;
};

bool parse_load(int argc, char** argv, LoadCommand& c) {
  KnotLoadOptions& o = c.options;
  ArgParser args("load", "STATE (--pull I,J | --plates | --force I,J) --to X [--from X] [--normal X,Y,Z] [--steps N] "
                         "[--max-points N] [--go-on] [--as-is] [--rest-length L] [--dataset FILE] -o DIR [--overwrite] [--json]");
  args.positional("STATE", &c.file, "a curve (.obj or .txt), relaxed first without load; e.g. from knots export");
  args.option("--pull", &c.pull, "pull vertices I and J (0-based) apart: the control is their distance");
  args.flag("--plates", &c.plates, "press the knot between two parallel plates: the control is their gap");
  args.option("--force", &c.force, "opposite forces on vertices I and J along their line: the control is the force");
  args.option("--to", &o.to, "where the control ends (distance, gap or force)");
  args.option("--from", &o.from,
              "where it starts (default: the relaxed state's distance of I and J, its extent along the plates' "
              "normal plus the plates' reach on each side, or force 0)");
  args.option("--normal", &c.normal, "the plates' normal (default: the relaxed state's axis of least extent)");
  args.option("--steps", &o.steps, "the first step is |to - from| / steps (default 40)");
  args.option("--max-points", &o.max_points, "points of the path at most (default 400)");
  args.flag("--go-on", &c.go_on, "go on after a snap from the state it fell into (default: stop at the first)");
  args.flag("--as-is", &c.as_is,
            "take STATE as it is, without relaxing it first: an equilibrium under the load at --from (e.g. a point "
            "of an earlier path); needs --from");
  args.option("--rest-length", &c.rest_length, "rest length of every edge (default: the state's own edge lengths)");
  args.option("--dataset", &c.dataset, "match the start and each snap's released state to this data set's equilibria");
  args.option("-o,--output", &c.out, "folder for path.csv, the curves and summary.json (must not exist)");
  args.flag("--overwrite", &c.overwrite, "replace an existing output folder (after the run, when complete)");
  args.flag("--json", &c.json, "print the summary as one JSON object");
  return args.parse(argc, argv);
}

/// "I,J" as two vertex indices.
std::array<int, 2> parse_pair(const std::string& text, const std::string& option) {
  std::istringstream in(text);
  std::array<int, 2> v{-1, -1};
  char comma = 0;
  if (!(in >> v[0] >> comma >> v[1]) || comma != ',' || !in.eof())
    throw InputError(option + " expects two vertex indices I,J, not '" + text + "'");
  return v;
}

/// The options' load from the command line: exactly one of --pull, --plates, --force.
void resolve_load(LoadCommand& c) {
  const int chosen = (c.pull ? 1 : 0) + (c.plates ? 1 : 0) + (c.force ? 1 : 0);
  require_input(chosen == 1, "give exactly one of --pull I,J, --plates and --force I,J");
  KnotLoadOptions& o = c.options;
  if (c.pull) {
    o.kind = LoadKind::Pull;
    o.vertices = parse_pair(*c.pull, "--pull");
  } else if (c.force) {
    o.kind = LoadKind::Force;
    o.vertices = parse_pair(*c.force, "--force");
  } else {
    o.kind = LoadKind::Plates;
  }
  require_input(!c.normal || o.kind == LoadKind::Plates, "--normal applies to --plates only");
  if (c.normal) o.normal = parse_vec3(*c.normal, "--normal");
  require_input(!c.rest_length || (*c.rest_length > 0.0 && std::isfinite(*c.rest_length)),
                "--rest-length must be positive");
  o.stop_at_snap = !c.go_on;
  require_input(!c.as_is || o.from, "--as-is needs --from: the control at which STATE is an equilibrium");
  o.relax_start = !c.as_is;
  o.validate();
}

Json summary_json(const LoadCommand& c, const KnotLoadResult& r, const DatasetReader* reader) {
  std::vector<Json> released;
  for (const Snap& s : r.snaps) released.push_back(closest_equilibrium_json(reader, s.released));
  return framed_summary(
      c.file, knot_load_json(c.options, r, closest_equilibrium_json(reader, as_points(r.path.points.front().dofs)), released),
      c.out);
}

/// path.csv: one row per point; `stiffness` is the secant dF/dδ from the
/// previous point (empty at the first and across a snap).
void write_path_csv(const fs::path& file, const KnotLoadResult& r) {
  AtomicFile f(file.string());
  std::ostream& out = f.stream();
  out.precision(12);
  out << "point,parameter,displacement,reaction,stiffness,energy,load_energy,gradient_norm,index,lowest_eigenvalue,"
         "stable,event,corrector_iterations\n";
  const auto& pts = r.path.points;
  for (size_t k = 0; k < pts.size(); ++k) {
    const PathPoint& p = pts[k];
    out << k << "," << p.parameter << "," << p.displacement << "," << p.reaction << ",";
    if (const auto stiffness = secant_stiffness(r.path, k)) out << *stiffness;
    out << "," << p.energy << "," << p.load_energy << "," << p.gradient_norm << "," << p.index << ","
        << p.lowest_eigenvalue << "," << (p.stable ? "true" : "false") << "," << to_string(p.event) << ","
        << p.corrector_iterations << "\n";
  }
  f.commit();
}

void write_outputs(const LoadCommand& c, const KnotLoadResult& r, const Json& summary) {
  write_folder(c.out, [&](const fs::path& tmp) {
    const auto& pts = r.path.points;
    write_path_csv(tmp / "path.csv", r);
    write_curve((tmp / "start.obj").string(), as_points(pts.front().dofs));
    write_curve((tmp / "end.obj").string(), as_points(pts.back().dofs));
    for (size_t k = 0; k < r.snaps.size(); ++k) {
      const Snap& s = r.snaps[k];
      const std::string id = std::to_string(k);
      write_curve((tmp / ("snap_" + id + "_before.obj")).string(),
                  as_points(pts[static_cast<size_t>(s.point) - 1].dofs));
      write_curve((tmp / ("snap_" + id + "_loaded.obj")).string(), s.loaded);
      write_curve((tmp / ("snap_" + id + "_released.obj")).string(), s.released);
    }
    write_summary_json(tmp, summary);
  });
}

}  // namespace

int cmd_load(int argc, char** argv) {
  LoadCommand c;
  if (!parse_load(argc, argv, c)) return 0;
  resolve_load(c);
  check_output_folder(c.out, c.overwrite);
  const Points state = read_curve(c.file);
  const VecX rest = c.rest_length ? VecX::Constant(state.rows(), *c.rest_length) : edge_lengths(state);
  std::optional<DatasetReader> reader;
  if (!c.dataset.empty()) reader.emplace(c.dataset);
  const KnotLoadResult r = load_knot(state, rest, c.options);
  if (r.path.points.empty()) {
    std::cerr << "knots load: no equilibrium under the load at its start (" << r.parameter_name << " "
              << fmt(r.from) << "): the path " << to_string(r.path.status)
              << " before its first point; start where the relaxed knot rests under the load (without --from the "
                 "load starts touching it); nothing is written"
              << std::endl;
    return 1;
  }
  if (!r.alexander_preserved) throw TopologyError("load: the knot type changed along the path; nothing is written");
  const Json summary = summary_json(c, r, reader ? &*reader : nullptr);
  write_outputs(c, r, summary);
  if (c.json) {
    print_json(summary);
    return 0;
  }
  const auto& pts = r.path.points;
  std::cout << to_string(c.options.kind) << ": " << r.parameter_name << " " << fmt(pts.front().parameter) << " -> "
            << fmt(pts.back().parameter) << " (" << to_string(r.path.status) << ", " << pts.size() << " points, "
            << fmt(r.path.seconds, 3) << " s)\n"
            << "energy " << fmt(r.start_energy) << " -> " << fmt(pts.back().energy) << ", work " << fmt(r.work)
            << ", dissipated " << fmt(r.dissipated) << ", branch jumps " << r.branch_jumps << "\n";
  for (const Snap& s : r.snaps)
    std::cout << "snap at " << r.parameter_name << " " << fmt(s.parameter) << ", force " << fmt(s.reaction)
              << ", jump " << fmt(s.jump, 4) << ", energy drop " << fmt(s.energy_drop, 4) << "; released: "
              << s.released_status << ", energy " << fmt(s.released_energy) << "\n";
  std::cout << "wrote " << c.out << "\n";
  return 0;
}

}  // namespace ek::cli
