#include "ek/mechanics/continuation.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <limits>

#include "ek/core/errors.hpp"
#include "ek/core/stopwatch.hpp"
#include "ek/optim/eigen_analysis.hpp"
#include "ek/optim/rigid_solve.hpp"
#include "ek/optim/saddle.hpp"

namespace ek {

void ContinuationOptions::validate() const {
  require_input(std::isfinite(target), "continuation: the target must be finite");
  require_input(!step || (*step > 0.0 && std::isfinite(*step)), "continuation: the step must be positive");
  require_input(min_step_factor > 0.0 && min_step_factor < 1.0, "continuation: min_step_factor must be in (0, 1)");
  require_input(max_step_factor >= 1.0, "continuation: max_step_factor must be >= 1");
  require_input(max_points >= 1 && corrector_iterations >= 1, "continuation: max_points and corrector_iterations >= 1");
  require_input(gradient_tolerance > 0.0 && index_threshold > 0.0 && eigen_count >= 0,
                "continuation: tolerance and index threshold must be positive, eigen_count >= 0");
  require_input(max_jump > 0.0, "continuation: max_jump must be positive");
  if (minimizer) minimizer->validate();
}

std::string to_string(PathEvent e) {
  switch (e) {
    case PathEvent::Regular: return "regular";
    case PathEvent::LimitPoint: return "limit-point";
    case PathEvent::Bifurcation: return "bifurcation";
    case PathEvent::Snap: return "snap";
    case PathEvent::BranchJump: return "branch-jump";
  }
  return "?";
}

std::string to_string(PathStatus s) {
  switch (s) {
    case PathStatus::Reached: return "reached";
    case PathStatus::MaxPoints: return "max-points";
    case PathStatus::Stalled: return "stalled";
    case PathStatus::Stopped: return "stopped";
  }
  return "?";
}

// ---- the loaded knot -----------------------------------------------------------

namespace {

std::vector<Potential*> with_load(const CompositeObjective& knot, ControlledLoad& load) {
  std::vector<Potential*> terms = knot.terms();
  terms.push_back(&load);
  return terms;
}

}  // namespace

LoadedKnot::LoadedKnot(CompositeObjective& knot, ControlledLoad& load)
    : knot_(knot),
      load_(load),
      sum_({[&knot] { return knot.num_dofs(); }, [&knot] { return knot.dofs(); }, {}}, with_load(knot, load)) {
  x_ = knot_.dofs();
  load_.set_dofs(x_);
}

void LoadedKnot::set_dofs(const VecX& x) {
  x_ = x;
  sum_.set_dofs(x);
}

void LoadedKnot::set_parameter(double mu) { load_.set_parameter(mu); }

Eigen::MatrixXd LoadedKnot::rigid_modes() {
  if (!load_.plates()) return knot_.rigid_modes();
  // the plates keep the translations in their plane and the rotation about their normal
  const Points P = as_points(x_.head(x_.size() / 3 * 3));
  const Vec3 a = load_.normal(), c = P.colwise().mean().transpose();
  const Vec3 u = a.unitOrthogonal(), v = a.cross(u);
  Eigen::MatrixXd Q = Eigen::MatrixXd::Zero(num_dofs(), 3);
  for (Eigen::Index i = 0; i < P.rows(); ++i) {
    Q.block<3, 1>(3 * i, 0) = u;
    Q.block<3, 1>(3 * i, 1) = v;
    Q.block<3, 1>(3 * i, 2) = a.cross(P.row(i).transpose() - c);
  }
  Eigen::HouseholderQR<Eigen::MatrixXd> qr(Q);
  return qr.householderQ() * Eigen::MatrixXd::Identity(num_dofs(), 3);
}

// ---- path following --------------------------------------------------------------

namespace {

/// The RMS distance per vertex from the predictor xp to the landing x after
/// the best rigid motion of the first `vertices` positions (Eigen::umeyama,
/// without scaling); with no vertices, |x − xp| / √(dofs/3).
double shape_jump(const VecX& x, const VecX& xp, Eigen::Index vertices) {
  if (vertices < 3) return (x - xp).norm() / std::sqrt(std::max(1.0, static_cast<double>(x.size()) / 3.0));
  const Eigen::Map<const Eigen::Matrix3Xd> to(x.data(), 3, vertices), from(xp.data(), 3, vertices);
  const Eigen::Matrix4d T = Eigen::umeyama(to, from, false);
  const Eigen::Matrix3Xd moved = (T.topLeftCorner<3, 3>() * to).colwise() + T.topRightCorner<3, 1>();
  return std::sqrt((moved - from).squaredNorm() / static_cast<double>(vertices));
}

/// How a step's attempt ended.
enum class Landing {
  Point,       ///< a point of the branch followed
  Snap,        ///< the branch ended: its last state fell to a state of lower energy at the same control
  BranchJump,  ///< at the smallest step, a landing that is neither the branch nor a snap off it
  Retry,       ///< no landing: halve the step
};

struct Tangent {
  VecX x;
  double mu = 0.0;
};

class Tracer {
 public:
  Tracer(ParameterizedObjective& f, const ContinuationOptions& o) : f_(f), o_(o), w2_(1.0 / f.num_dofs()) {}

