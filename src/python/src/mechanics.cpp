// mechanics: a knot under load, its path of stable equilibria and its snaps;
// a knot in time.
#include <cmath>
#include <limits>

#include "common.hpp"
#include "ek/analysis/attributes.hpp"
#include "ek/core/errors.hpp"
#include "ek/core/stopwatch.hpp"
#include "ek/dataset/json.hpp"
#include "ek/geometry/polyline.hpp"
#include "ek/mechanics/json.hpp"
#include "ek/mechanics/knot_loading.hpp"

namespace ek::python {
namespace {

/// The path's columns (those of path.csv) as numpy arrays, and its curves.
Result path_result(const LoadPath& path, Eigen::Index n) {
  const auto& pts = path.points;
  const auto m = static_cast<py::ssize_t>(pts.size());
  py::array_t<double> parameter(m), displacement(m), reaction(m), stiffness(m), energy(m), load_energy(m),
      gradient_norm(m), lowest_eigenvalue(m);
  py::array_t<int> index(m), corrector_iterations(m);
  py::array_t<bool> stable(m);
  py::list event;
  py::array_t<double> curves({m, static_cast<py::ssize_t>(n), py::ssize_t{3}});
  for (py::ssize_t k = 0; k < m; ++k) {
    const PathPoint& p = pts[static_cast<size_t>(k)];
    parameter.mutable_at(k) = p.parameter;
    displacement.mutable_at(k) = p.displacement;
    reaction.mutable_at(k) = p.reaction;
    stiffness.mutable_at(k) =
        secant_stiffness(path, static_cast<size_t>(k)).value_or(std::numeric_limits<double>::quiet_NaN());
    energy.mutable_at(k) = p.energy;
    load_energy.mutable_at(k) = p.load_energy;
    gradient_norm.mutable_at(k) = p.gradient_norm;
    index.mutable_at(k) = p.index;
    lowest_eigenvalue.mutable_at(k) = p.lowest_eigenvalue;
    stable.mutable_at(k) = p.stable;
    event.append(to_string(p.event));
    corrector_iterations.mutable_at(k) = p.corrector_iterations;
    Eigen::Map<Points>(curves.mutable_data(k), n, 3) = as_points(p.dofs.head(3 * n));
  }
  Result r{"path", py::dict()};
  r.fields["parameter"] = parameter;
  r.fields["displacement"] = displacement;
  r.fields["reaction"] = reaction;
  r.fields["stiffness"] = stiffness;
  r.fields["energy"] = energy;
  r.fields["load_energy"] = load_energy;
  r.fields["gradient_norm"] = gradient_norm;
  r.fields["index"] = index;
  r.fields["lowest_eigenvalue"] = lowest_eigenvalue;
  r.fields["stable"] = stable;
  r.fields["event"] = event;
  r.fields["corrector_iterations"] = corrector_iterations;
  r.fields["points"] = curves;
  return r;
}

Result load_state(const py::handle& state, const std::string& kind, double to,
                  std::optional<std::array<int, 2>> vertices, std::optional<double> from,
                  std::optional<std::array<double, 3>> normal, int steps, int max_points, bool go_on,
                  std::optional<double> rest_length, std::optional<std::string> dataset) {
  KnotLoadOptions o;
  o.kind = parse_load_kind(kind);
  require_input(!vertices || o.kind != LoadKind::Plates, "load: vertices apply to pull and force only");
  require_input(!normal || o.kind == LoadKind::Plates, "--normal applies to --plates only");
  require_input(!rest_length || (*rest_length > 0.0 && std::isfinite(*rest_length)), "--rest-length must be positive");
  o.vertices = vertices;
  o.from = from;
  o.to = to;
  if (normal) o.normal = Vec3((*normal)[0], (*normal)[1], (*normal)[2]);
  o.steps = steps;
  o.max_points = max_points;
  o.stop_at_snap = !go_on;
  o.validate();
  const Points P = curve_arg(state, "state");
  const VecX rest = rest_length ? VecX::Constant(P.rows(), *rest_length) : edge_lengths(P);
  std::optional<DatasetReader> reader;
  if (dataset) reader.emplace(*dataset);
  KnotLoadResult r;
  Json start_match;
  std::vector<Json> released_matches;
  {
    py::gil_scoped_release release;
    r = load_knot(P, rest, o);
    if (r.alexander_preserved) {
      const DatasetReader* dr = reader ? &*reader : nullptr;
      if (!r.path.points.empty())
        start_match = closest_equilibrium_json(dr, as_points(r.path.points.front().dofs.head(3 * P.rows())));
      for (const Snap& s : r.snaps) released_matches.push_back(closest_equilibrium_json(dr, s.released));
    }
  }
  if (!r.alexander_preserved) throw TopologyError("load: the knot type changed along the path");
  const Json j = knot_load_json(o, r, start_match, released_matches);
  Result result = result_from_json(j, "load");
  py::list snaps;
  for (size_t k = 0; k < r.snaps.size(); ++k) {
    Result s = result_from_json(j["snaps"][k], "snap");
    s.fields["loaded"] = to_array(r.snaps[k].loaded);
    s.fields["released"] = to_array(r.snaps[k].released);
    snaps.append(py::cast(std::move(s)));
  }
  result.fields["snaps"] = snaps;
  result.fields["path"] = py::cast(path_result(r.path, P.rows()));
  return result;
}

/// The trajectory's columns (those of trajectory.csv) as numpy arrays, and its frames.
Result trajectory_result(const DynamicsResult& r, Eigen::Index n) {
  const auto m = static_cast<py::ssize_t>(r.frames.size());
  py::array_t<double> time(m), kinetic(m), elastic(m), gravity(m), total(m), max_speed(m), threedim_(m);
  py::array_t<int> contacts(m), iterations(m);
  py::array_t<double> frames({m, static_cast<py::ssize_t>(n), py::ssize_t{3}});
  for (py::ssize_t k = 0; k < m; ++k) {
    const DynamicsFrame& f = r.frames[static_cast<size_t>(k)];
    time.mutable_at(k) = f.time;
    kinetic.mutable_at(k) = f.kinetic;
    elastic.mutable_at(k) = f.elastic;
    gravity.mutable_at(k) = f.gravity;
    total.mutable_at(k) = f.kinetic + f.elastic + f.gravity;
    max_speed.mutable_at(k) = f.max_speed;
    contacts.mutable_at(k) = f.contacts;
    threedim_.mutable_at(k) = threedim(f.positions);
    iterations.mutable_at(k) = f.newton_iterations;
    Eigen::Map<Points>(frames.mutable_data(k), n, 3) = f.positions;
  }
  Result t{"trajectory", py::dict()};
  t.fields["time"] = time;
  t.fields["kinetic"] = kinetic;
  t.fields["elastic"] = elastic;
  t.fields["gravity"] = gravity;
  t.fields["total"] = total;
  t.fields["max_speed"] = max_speed;
  t.fields["contacts"] = contacts;
  t.fields["threedim"] = threedim_;
  t.fields["newton_iterations"] = iterations;
  t.fields["frames"] = frames;
  return t;
}

Result dynamics_state(const py::handle& state, std::optional<double> link, double time_step, double duration,
                      double density, double damping, std::optional<std::array<double, 3>> gravity, double friction,
                      double friction_velocity, std::optional<double> envelope, double envelope_speed,
                      const py::handle& velocity, int frame_every, double rest_speed, int rest_steps,
                      std::optional<double> rest_length, const py::handle& rest_from, std::optional<std::string> dataset) {
  DynamicsOptions o;
  o.model.link = link;
  o.time_step = time_step;
  o.duration = duration;
  o.density = density;
  o.damping = damping;
  if (gravity) o.gravity = Vec3((*gravity)[0], (*gravity)[1], (*gravity)[2]);
  o.friction = friction;
  o.friction_velocity = friction_velocity;
  if (envelope) {
    o.envelope = SlabOptions();
    o.envelope->half_thickness = *envelope;
  }
  o.envelope_speed = envelope_speed;
  o.frame_every = frame_every;
  o.rest_speed = rest_speed;
  o.rest_steps = rest_steps;
  require_input(!rest_length || (*rest_length > 0.0 && std::isfinite(*rest_length)), "--rest-length must be positive");
  require_input(!rest_length || rest_from.is_none(), "give --rest-length or --rest-from, not both");
  o.validate();
  const Points P = curve_arg(state, "state");
  const Points v = velocity.is_none() ? Points() : rows3_arg(velocity, "velocity");
  const VecX rest = rest_length          ? VecX::Constant(P.rows(), *rest_length)
                    : rest_from.is_none() ? edge_lengths(P)
                                          : edge_lengths(curve_arg(rest_from, "rest_from"));
  std::optional<DatasetReader> reader;
  if (dataset) reader.emplace(*dataset);
  DynamicsResult r;
  Json end_match;
  double seconds = 0.0;
  {
    py::gil_scoped_release release;
    const Stopwatch t0;
    r = simulate(P, rest, o, v);
    seconds = t0.seconds();
    if (r.alexander_preserved) end_match = closest_equilibrium_json(reader ? &*reader : nullptr, r.positions);
  }
  if (!r.alexander_preserved) throw TopologyError("dynamics: the knot type changed");
  Result result = result_from_json(dynamics_json(o, r, end_match, seconds), "dynamics");
  result.fields["positions"] = to_array(r.positions);
  result.fields["velocities"] = to_array(r.velocities);
  result.fields["trajectory"] = py::cast(trajectory_result(r, P.rows()));
  return result;
}

}  // namespace

void bind_mechanics(py::module_& m) {
  const DynamicsOptions d;
  m.def("dynamics", &dynamics_state, py::arg("state"), py::kw_only(), py::arg("link") = py::none(),
        py::arg("time_step") = d.time_step, py::arg("duration") = d.duration, py::arg("density") = d.density,
        py::arg("damping") = d.damping, py::arg("gravity") = py::none(), py::arg("friction") = d.friction,
        py::arg("friction_velocity") = d.friction_velocity, py::arg("envelope") = py::none(),
        py::arg("envelope_speed") = d.envelope_speed, py::arg("velocity") = py::none(),
        py::arg("frame_every") = d.frame_every, py::arg("rest_speed") = d.rest_speed,
        py::arg("rest_steps") = d.rest_steps, py::arg("rest_length") = py::none(), py::arg("rest_from") = py::none(),
        py::arg("dataset") = py::none(),
        R"doc(A knot in time (docs/models.md, "Knots in time"), as `knots dynamics`: backward
Euler from the closed polygon state, (n, 3), at rest or with velocity, (n, 3), on the
relaxation's model with the wire's lumped mass (density), viscous damping, gravity (3
floats) and Coulomb friction between touching wires and against the envelope. link: the
full model with that link fixed (None: twist-free). envelope: the half-thickness H of
the plates |z| < H holding the state (None: none), moving apart at envelope_speed.
time_step, duration; frame_every: a frame every that many steps; rest_speed, rest_steps:
at rest once every vertex is slower than rest_speed for rest_steps steps (0: never).
rest_length of every edge, or rest_from, (n, 3): a curve whose edges are the rest lengths
(None: the state's own edge lengths). dataset: the end is matched to its closest
equilibrium.

Fields: the JSON keys of `knots dynamics` (model, link, time_step, ..., status,
failed_status, steps, time, rest_time, frames, newton_iterations, max_speed, max_kinetic,
start_energy, end_energy, start_threedim, end_threedim, max_threedim, dissipated,
alexander_preserved, end_match, seconds); positions and velocities, (n, 3), at the end;
trajectory: a Result of arrays, one entry per frame (the columns of trajectory.csv:
time, kinetic, elastic, gravity, total, max_speed, contacts, threedim, newton_iterations)
and frames, (frames, n, 3). A change of knot type raises TopologyError. Releases the GIL
while it computes.)doc");

  m.def("load", &load_state, py::arg("state"), py::arg("kind"), py::arg("to"), py::kw_only(),
        py::arg("vertices") = py::none(), py::arg("from_") = py::none(), py::arg("normal") = py::none(),
        py::arg("steps") = KnotLoadOptions{}.steps, py::arg("max_points") = KnotLoadOptions{}.max_points,
        py::arg("go_on") = false, py::arg("rest_length") = py::none(), py::arg("dataset") = py::none(),
        R"doc(A knot under load (docs/models.md, "Knots under load"), as `knots load`: the closed
polygon state, (n, 3), is relaxed without load, then its stable equilibria are followed
as the control moves from from_ to `to`; where the branch ends the knot snaps into
another stable state. kind: "pull" (vertices I and J pulled apart by a stiff spring;
the parameter is their distance), "plates" (two parallel plates close on the knot; the
gap) or "force" (opposite forces on I and J; the force). vertices: (I, J), 0-based, for
pull and force (None: the relaxed state's two vertices farthest apart). from_ (`from` is a
Python keyword): where the control starts (None: the relaxed state's distance of I and J,
its extent along the normal plus the plates' reach on each side, or force 0). normal:
the plates' normal, 3 floats (None: the relaxed state's axis of least extent). steps: the
first step is |to - from| / steps. max_points: points of the path at most. go_on: go on
after a snap from the state it fell into (False: stop at the first). rest_length: of
every edge (None: the state's own edge lengths). dataset: a data set file; the start and
each snap's released state are matched to its closest equilibrium (ICP).

Fields: the JSON keys of `knots load` (load, parameter, from, to, vertices, normal,
pull_stiffness, status, points, start_energy, end_energy, end_parameter, work,
dissipated, branch_jumps, alexander_preserved, start_match, snaps, seconds); each snap a Result with
point, parameter, reaction, jump, energy_drop, loaded_energy, released_status,
released_energy, released_match, and loaded and released, (n, 3): the state it fell into
under the load and that state relaxed without it. path: a Result of arrays, one entry per
point (the columns of path.csv): parameter, displacement, reaction, stiffness (NaN at the
first point and at a snap), energy, load_energy, gradient_norm, index, lowest_eigenvalue,
stable, event (a list of "regular", "snap", ...), corrector_iterations, and points,
(points, n, 3), the equilibrium at each. A path whose start did not converge has status
"stalled", no point, and end_energy and end_parameter None. A change of knot type
raises TopologyError.
Releases the GIL while it computes.)doc");
}

}  // namespace ek::python
