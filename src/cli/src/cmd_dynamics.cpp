// knots dynamics STATE [--link LK] [--time-step H] [--duration T] [--density RHO] [--damping G]
//                [--gravity X,Y,Z] [--friction MU] [--friction-velocity V] [--envelope H]
//                [--envelope-speed S] [--velocity FILE] [--frame-every K] [--rest-speed V] [--rest-steps K]
//                [--rest-length L | --rest-from CURVE] [--dataset FILE] -o DIR [--overwrite] [--json]
//
// A knot in time (ek/mechanics/dynamics.hpp): backward Euler with inertia,
// damping, gravity and friction on the relaxation's model. DIR is written
// as a whole (folder_output.hpp).
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "args.hpp"
#include "commands.hpp"
#include "ek/analysis/attributes.hpp"
#include "ek/core/atomic_file.hpp"
#include "ek/core/errors.hpp"
#include "ek/core/stopwatch.hpp"
#include "ek/dataset/dataset_file.hpp"
#include "ek/dataset/json.hpp"
#include "ek/geometry/curve_io.hpp"
#include "ek/geometry/polyline.hpp"
#include "ek/mechanics/json.hpp"
#include "folder_output.hpp"
#include "output.hpp"

namespace ek::cli {
namespace {

namespace fs = std::filesystem;

struct DynamicsCommand {
  std::string file, out, dataset, velocity, rest_from;
  std::optional<std::string> gravity;
  std::optional<double> link, envelope, rest_length;
  bool json = false, overwrite = false;
  DynamicsOptions options;
};

bool parse_dynamics(int argc, char** argv, DynamicsCommand& c) {
  DynamicsOptions& o = c.options;
  ArgParser args("dynamics",
                 "STATE [--link LK] [--time-step H] [--duration T] [--density RHO] [--damping G] [--gravity X,Y,Z] "
                 "[--friction MU] [--friction-velocity V] [--envelope H] [--envelope-speed S] [--velocity FILE] "
                 "[--frame-every K] [--rest-speed V] [--rest-steps K] [--rest-length L | --rest-from CURVE] [--dataset FILE] -o DIR "
                 "[--overwrite] [--json]");
  args.positional("STATE", &c.file, "a curve (.obj or .txt): the start, at rest unless --velocity");
  args.option("--link", &c.link, "prescribed link Lk [turns]: the full model with the twist following quasi-statically "
                                 "(default: twist-free)");
  args.option("--time-step", &o.time_step, "time step h [time] (default 1)");
  args.option("--duration", &o.duration, "the run ends at this time unless it comes to rest first (default 100)");
  args.option("--density", &o.density, "density rho of the wire [mass/length^3] (default 1)");
  args.option("--damping", &o.damping, "viscous damping gamma [1/time]: a force -gamma m v on every vertex (default 0)");
  args.option("--gravity", &c.gravity, "gravity X,Y,Z [length/time^2] (default none)");
  args.option("--friction", &o.friction, "Coulomb friction coefficient mu between touching wires and against the "
                                         "envelope (default 0)");
  args.option("--friction-velocity", &o.friction_velocity,
              "slower relative motions feel viscous, not Coulomb, friction [length/time] (default 1e-3)");
  args.option("--envelope", &c.envelope, "half-thickness H of the envelope |z| < H (the planarity slab's plates; "
                                         "default: none, a flat start is released at t = 0)");
  args.option("--envelope-speed", &o.envelope_speed, "each plate moves away from z = 0 at this speed (default 0: held)");
  args.option("--velocity", &c.velocity, "the start velocities: a .obj or .txt file with one row per vertex, in "
                                         "order (equal rows allowed; default: at rest)");
  args.option("--frame-every", &o.frame_every, "a frame every K steps (default 10)");
  args.option("--rest-speed", &o.rest_speed, "at rest once every vertex is slower than this for --rest-steps steps "
                                             "(default 0: run to the end)");
  args.option("--rest-steps", &o.rest_steps, "steps below --rest-speed that count as rest (default 10)");
  args.option("--rest-length", &c.rest_length, "rest length of every edge (default: the state's own edge lengths)");
  args.option("--rest-from", &c.rest_from, "a curve with as many vertices whose edge lengths are the rest lengths (e.g. "
                                           "the coil a flat state was relaxed from)");
  args.option("--dataset", &c.dataset, "match the end state to this data set's equilibria");
  args.option("-o,--output", &c.out, "folder for trajectory.csv, the frames and summary.json (must not exist)");
  args.flag("--overwrite", &c.overwrite, "replace an existing output folder (after the run, when complete)");
  args.flag("--json", &c.json, "print the summary as one JSON object");
  return args.parse(argc, argv);
}

void resolve(DynamicsCommand& c) {
  DynamicsOptions& o = c.options;
  o.model.link = c.link;
  if (c.gravity) o.gravity = parse_vec3(*c.gravity, "--gravity");
  if (c.envelope) {
    o.envelope = SlabOptions();
    o.envelope->half_thickness = *c.envelope;
  }
  require_input(!c.rest_length || (*c.rest_length > 0.0 && std::isfinite(*c.rest_length)),
                "--rest-length must be positive");
  require_input(!c.rest_length || c.rest_from.empty(), "give --rest-length or --rest-from, not both");
  o.validate();
}

/// trajectory.csv: one row per frame.
void write_trajectory(const fs::path& file, const DynamicsResult& r) {
  AtomicFile f(file.string());
  std::ostream& out = f.stream();
  out.precision(12);
  out << "frame,time,kinetic,elastic,gravity,total,max_speed,contacts,threedim,newton_iterations\n";
  for (size_t k = 0; k < r.frames.size(); ++k) {
    const DynamicsFrame& fr = r.frames[k];
    out << k << "," << fr.time << "," << fr.kinetic << "," << fr.elastic << "," << fr.gravity << ","
        << fr.kinetic + fr.elastic + fr.gravity << "," << fr.max_speed << "," << fr.contacts << ","
        << threedim(fr.positions) << "," << fr.newton_iterations << "\n";
  }
  f.commit();
}

void write_outputs(const DynamicsCommand& c, const DynamicsResult& r, const Json& summary) {
  write_folder(c.out, [&](const fs::path& tmp) {
    write_trajectory(tmp / "trajectory.csv", r);
    fs::create_directories(tmp / "frames");
    for (size_t k = 0; k < r.frames.size(); ++k) {
      char name[32];
      std::snprintf(name, sizeof name, "%05zu.obj", k);
      write_curve((tmp / "frames" / name).string(), r.frames[k].positions);
    }
    write_curve((tmp / "start.obj").string(), r.frames.front().positions);
    write_curve((tmp / "end.obj").string(), r.positions);
    write_summary_json(tmp, summary);
  });
}

}  // namespace

int cmd_dynamics(int argc, char** argv) {
  DynamicsCommand c;
  if (!parse_dynamics(argc, argv, c)) return 0;
  resolve(c);
  check_output_folder(c.out, c.overwrite);
  const Points state = read_curve(c.file);
  const Points velocity = c.velocity.empty() ? Points() : read_vectors(c.velocity);
  const VecX rest = c.rest_length          ? VecX::Constant(state.rows(), *c.rest_length)
                    : c.rest_from.empty() ? edge_lengths(state)
                                          : edge_lengths(read_curve(c.rest_from));
  std::optional<DatasetReader> reader;
  if (!c.dataset.empty()) reader.emplace(c.dataset);
  const Stopwatch t0;
  const DynamicsResult r = simulate(state, rest, c.options, velocity);
  const double seconds = t0.seconds();
  if (!r.alexander_preserved) throw TopologyError("dynamics: the knot type changed; nothing is written");
  const Json summary = framed_summary(
      c.file, dynamics_json(c.options, r, closest_equilibrium_json(reader ? &*reader : nullptr, r.positions), seconds),
      c.out);
  write_outputs(c, r, summary);
  if (c.json) {
    print_json(summary);
    return r.status == DynamicsStatus::StepFailed ? 1 : 0;
  }
  std::cout << to_string(r.model) << ", " << r.status << (r.failed_status ? " (" + to_string(*r.failed_status) + ")" : "") << " at t = "
            << fmt(r.time) << " after " << r.steps << " steps (" << r.newton_iterations << " Newton iterations, "
            << fmt(seconds, 3) << " s)\n"
            << "elastic energy " << fmt(summary["start_energy"].get<double>()) << " -> "
            << fmt(summary["end_energy"].get<double>()) << ", 3D-ness " << fmt(summary["start_threedim"].get<double>())
            << " -> " << fmt(summary["end_threedim"].get<double>()) << " (max "
            << fmt(summary["max_threedim"].get<double>()) << "), max speed " << fmt(r.max_speed) << "\n"
            << "wrote " << c.out << "\n";
  return r.status == DynamicsStatus::StepFailed ? 1 : 0;
}

}  // namespace ek::cli