  /// Moves (f's dofs, μ) to (x, μ) if the state is admissible there.
  bool move(const VecX& x, double mu) {
    f_.set_parameter(mu);
    f_.set_dofs(x);
    return std::isfinite(f_.energy());
  }

  /// Newton on G = 0 and the arclength condition (or with μ fixed when
  /// `tangent` is null), from f's dofs; every step collision-free.
  bool correct(const Tangent* tangent, const VecX& xp, double mup, int& iterations) {
    for (iterations = 0; iterations < o_.corrector_iterations; ++iterations) {
      VecX x = f_.dofs();
      double mu = f_.parameter();
      const VecX G = f_.gradient();
      const double N = tangent ? w2_ * tangent->x.dot(x - xp) + tangent->mu * (mu - mup) : 0.0;
      if (G.norm() <= o_.gradient_tolerance && std::abs(N) <= 1e-12 * (1.0 + std::abs(mup))) return true;
      const RigidRegularizedSolver H(f_);  // the exact Hessian, rigid directions regularised
      if (!H.ok()) return false;
      VecX dx = H.solve(-G);
      double dmu = 0.0;
      if (tangent) {
        const VecX b = H.solve(-f_.parameter_gradient());
        dmu = -(N + w2_ * tangent->x.dot(dx)) / (w2_ * tangent->x.dot(b) + tangent->mu);
        dx += dmu * b;
      }
      if (!step(x, mu, dx, dmu, G.norm())) return false;
    }
    return f_.gradient().norm() <= o_.gradient_tolerance;
  }

  /// The stable path's corrector: E(·; μ) minimised from f's dofs (μ fixed).
  /// Its distance from `xp` in `jump`: |Δx| / √(dofs/3), the RMS vertex
  /// distance when the dofs are vertices (|Δx| for fewer than 3 dofs).
  bool minimize(const VecX& xp, int& iterations, double& jump) {
    NewtonSolver solver(*o_.minimizer);
    const NewtonReport r = solver.minimize(f_);
    iterations = r.iterations;
    jump = shape_jump(f_.dofs(), xp, f_.rigid_vertices());
    return r.status == SolverStatus::ConvergedStable;
  }

  /// The stable path's step to μ_p. E(·; μ_p) is minimised from the
  /// predictor xp; that landing is a point of the branch when it lies within
  /// max_jump of xp and not above E(x_k; μ_p), the energy of the branch's
  /// last state at the new control (along a stable branch the minimum at μ_p
  /// lies below it). Otherwise (near a fold or a bifurcation dx/dμ grows and
  /// the predictor can cross into another basin) it is minimised again from
  /// x_k itself: within max_jump of x_k, the branch goes on; farther, at the
  /// smallest step, the knot snaps, releasing `drop` = E(x_k; μ_p) −
  /// E(x; μ_p) > 0 at the same control, if the branch has ended: x_k and
  /// the landing are two stable states at μ_k (bistable()); otherwise the
  /// branch only moved fast and the landing is its next point. A landing that
  /// releases nothing, or an x_k the load no longer admits at μ_p (e.g.
  /// outside the closing plates) with a far landing, is a branch jump;
  /// above the smallest step both retry with a smaller one.
  Landing land(const VecX& xk, double muk, const VecX& xp, double mup, bool smallest, int& iterations, double& drop) {
    const bool admitted = move(xk, mup);
    const double e_branch = admitted ? f_.energy() : std::numeric_limits<double>::infinity();
    const double slack = 1e-10 * std::max(1.0, std::abs(e_branch));
    double jump = 0.0;
    if (f_.max_step(xk, xp - xk) >= 1.0 && move(xp, mup)) {
      f_.accept();
      const bool converged = minimize(xp, iterations, jump);
      if (converged && jump <= o_.max_jump && !(f_.energy() > e_branch + slack)) return Landing::Point;
      if (converged && !admitted && smallest) return Landing::BranchJump;
    }
    if (!admitted) return Landing::Retry;
    move(xk, mup);
    f_.accept();
    if (!minimize(xk, iterations, jump)) return Landing::Retry;
    if (jump <= o_.max_jump) return Landing::Point;
    if (!smallest) return Landing::Retry;
    drop = e_branch - f_.energy();
    if (!(drop > slack)) return Landing::BranchJump;
    return bistable(xk, muk, mup) ? Landing::Snap : Landing::Point;
  }

