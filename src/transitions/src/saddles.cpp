#include "ek/transitions/saddles.hpp"

#include <cmath>

#include "ek/core/errors.hpp"
#include "ek/core/stopwatch.hpp"
#include "ek/geometry/polyline.hpp"
#include "ek/knots/alexander.hpp"
#include "saddle_checks.hpp"

namespace ek {

namespace detail {

RelaxOptions direct(const KnotSaddleOptions& o) { return with_method(o.relax, "hybrid"); }

AlexanderPolynomial alexander_or_zero(const Points& x) {
  try {
    return alexander(x);
  } catch (const InputError&) {
    return AlexanderPolynomial{{0}};
  }
}

}  // namespace detail

namespace {

using detail::alexander_or_zero;
using detail::direct;

/// Halvings of the displacement from the saddle before a descent is given up.
constexpr int kMaxHalvings = 30;

/// At most `count` images evenly spaced by path length (first and last kept).
void thin_images(Descent& d, int count) {
  const size_t m = d.images.size();
  if (static_cast<int>(m) <= count) return;
  std::vector<double> s(m, 0.0);
  for (size_t k = 1; k < m; ++k) s[k] = s[k - 1] + (d.images[k] - d.images[k - 1]).norm();
  std::vector<VecX> images;
  std::vector<double> energies;
  size_t k = 0;
  for (int j = 0; j < count; ++j) {
    const double target = s.back() * j / (count - 1);
    while (k + 1 < m && s[k] < target) ++k;
    if (!images.empty() && images.back() == d.images[k]) continue;
    images.push_back(d.images[k]);
    energies.push_back(d.energies[k]);
  }
  d.images = std::move(images);
  d.energies = std::move(energies);
}

/// Lk at the rod's current state; true when no link is prescribed or it is
/// within the tolerance.
bool link_holds(RodModel& sys, const KnotSaddleOptions& o, double& link) {
  if (!o.relax.link) return true;
  link = sys.rod().link();
  return std::abs(link - *o.relax.link) <= o.link_tolerance;
}

/// f's dofs set to x_s + δ·step, δ halved from the largest step the CCD
/// allows until E is below the saddle's `saddle_energy` (up to kMaxHalvings
/// times); false when it never is. A linear step along a bending mode
/// stretches the edges at second order (energy ~ δ⁴ against ½λδ²).
bool displace_below(Objective& f, const VecX& xs, double saddle_energy, const VecX& step) {
  VecX d = step * f.max_step(xs, step);
  for (int j = 0; j < kMaxHalvings; ++j, d *= 0.5) {
    f.set_dofs(xs + d);
    if (f.energy() < saddle_energy) break;
  }
  return f.energy() < saddle_energy;
}

/// Newton from x_s + δ·v (item 3 of saddles.hpp's file comment). The system
/// is built at x_s's positions (θ relaxed there when the model has θ: at an
/// equilibrium θ minimises the twisting energy); `step` is a direction, whose
/// θ part does not depend on the reference frames.
SaddleMinimum descend_from(const AlexanderPolynomial& alexander, const VecX& rest, const KnotSaddleOptions& o,
                           const Points& saddle, const VecX& step) {
  RodModel sys(saddle, rest, direct(o));
  Objective& f = sys.objective();
  const VecX xs = f.dofs();
  const double saddle_energy = f.energy();
  SaddleMinimum m;
  if (!displace_below(f, xs, saddle_energy, step)) {
    m.status = DescentStatus::NotBelowSaddle;
    return m;
  }
  f.accept();
  Descent descent = descend(f, sys.newton());
  m.link_preserved = link_holds(sys, o, m.link);
  descent.images.insert(descent.images.begin(), xs);
  descent.energies.insert(descent.energies.begin(), saddle_energy);
  m.status = descent_status(descent.report.status);
  m.iterations = descent.report.iterations;
  m.gradient_norm = descent.report.gradient_norm;
  m.energy = descent.energies.back();
  thin_images(descent, o.max_images);
  for (const VecX& x : descent.images) {
    m.images.push_back(sys.positions(x));
    if (alexander_or_zero(m.images.back()) != alexander) m.alexander_preserved = false;
  }
  m.energies = descent.energies;
  m.positions = m.images.back();
  if (!m.alexander_preserved || !m.link_preserved) m.status = DescentStatus::TopologyChanged;
  return m;
}

}  // namespace

namespace detail {

std::optional<SearchStatus> descend_saddle(const AlexanderPolynomial& alexander, const VecX& rest,
                                           const KnotSaddleOptions& o, RodModel& sys, const VecX& xs,
                                           SaddleRecord& r) {
  Objective& f = sys.objective();
  f.set_dofs(xs);
  const double threshold = sys.newton().shift_epsilon * sys.lambda_min();
  const HessianIndex idx = hessian_index(f, 2, threshold);
  if (!idx.converged) return SearchOutcome::DegenerateHessian;
  r.index = idx.negative;
  r.negative_eigenvalue = idx.values(0);
  r.second_eigenvalue = idx.values.size() > 1 ? idx.values(1) : 0.0;
  if (idx.near_zero > 0) return SearchOutcome::DegenerateHessian;
  if (idx.negative != 1) return SearchStatus::with_index(idx.negative);
  const VecX v = idx.vectors.col(0);
  const VecX step = v * (o.displacement / v.head(3 * rest.size()).cwiseAbs().maxCoeff());
  const bool link_ok = link_holds(sys, o, r.link);
  const Points saddle = sys.positions(xs);
  r.minima = {descend_from(alexander, rest, o, saddle, step), descend_from(alexander, rest, o, saddle, -step)};
  const SaddleMinimum& a = r.minima[0];
  const SaddleMinimum& b = r.minima[1];
  if (!link_ok || !a.alexander_preserved || !b.alexander_preserved || !a.link_preserved || !b.link_preserved)
    return SearchOutcome::TopologyChanged;
  if (a.status != DescentStatus::ConvergedStable || b.status != DescentStatus::ConvergedStable)
    return SearchOutcome::DescentFailed;
  return std::nullopt;
}

SaddleSearchResult search_into(RodModel& sys, const VecX& direction, SaddleSearchOptions search, double max_rise,
                               SaddleRecord& r) {
  search.gradient_tolerance = sys.tolerance();
  search.base_shift = sys.newton().shift_epsilon * sys.lambda_min();
  search.max_energy_rise = max_rise;
  const SaddleSearchResult s = search_saddle(sys.objective(), direction, search);
  if (s.status != SaddleStatus::Converged) r.status = search_outcome(s.status);
  r.energy = s.energy;
  r.gradient_norm = s.gradient_norm;
  r.negative_eigenvalue = s.eigenvalue;
  r.iterations = s.iterations;
  r.rejected = s.rejected;
  r.saddle = sys.positions(s.x);
  return s;
}

}  // namespace detail

namespace {

/// Items 2-4 of the file comment for a converged search at x_s.
void check_saddle(const SaddleStart& start, const VecX& rest, const KnotSaddleOptions& o, RodModel& sys,
                  const VecX& xs, const CurveSimilarity& similarity, SaddleRecord& r) {
  const std::optional<SearchStatus> failed = detail::descend_saddle(start.alexander, rest, o, sys, xs, r);
  for (SaddleMinimum& m : r.minima)
    if (!m.images.empty()) m.start_similarity = similarity(m.positions, start.positions);
  SaddleMinimum& a = r.minima[0];
  SaddleMinimum& b = r.minima[1];
  const auto is_start = [&](const SaddleMinimum& m) {
    return m.start_similarity >= o.start_similarity &&
           std::abs(m.energy - start.energy) <= o.start_energy_tolerance * std::abs(start.energy);
  };
  if (is_start(b) > is_start(a) || (is_start(b) == is_start(a) && b.start_similarity > a.start_similarity))
    std::swap(a, b);
  if (failed) r.status = *failed;
  else if (!is_start(a)) r.status = SearchOutcome::StartNotReached;
  else if (is_start(b)) r.status = SearchOutcome::ReturnsToStart;
  else r.status = SearchOutcome::Verified;
  r.verified = r.status.verified();
}

/// One search from the start along `direction` (dofs) and its checks. The
/// system is built at the start's positions (θ relaxed: the start's θ up to
/// the tolerance, in this system's reference frames).
SaddleRecord search_one(const SaddleStart& start, const VecX& rest, const KnotSaddleOptions& o,
                        const VecX& direction, const CurveSimilarity& similarity) {
  const Stopwatch t0;
  RodModel sys(start.positions, rest, direct(o));
  SaddleRecord r;
  const SaddleSearchResult s = detail::search_into(sys, direction, o.search, o.max_rise_factor * start.energy, r);
  if (s.status == SaddleStatus::Converged) check_saddle(start, rest, o, sys, s.x, similarity, r);
  r.seconds = t0.seconds();
  return r;
}

}  // namespace

void KnotSaddleOptions::validate() const {
  relax.validate();
  require_input(!relax.slab, "saddles: the planarity slab is not supported");
  require_input(modes >= 1 && modes <= 32, "saddles: modes must be in [1, 32]");
  require_input(max_rise_factor > 0.0 && std::isfinite(max_rise_factor), "saddles: max_rise_factor must be positive");
  require_input(displacement > 0.0 && displacement < 1.0, "saddles: displacement must be in (0, 1)");
  require_input(start_similarity > 0.0 && start_similarity <= 1.0, "saddles: start_similarity must be in (0, 1]");
  require_input(start_energy_tolerance > 0.0 && start_energy_tolerance < 1.0,
                "saddles: start_energy_tolerance must be in (0, 1)");
  require_input(max_images >= 2, "saddles: max_images must be >= 2");
  require_input(start_gradient_factor >= 1.0, "saddles: start_gradient_factor must be >= 1");
  require_input(link_tolerance > 0.0 && link_tolerance < 1.0, "saddles: link_tolerance must be in (0, 1)");
}

PointCheck check_point(const Points& x, const VecX& rest, const RelaxOptions& model, int count) {
  require_input(!model.slab, "check_point: the planarity slab is not part of the saddles' model");
  RodModel sys(x, rest, with_method(model, "hybrid"));
  Objective& f = sys.objective();
  PointCheck c;
  c.gradient_norm = f.gradient().norm();
  c.tolerance = sys.tolerance();
  c.threshold = sys.newton().shift_epsilon * sys.lambda_min();
  c.energy = f.energy();
  c.index = hessian_index(f, count, c.threshold);
  return c;
}

SaddleStart prepare_start(const Points& state, const VecX& rest, const KnotSaddleOptions& o) {
  o.validate();
  RodModel sys(state, rest, direct(o));
  Objective& f = sys.objective();
  SaddleStart s;
  s.tolerance = sys.tolerance();
  s.lambda_min = sys.lambda_min();
  s.input_gradient_norm = f.gradient().norm();
  require_input(s.input_gradient_norm <= o.start_gradient_factor * s.tolerance,
                "the start is not an equilibrium: gradient norm " + std::to_string(s.input_gradient_norm) +
                    " at these rest lengths (relax it first, or give its rest length)");
  const double base = sys.newton().shift_epsilon * sys.lambda_min();
  const HessianIndex before = hessian_index(f, 2, base);  // Newton would leave a saddle for a minimum
  require_input(before.converged, "the start's lowest eigenpairs did not converge");
  require_input(before.negative == 0,
                "the start is not a stable equilibrium: " + std::to_string(before.negative) +
                    " negative eigenvalue(s) of its Hessian (lowest " + std::to_string(before.values(0)) + ")");
  const Descent polish = descend(f, sys.newton());
  require_input(polish.report.status == SolverStatus::ConvergedStable && !polish.report.marginal,
                "the start is not a stable equilibrium (Newton from it ends " + to_string(polish.report.status) +
                    (polish.report.marginal ? ", marginal" : "") + ")");
  s.dofs = f.dofs();
  s.positions = sys.positions(s.dofs);
  s.energy = f.energy();
  s.gradient_norm = f.gradient().norm();
  s.alexander = alexander(s.positions);
  SparseAssembler A;
  f.assemble_hessian(A, HessianKind::Exact);
  const Eigen::MatrixXd Q = f.rigid_modes();
  const int modes = std::min(o.modes, max_modes(f.num_dofs(), static_cast<int>(Q.cols())));
  const LowestModes m = lowest_modes(A.matrix(), Q, modes, -base, base, o.search.eigen_tolerance);
  require_input(m.converged, "the start's lowest eigenpairs did not converge");
  require_input(m.values(0) > base, "the start is not a stable equilibrium: its lowest non-rigid eigenvalue is " +
                                        std::to_string(m.values(0)));
  s.mode_eigenvalues = m.values;
  s.modes = m.vectors;
  s.energy_scale = sys.rod().material().bending_stiffness() / rest.sum();
  return s;
}

std::vector<SaddleRecord> find_knot_saddles(const SaddleStart& start, const VecX& rest, const KnotSaddleOptions& o,
                                            const CurveSimilarity& similarity, const SaddleProgress& progress) {
  o.validate();
  require(static_cast<bool>(similarity), "find_knot_saddles: a similarity function is needed");
  const int modes = static_cast<int>(start.modes.cols());
  std::vector<SaddleRecord> records;
  const int total = 2 * modes;
  for (int k = 0; k < modes; ++k) {
    for (const int sign : {1, -1}) {
      KnotSaddleOptions ok = o;
      ok.search.eigen_count = std::max(o.search.eigen_count, k + 2);
      SaddleRecord r = search_one(start, rest, ok, sign * start.modes.col(k), similarity);
      r.mode = k;
      r.direction = sign;
      for (size_t j = 0; j < records.size() && r.verified; ++j) {
        const SaddleRecord& e = records[j];
        if (e.verified && e.duplicate_of < 0 && std::abs(e.energy - r.energy) <= 1e-9 * std::abs(e.energy) &&
            similarity(e.saddle, r.saddle) >= 0.99)
          r.duplicate_of = static_cast<int>(j);
      }
      records.push_back(std::move(r));
      if (progress) progress(static_cast<int>(records.size()), total);
    }
  }
  return records;
}

std::vector<Points> saddle_path(const SaddleRecord& r, std::vector<double>& energies, int& saddle_image) {
  require(r.verified, "saddle_path: the record is not a verified saddle");
  std::vector<Points> path;
  energies.clear();
  const SaddleMinimum& a = r.minima[0];
  const SaddleMinimum& b = r.minima[1];
  for (size_t k = a.images.size(); k-- > 0;) {
    path.push_back(a.images[k]);
    energies.push_back(a.energies[k]);
  }
  saddle_image = static_cast<int>(path.size()) - 1;
  for (size_t k = 1; k < b.images.size(); ++k) {
    path.push_back(b.images[k]);
    energies.push_back(b.energies[k]);
  }
  return path;
}

}  // namespace ek
