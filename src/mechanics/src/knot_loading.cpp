#include "ek/mechanics/knot_loading.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "ek/core/errors.hpp"
#include "ek/geometry/polyline.hpp"
#include "ek/knots/alexander.hpp"
#include "ek/optim/saddle.hpp"
#include "ek/solver/rod_model.hpp"

namespace ek {

std::string to_string(LoadKind kind) {
  switch (kind) {
    case LoadKind::Pull: return "pull";
    case LoadKind::Plates: return "plates";
    case LoadKind::Force: return "force";
  }
  return "?";
}

LoadKind parse_load_kind(const std::string& text) {
  if (text == "pull") return LoadKind::Pull;
  if (text == "plates") return LoadKind::Plates;
  if (text == "force") return LoadKind::Force;
  throw InputError("unknown load '" + text + "' (expected pull, plates or force)");
}

void KnotLoadOptions::validate() const {
  relax.validate();
  require_input(!relax.link && !relax.full_model && !relax.slab,
                "load: only the twist-free model (no link, no full model, no slab)");
  if (vertices)
    require_input((*vertices)[0] >= 0 && (*vertices)[1] >= 0 && (*vertices)[0] != (*vertices)[1],
                  "load: a pull or force needs two distinct vertices");
  require_input(std::isfinite(to) && (!from || std::isfinite(*from)), "load: the parameter's ends must be finite");
  require_input(!normal || (normal->allFinite() && normal->norm() > 0.0), "load: the plates' normal must be nonzero");
  require_input(pull_stiffness > 0.0 && plates_reach > 0.0 && plates_stiffness > 0.0,
                "load: the pull's stiffness and the plates' reach and stiffness must be positive");
  require_input(steps >= 1 && max_points >= 2 && eigen_count >= 0, "load: steps >= 1, max_points >= 2 required");
  require_input(snap_jump > 0.0 && std::isfinite(snap_jump), "load: snap_jump must be positive");
  // A device that would press the wire thinner than it is, or pull two
  // points to a negative distance, describes no physical load.
  const double thickness = 2.0 * relax.material.radius;
  std::ostringstream t;
  t << thickness;
  if (kind == LoadKind::Plates)
    require_input(to >= thickness && (!from || *from >= thickness),
                  "load: the plates' gap must be at least the wire's thickness 2r = " + t.str());
  if (kind == LoadKind::Pull)
    require_input(to > 0.0 && (!from || *from > 0.0), "load: the pulled points' distance must be positive");
}

namespace {

/// The load of `o` on the relaxed start `X` (its parameter set to `from`).
std::unique_ptr<ControlledLoad> make_load(const Points& X, const VecX& rest, const KnotLoadOptions& o,
                                          KnotLoadResult& out, double& from) {
  const int n = static_cast<int>(X.rows());
  const double ell = rest.mean();
  if (o.kind != LoadKind::Plates) {
    out.vertices = o.vertices.value_or(diameter_pair(X));
    require_input(std::max(out.vertices[0], out.vertices[1]) < n,
                  "load: a vertex index is beyond the curve's " + std::to_string(n) + " vertices");
  }
  const auto [i, j] = out.vertices;
  if (o.kind == LoadKind::Pull) {
    out.pull_stiffness = o.pull_stiffness * o.relax.material.bending_stiffness() / (ell * ell * ell);
    from = o.from.value_or((X.row(i) - X.row(j)).norm());
    return std::make_unique<PullLoad>(i, j, from, out.pull_stiffness);
  }
  if (o.kind == LoadKind::Force) {
    from = o.from.value_or(0.0);
    return std::make_unique<ForceLoad>(i, j, from);
  }
  out.normal = o.normal ? o.normal->normalized() : principal_axes(X).col(0);  // the start's axis of least extent
  // centred on the knot's extent along the normal, so that by default both plates touch it at the start
  const Vec3 centroid = X.colwise().mean().transpose();
  const VecX s = (X.rowwise() - centroid.transpose()) * out.normal;
  const Vec3 c = centroid + 0.5 * (s.maxCoeff() + s.minCoeff()) * out.normal;
  const double extent = 0.5 * (s.maxCoeff() - s.minCoeff());
  const ResolvedModel model = resolve_model(o.relax, ell);
  const double reach = o.plates_reach * o.relax.material.radius;
  from = o.from.value_or(2.0 * (extent + reach));
  auto plates = std::make_unique<PlatesLoad>(c, out.normal, from, reach, o.plates_stiffness * model.contact_stiffness);
  plates->set_dofs(as_vector(X));
  require_input(plates->inside(from), "load: the curve is not strictly between the plates at gap " + std::to_string(from));
  return plates;
}

/// The snap at path point `k` (PathEvent::Snap): the jump from point k − 1,
/// the last of the branch that ended, to the stable state k, and that state
/// relaxed without the load.
Snap snap_at(int k, const LoadPath& path, const RodModel& sys, const VecX& rest, const KnotLoadOptions& o,
             const AlexanderPolynomial& alexander0) {
  const PathPoint& before = path.points[static_cast<size_t>(k) - 1];
  const PathPoint& p = path.points[static_cast<size_t>(k)];
  Snap s;
  s.point = k;
  s.parameter = before.parameter;
  s.reaction = before.reaction;
  s.loaded = sys.positions(p.dofs);
  s.loaded_energy = p.energy;
  s.energy_drop = p.energy_drop;
  s.jump = std::sqrt((s.loaded - sys.positions(before.dofs)).rowwise().squaredNorm().mean());
  RelaxOptions ro = o.relax;
  ro.rest_lengths = rest;
  const RelaxResult released = relax(s.loaded, ro);
  s.released = released.positions;
  s.released_status = released.status();
  s.released_energy = released.energy.total;
  s.alexander_preserved = alexander(s.loaded) == alexander0 && released.alexander_preserved;
  return s;
}

}  // namespace

std::array<int, 2> diameter_pair(const Points& X) {
  std::array<int, 2> best{0, 1};
  double d2 = -1.0;
  for (Eigen::Index a = 0; a < X.rows(); ++a)
    for (Eigen::Index b = a + 1; b < X.rows(); ++b)
      if (const double d = (X.row(a) - X.row(b)).squaredNorm(); d > d2) {
        d2 = d;
        best = {static_cast<int>(a), static_cast<int>(b)};
      }
  return best;
}

std::optional<double> secant_stiffness(const LoadPath& path, size_t k) {
  const auto& pts = path.points;
  if (k == 0 || k >= pts.size()) return std::nullopt;
  const PathPoint &p = pts[k], &q = pts[k - 1];
  if (p.event == PathEvent::Snap || p.event == PathEvent::BranchJump || p.displacement == q.displacement)
    return std::nullopt;
  return (p.reaction - q.reaction) / (p.displacement - q.displacement);
}

double path_work(const LoadPath& path, size_t end) {
  const auto& pts = path.points;
  double work = 0.0;
  for (size_t k = 1; k < std::min(end, pts.size()); ++k)
    if (pts[k].event != PathEvent::Snap && pts[k].event != PathEvent::BranchJump)
      work += 0.5 * (pts[k - 1].parameter_derivative + pts[k].parameter_derivative) *
              (pts[k].parameter - pts[k - 1].parameter);
  return work;
}

KnotLoadResult load_knot(const Points& start, const VecX& rest, const KnotLoadOptions& o) {
  o.validate();
  RelaxOptions ro = o.relax;
  ro.rest_lengths = rest;
  KnotLoadResult out;
  Points x0 = start;
  if (o.relax_start) {
    const RelaxResult relaxed = relax(start, ro);
    out.start_energy = relaxed.energy.total;
    x0 = relaxed.positions;
  }
  const AlexanderPolynomial alexander0 = alexander(x0);
  RodModel sys(x0, rest, o.relax);
  if (!o.relax_start) out.start_energy = sys.objective().energy();
  double from = 0.0;
  const std::unique_ptr<ControlledLoad> load = make_load(x0, rest, o, out, from);
  out.parameter_name = load->parameter_name();
  out.from = from;
  LoadedKnot f(sys.objective(), *load);
  f.set_parameter(from);
  ContinuationOptions co;
  co.target = o.to;
  co.step = std::max(std::abs(o.to - from), 1e-12) / o.steps;
  co.max_points = o.max_points;
  co.gradient_tolerance = sys.tolerance();
  co.eigen_count = o.eigen_count;
  co.index_threshold = 1e3 * sys.newton().shift_epsilon * sys.lambda_min();
  co.minimizer = sys.newton();
  co.max_jump = o.snap_jump * rest.mean();
  out.path = follow_path(f, co, [&](const PathPoint& p) {
    if (alexander(sys.positions(p.dofs)) != alexander0) out.alexander_preserved = false;
    return !(p.event == PathEvent::Snap && o.stop_at_snap);
  });
  const auto& pts = out.path.points;
  for (size_t k = 1; k < pts.size(); ++k) {
    out.branch_jumps += pts[k].event == PathEvent::BranchJump;
    if (pts[k].event != PathEvent::Snap) continue;
    out.snaps.push_back(snap_at(static_cast<int>(k), out.path, sys, rest, o, alexander0));
    out.dissipated += out.snaps.back().energy_drop;
    if (!out.snaps.back().alexander_preserved) out.alexander_preserved = false;
  }
  out.work = path_work(out.path, pts.size());
  return out;
}

}  // namespace ek