  /// Whether f's landing x at μ_p and x_k are two stable states at μ_k: x
  /// minimised back at μ_k does not return within max_jump of x_k. A branch
  /// that only moves fast along a soft mode (dx/dμ large where the lowest
  /// eigenvalue is small but the branch goes on, as contacts slide) returns;
  /// a branch that ended between μ_k and μ_p does not. Leaves f at (x, μ_p).
  bool bistable(const VecX& xk, double muk, double mup) {
    const VecX x = f_.dofs();
    int iterations = 0;
    double back = 0.0;
    bool returned = move(x, muk);
    if (returned) {
      f_.accept();
      returned = minimize(xk, iterations, back) && back <= o_.max_jump;
    }
    move(x, mup);
    f_.accept();
    return !returned;
  }

  /// The unit tangent at f's point, oriented along `previous` (or towards increasing μ).
  std::optional<Tangent> tangent(const Tangent* previous) {
    const RigidRegularizedSolver H(f_);  // the exact Hessian, rigid directions regularised
    if (!H.ok()) return std::nullopt;
    Tangent t{H.solve(-f_.parameter_gradient()), 1.0};
    const double norm = std::sqrt(w2_ * t.x.squaredNorm() + 1.0);
    t.x /= norm;
    t.mu /= norm;
    const double along = previous ? w2_ * t.x.dot(previous->x) + t.mu * previous->mu : t.mu;
    if (along < 0.0) {
      t.x = -t.x;
      t.mu = -t.mu;
    }
    return t;
  }

  /// The point's measures, stability included.
  PathPoint measure(int iterations) {
    PathPoint p;
    p.dofs = f_.dofs();
    p.parameter = f_.parameter();
    p.energy = f_.energy();
    p.gradient_norm = f_.gradient().norm();
    p.parameter_derivative = f_.parameter_derivative();
    p.corrector_iterations = iterations;
    p.displacement = f_.displacement();
    p.reaction = f_.reaction();
    p.load_energy = f_.load_energy();
    if (o_.eigen_count > 0) stability(p);
    return p;
  }

 private:
  /// x + t·dx, μ + t·dμ with t the collision-free fraction, halved until
  /// the state is admissible (e.g. between the plates) and ||G|| decreases
  /// (||G(t)|| <= (1 − 10⁻⁴ t)·||G(0)||, a merit line search: a full Newton
  /// step along a soft sliding mode can overshoot into the contact barrier).
  bool step(const VecX& x, double mu, const VecX& dx, double dmu, double g0) {
    for (double t = std::min(1.0, f_.max_step(x, dx)); t > 1e-6; t *= 0.5) {
      if (move(x + t * dx, mu + t * dmu) && f_.gradient().norm() <= (1.0 - 1e-4 * t) * g0) {
        f_.accept();
        return true;
      }
    }
    move(x, mu);
    return false;
  }

  void stability(PathPoint& p) {
    SparseAssembler A;
    f_.assemble_hessian(A, HessianKind::Exact);
    const Eigen::MatrixXd Q = f_.rigid_modes();
    const int count = std::min(o_.eigen_count, max_modes(f_.num_dofs(), static_cast<int>(Q.cols())));
    const LowestModes m = lowest_modes(A.matrix(), Q, count, -o_.index_threshold, o_.index_threshold);
    if (!m.converged) return;
    p.lowest_eigenvalue = m.values(0);
    p.lowest_mode = m.vectors.col(0);
    p.index = static_cast<int>((m.values.array() < -o_.index_threshold).count());
    p.stable = p.index == 0;
  }

  ParameterizedObjective& f_;
  const ContinuationOptions& o_;
  double w2_;
};

/// A predictor step: the point (x, μ) predicted, its length h (the step
/// that was halved on failure) and whether it lands on the target.
struct Step {
  VecX x;
  double mu = 0.0;
  double h = 0.0;
  bool last = false;
};

/// Pseudo-arclength predictor: h = Δs along the unit tangent, or the step
/// that lands on the target when that is shorter.
Step arclength_step(const Tangent& t, const VecX& xk, double muk, double ds, double target) {
  const bool towards = (target - muk) * t.mu > 0.0;
  Step s;
  s.last = towards && std::abs(ds * t.mu) >= std::abs(target - muk);
  s.h = s.last ? (target - muk) / t.mu : ds;
  s.x = xk + s.h * t.x;
  s.mu = s.last ? target : muk + s.h * t.mu;
  return s;
}

/// Stable-path predictor: a stable branch is a graph over μ (H positive
/// definite), so μ moves by Δs towards the target and x by Δμ·dx/dμ, with
/// dx/dμ = −H⁻¹ ∂g/∂μ = t.x / t.mu (independent of the tangent's
/// orientation); near a fold, where dx/dμ grows, the CCD's safe step and the
/// minimizer's jump halve Δs.
Step stable_step(const Tangent& t, const VecX& xk, double muk, double ds, const ContinuationOptions& o) {
  Step s;
  s.last = std::abs(o.target - muk) <= ds;
  s.h = s.last ? std::abs(o.target - muk) : ds;
  s.mu = s.last ? o.target : muk + std::copysign(ds, o.target - muk);
  s.x = xk + (t.x / t.mu) * (s.mu - muk);
  return s;
}

}  // namespace

LoadPath follow_path(ParameterizedObjective& f, const ContinuationOptions& o,
                     const std::function<bool(const PathPoint&)>& on_point) {
  o.validate();
  const Stopwatch t0;
  LoadPath path;
  Tracer tr(f, o);
  const double mu0 = f.parameter();
  const double first = o.step.value_or(std::max(std::abs(o.target - mu0), 1e-12) / 40.0);
  const auto finish = [&](PathStatus s) {
    path.status = s;
    path.seconds = t0.seconds();
    return path;
  };
  const auto record = [&](PathPoint p) {  // false: the caller stops the path
    path.points.push_back(p);
    return !on_point || on_point(path.points.back());
  };
  int its = 0;
  if (!tr.move(f.dofs(), mu0) || !tr.correct(nullptr, f.dofs(), mu0, its)) return finish(PathStatus::Stalled);
  std::optional<Tangent> t = tr.tangent(nullptr);
  if (!t) return finish(PathStatus::Stalled);
  if ((o.target - mu0) * t->mu < 0.0) {
    t->x = -t->x;
    t->mu = -t->mu;
  }
  PathPoint p = tr.measure(its);
  p.tangent_parameter = t->mu;
  if (!record(p)) return finish(PathStatus::Stopped);
  double ds = first;
  while (static_cast<int>(path.points.size()) < o.max_points) {
    const VecX xk = path.points.back().dofs;
    const double muk = path.points.back().parameter;
    // the last step lands on the target with μ fixed there
    const Step st = o.minimizer ? stable_step(*t, xk, muk, ds, o) : arclength_step(*t, xk, muk, ds, o.target);
    const bool last = st.last;
    const double h = st.h;
    const VecX& xp = st.x;
    const double mup = st.mu;
    const bool smallest = std::min(ds, h) * 0.5 < o.min_step_factor * first;
    Landing landing = Landing::Retry;
    double drop = 0.0;
    if (o.minimizer) {
      landing = tr.land(xk, muk, xp, mup, smallest, its, drop);
    } else if (f.max_step(xk, xp - xk) >= 1.0 && tr.move(xp, mup)) {
      f.accept();
      if (tr.correct(last ? nullptr : &*t, xp, mup, its)) landing = Landing::Point;
    }
    if (landing == Landing::Retry) {
      tr.move(xk, muk);
      f.accept();
      ds = std::min(ds, h) * 0.5;
      if (ds < o.min_step_factor * first) return finish(PathStatus::Stalled);
      continue;
    }
    const bool snapped = landing == Landing::Snap;
    const std::optional<Tangent> next = tr.tangent(&*t);
    if (!next) return finish(PathStatus::Stalled);
    PathPoint q = tr.measure(its);
    q.tangent_parameter = next->mu;
    q.energy_drop = drop;
    const PathPoint& prev = path.points.back();
    if (snapped) q.event = PathEvent::Snap;
    else if (landing == Landing::BranchJump) q.event = PathEvent::BranchJump;
    else if (!o.minimizer && next->mu * t->mu < 0.0) q.event = PathEvent::LimitPoint;
    else if (q.index >= 0 && prev.index >= 0 && q.index != prev.index) q.event = PathEvent::Bifurcation;
    if (!record(q)) return finish(PathStatus::Stopped);
    t = next;
    if (last) return finish(PathStatus::Reached);
    if (snapped || landing == Landing::BranchJump) ds = first;
    else if (its <= (o.minimizer ? 8 : 3)) ds = std::min(ds * 1.5, o.max_step_factor * first);
  }
  return finish(PathStatus::MaxPoints);
}

}  // namespace ek
