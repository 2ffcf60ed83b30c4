#include "ek/solver/symmetric.hpp"

#include "ek/core/errors.hpp"
#include "ek/core/stopwatch.hpp"
#include "ek/knots/alexander.hpp"
#include "ek/optim/rigid_solve.hpp"
#include "ek/optim/saddle.hpp"
#include "ek/solver/rod_model.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numeric>
#include <stdexcept>
#include <string>

namespace ek {

namespace {

void check_divisible(Eigen::Index n, int p) {
  if (p < 2) throw std::invalid_argument("cyclic symmetry: the order must be at least 2, got " + std::to_string(p));
  if (n < p || n % p != 0)
    throw std::invalid_argument("cyclic symmetry: " + std::to_string(n) + " vertices are not divisible by " +
                                std::to_string(p));
}

}  // namespace

Mat3 CyclicSymmetry::rotation(int t) const { return Eigen::AngleAxisd(t * angle, axis.normalized()).toRotationMatrix(); }

double cyclic_symmetry_residual(const Points& P, const CyclicSymmetry& s) {
  check_divisible(P.rows(), s.order);
  const Eigen::Index n = P.rows(), m = n / s.order;
  const Mat3 R = s.rotation(1);
  double sum = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const Vec3 x = P.row(i).transpose(), y = P.row((i + m) % n).transpose();
    sum += (y - s.center - R * (x - s.center)).squaredNorm();
  }
  return std::sqrt(sum / static_cast<double>(n));
}

CyclicSymmetry fit_cyclic_symmetry(const Points& P, int p, const Vec3& center, const Vec3& axis) {
  check_divisible(P.rows(), p);
  CyclicSymmetry best;
  double best_residual = INFINITY;
  for (int k = 1; k < p; ++k) {
    if (std::gcd(k, p) != 1) continue;
    const CyclicSymmetry s{p, center, axis.normalized(), 2.0 * M_PI * k / p};
    const double r = cyclic_symmetry_residual(P, s);
    if (r < best_residual) {
      best_residual = r;
      best = s;
    }
  }
  return best;
}

Points project_symmetric(const Points& P, const CyclicSymmetry& s) {
  check_divisible(P.rows(), s.order);
  const Eigen::Index n = P.rows(), m = n / s.order;
  Points out(n, 3);
  for (Eigen::Index i = 0; i < m; ++i) {
    Vec3 y = Vec3::Zero();
    for (int t = 0; t < s.order; ++t)
      y += s.rotation(-t) * (P.row(i + t * m).transpose() - s.center);
    y /= s.order;
    for (int t = 0; t < s.order; ++t) out.row(i + t * m) = (s.center + s.rotation(t) * y).transpose();
  }
  return out;
}

std::vector<double> symmetry_classes(const VecX& v, const CyclicSymmetry& s) {
  check_divisible(v.size() / 3, s.order);
  if (v.size() % 3 != 0) throw std::invalid_argument("symmetry_classes: the vector is not 3n long");
  const int p = s.order;
  const Eigen::Index n = v.size() / 3, m = n / p;
  // T^t v at vertex j: R^t v_{j - t m}. Class k: (1/p) Σ_t e^{-2πikt/p} T^t v.
  std::vector<Eigen::Matrix<std::complex<double>, Eigen::Dynamic, 1>> w(
      static_cast<size_t>(p), Eigen::Matrix<std::complex<double>, Eigen::Dynamic, 1>::Zero(v.size()));
  for (int t = 0; t < p; ++t) {
    const Mat3 R = s.rotation(t);
    VecX Tv(v.size());
    for (Eigen::Index j = 0; j < n; ++j) Tv.segment<3>(3 * j) = R * v.segment<3>(3 * (((j - t * m) % n + n) % n));
    for (int k = 0; k < p; ++k) w[static_cast<size_t>(k)] += std::polar(1.0 / p, -2.0 * M_PI * k * t / p) * Tv.cast<std::complex<double>>();
  }
  const double total = v.squaredNorm();
  std::vector<double> out(static_cast<size_t>(p / 2 + 1), 0.0);
  for (int k = 0; k < p; ++k) {
    const int c = std::min(k, p - k);
    out[static_cast<size_t>(c)] += total > 0.0 ? w[static_cast<size_t>(k)].squaredNorm() / total : 0.0;
  }
  return out;
}

SymmetricObjective::SymmetricObjective(Objective& full, const CyclicSymmetry& symmetry)
    : full_(full), symmetry_(symmetry) {
  symmetry_.axis.normalize();
  const VecX x = full_.dofs();
  if (x.size() % 3 != 0) throw std::invalid_argument("SymmetricObjective: the dofs are not 3n positions");
  n_ = static_cast<int>(x.size() / 3);
  check_divisible(n_, symmetry_.order);
  m_ = n_ / symmetry_.order;
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<size_t>(9 * n_));
  b_.resize(3 * n_);
  for (int t = 0; t < symmetry_.order; ++t) {
    const Mat3 R = symmetry_.rotation(t);
    const Vec3 shift = symmetry_.center - R * symmetry_.center;
    for (int i = 0; i < m_; ++i) {
      const int j = i + t * m_;
      for (int a = 0; a < 3; ++a)
        for (int c = 0; c < 3; ++c) entries.emplace_back(3 * j + a, 3 * i + c, R(a, c));
      b_.segment<3>(3 * j) = shift;
    }
  }
  S_.resize(3 * n_, 3 * m_);
  S_.setFromTriplets(entries.begin(), entries.end());
  const Points P = project_symmetric(as_points(x), symmetry_);
  y_ = as_vector(P).head(3 * m_);
  full_.set_dofs(full_dofs(y_));
}

void SymmetricObjective::set_dofs(const VecX& y) {
  y_ = y;
  full_.set_dofs(full_dofs(y_));
}

void SymmetricObjective::assemble_hessian(SparseAssembler& A, HessianKind kind) {
  full_.assemble_hessian(inner_, kind);
  const Eigen::SparseMatrix<double> H = inner_.matrix().selfadjointView<Eigen::Upper>();
  const Eigen::SparseMatrix<double> Hy = S_.transpose() * H * S_;
  A.begin(3 * m_);
  // Sᵀ H S's pattern is a function of H's: replayed while H's is unchanged
  A.segment(0, inner_.pattern_version());
  for (int col = 0; col < Hy.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(Hy, col); it; ++it)
      if (it.row() <= col) A.add(static_cast<int>(it.row()), col, it.value());
  A.end();
}

double SymmetricObjective::max_step(const VecX& y, const VecX& dy) {
  return full_.max_step(full_dofs(y), S_ * dy);
}

Eigen::MatrixXd SymmetricObjective::rigid_modes() {
  const Vec3 a = symmetry_.axis;
  Eigen::MatrixXd Q(3 * m_, 2);
  for (int i = 0; i < m_; ++i) {
    Q.block<3, 1>(3 * i, 0) = a;
    Q.block<3, 1>(3 * i, 1) = a.cross(y_.segment<3>(3 * i) - symmetry_.center);
  }
  Eigen::HouseholderQR<Eigen::MatrixXd> qr(Q);
  return qr.householderQ() * Eigen::MatrixXd::Identity(3 * m_, 2);
}

void CriticalPointOptions::validate() const {
  if (!(gradient_tolerance > 0.0) || max_iterations < 0 || !(min_step > 0.0 && min_step < 1.0))
    throw std::invalid_argument("critical point options: tolerance and min_step must be positive, iterations >= 0");
}

namespace {

/// The Newton–Raphson direction: (H + κ Q Qᵀ) d = −g, d ⊥ Q
/// (rigid_solve.hpp). Empty when the matrix is singular.
VecX root_direction(Objective& f, const VecX& g) {
  const RigidRegularizedSolver H(f);
  if (!H.ok()) return {};
  VecX d = H.solve(-g);
  if (!d.allFinite()) return {};
  return d;
}

}  // namespace

CriticalPointReport solve_critical_point(Objective& f, const CriticalPointOptions& o) {
  o.validate();
  const Stopwatch t0;
  CriticalPointReport r;
  VecX x = f.dofs(), g = f.gradient();
  const auto done = [&](SolverStatus status) {
    r.status = status;
    r.energy = f.energy();
    r.gradient_norm = g.norm();
    r.seconds = t0.seconds();
    return r;
  };
  for (r.iterations = 0; r.iterations < o.max_iterations; ++r.iterations) {
    if (g.norm() <= o.gradient_tolerance) return done(SolverStatus::ConvergedUnstable);
    const VecX d = root_direction(f, g);
    if (d.size() == 0) return done(SolverStatus::Stalled);
    const double merit = g.squaredNorm();
    bool accepted = false;
    for (double t = std::min(1.0, f.max_step(x, d)); t >= o.min_step && !accepted; t *= 0.5) {
      const VecX trial = x + t * d;
      f.set_dofs(trial);
      const VecX gt = f.gradient();
      if (std::isfinite(f.energy()) && gt.squaredNorm() <= (1.0 - 1e-4 * t) * merit) {
        x = trial;
        g = gt;
        f.accept();
        accepted = true;
      }
    }
    if (!accepted) {
      f.set_dofs(x);
      return done(SolverStatus::Stalled);
    }
  }
  return done(g.norm() <= o.gradient_tolerance ? SolverStatus::ConvergedUnstable : SolverStatus::MaxIterations);
}

std::string to_string(SymmetricSolve solve) { return solve == SymmetricSolve::Minimize ? "minimize" : "root"; }

void SymmetricSearchOptions::validate() const {
  relax.validate();
  require_input(!relax.link && !relax.full_model && !relax.slab,
                "symmetric critical point: only the twist-free model (no link, no full model, no slab)");
  require_input(max_modes >= 2, "symmetric critical point: max_modes must be at least 2");
  require_input(max_root_iterations >= 0, "symmetric critical point: max_root_iterations must be >= 0");
  require_input(!index_threshold || (*index_threshold > 0.0 && std::isfinite(*index_threshold)),
                "symmetric critical point: the index threshold must be positive");
}

namespace {

/// The Morse index and lowest eigenpairs of the full objective's exact
/// Hessian (rigid modes projected out): more eigenpairs are computed, up to
/// `max_modes`, while every computed one is negative.
void morse_index(Objective& f, const CyclicSymmetry& symmetry, int max_count, double threshold,
                 SymmetricCriticalPoint& out) {
  SparseAssembler A;
  f.assemble_hessian(A, HessianKind::Exact);
  const Eigen::MatrixXd Q = f.rigid_modes();
  const int limit = std::min(max_count, max_modes(f.num_dofs(), static_cast<int>(Q.cols())));
  LowestModes modes;
  for (int count = std::min(8, limit);; count = std::min(2 * count, limit)) {
    modes = lowest_modes(A.matrix(), Q, count, -threshold, threshold);
    if (!modes.converged) return;
    out.index = static_cast<int>((modes.values.array() < -threshold).count());
    out.near_zero = static_cast<int>((modes.values.array().abs() <= threshold).count());
      out.index_complete = out.index < count;
    if (out.index_complete || count == limit) break;
  }
  for (Eigen::Index k = 0; k < modes.values.size(); ++k) {
    SymmetricMode m;
    m.eigenvalue = modes.values(k);
    m.classes = symmetry_classes(modes.vectors.col(k), symmetry);
    m.dominant_class = static_cast<int>(std::max_element(m.classes.begin(), m.classes.end()) - m.classes.begin());
    m.vector = modes.vectors.col(k);
    out.modes.push_back(m);
  }
}

/// The negative eigenvalues (below −threshold) of the restricted Hessian,
/// up to `max_count` of them; -1 when the eigen-solve failed.
int subspace_index(Objective& reduced, int max_count, double threshold) {
  SparseAssembler A;
  reduced.assemble_hessian(A, HessianKind::Exact);
  const Eigen::MatrixXd Q = reduced.rigid_modes();
  const int limit = std::min(max_count, max_modes(reduced.num_dofs(), static_cast<int>(Q.cols())));
  for (int count = std::min(8, limit);; count = std::min(2 * count, limit)) {
    const LowestModes modes = lowest_modes(A.matrix(), Q, count, -threshold, threshold);
    if (!modes.converged) return -1;
    const int negative = static_cast<int>((modes.values.array() < -threshold).count());
    if (negative < count || count == limit) return negative;
  }
}

/// The rest lengths averaged over each orbit of the shift by n/p (so that E
/// is exactly invariant); InputError when they differ by more than 1e-6.
VecX periodic_rest_lengths(const VecX& rest, int n, int p) {
  require_input(p >= 2 && n >= 4 && n % p == 0, "symmetric critical point: " + std::to_string(n) +
                                                     " vertices are not divisible by p = " + std::to_string(p));
  require_input(rest.size() == n, "symmetric critical point: need one rest length per edge");
  const int m = n / p;
  for (int i = m; i < n; ++i)
    require_input(std::fabs(rest(i) - rest(i % m)) <= 1e-6 * rest(i % m),
                  "symmetric critical point: the rest lengths are not invariant under the p-fold shift");
  VecX periodic(n);
  for (int i = 0; i < m; ++i) {
    double mean = 0.0;
    for (int t = 0; t < p; ++t) mean += rest(i + t * m) / p;
    for (int t = 0; t < p; ++t) periodic(i + t * m) = mean;
  }
  return periodic;
}

/// The knot model at the projected start and its restriction to the subspace.
struct Restricted {
  VecX periodic;  ///< the rest lengths
  Points start;
  RodModel system;
  SymmetricObjective reduced;
  NewtonOptions newton;
  Restricted(const Points& x, const VecX& rest, const CyclicSymmetry& symmetry, const SymmetricSearchOptions& o)
      : periodic(periodic_rest_lengths(rest, static_cast<int>(x.rows()), symmetry.order)),
        start(project_symmetric(x, symmetry)),
        system(start, periodic, o.relax),
        reduced(system.objective(), symmetry),
        newton(system.newton()) {
    newton.lambda_min *= symmetry.order;  // Sᵀ H S has p times the curvature of H along symmetric directions
  }
  Points positions() const { return system.positions(reduced.full_dofs(reduced.dofs())); }
};

/// Records every iterate of the restricted solve (the images of a descent).
class Recording : public Objective {
 public:
  Recording(SymmetricObjective& f, RodModel& system, SymmetricDescent& out) : f_(f), system_(system), out_(out) {}
  int num_dofs() const override { return f_.num_dofs(); }
  VecX dofs() const override { return f_.dofs(); }
  void set_dofs(const VecX& y) override { f_.set_dofs(y); }
  double energy() override { return f_.energy(); }
  VecX gradient() override { return f_.gradient(); }
  void assemble_hessian(SparseAssembler& A, HessianKind kind) override { f_.assemble_hessian(A, kind); }
  double max_step(const VecX& y, const VecX& dy) override { return f_.max_step(y, dy); }
  void accept() override {
    f_.accept();
    record();
  }
  Eigen::MatrixXd rigid_modes() override { return f_.rigid_modes(); }
  std::vector<EnergyPart> energy_parts() override { return f_.energy_parts(); }
  int active_pairs() const override { return f_.active_pairs(); }
  void record() {
    const VecX x = f_.full_dofs(f_.dofs());
    out_.images.push_back(system_.positions(x));
    out_.energies.push_back(f_.energy());
    out_.gradient_norms.push_back(system_.objective().gradient().norm());
  }

 private:
  SymmetricObjective& f_;
  RodModel& system_;
  SymmetricDescent& out_;
};

}  // namespace

SymmetricDescent descend_symmetric(const Points& start, const VecX& rest, const CyclicSymmetry& symmetry,
                                   const SymmetricSearchOptions& options) {
  options.validate();
  Restricted r(start, rest, symmetry, options);
  SymmetricDescent out;
  Recording recording(r.reduced, r.system, out);
  recording.record();
  out.report = NewtonSolver(r.newton).minimize(recording);
  return out;
}

SymmetricCriticalPoint find_symmetric_critical_point(const Points& start, const VecX& rest,
                                                     const CyclicSymmetry& symmetry,
                                                     const SymmetricSearchOptions& options) {
  const Stopwatch t0;
  options.validate();
  Restricted model(start, rest, symmetry, options);
  SymmetricCriticalPoint out;
  out.symmetry = model.reduced.symmetry();
  out.solve = options.solve;
  if (options.solve == SymmetricSolve::Minimize) {
    const NewtonReport report = NewtonSolver(model.newton).minimize(model.reduced);
    out.status = report.status;
    out.iterations = report.iterations;
  } else {
    CriticalPointOptions co;
    co.gradient_tolerance = model.newton.gradient_tolerance;
    co.max_iterations = std::min(model.newton.max_iterations, options.max_root_iterations);
    const CriticalPointReport report = solve_critical_point(model.reduced, co);
    out.status = report.status;
    out.iterations = report.iterations;
  }
  out.positions = model.positions();
  Objective& full = model.system.objective();
  out.energy = full.energy();
  out.gradient_norm = full.gradient().norm();
  out.tolerance = model.system.tolerance();
  out.converged = (out.status == SolverStatus::ConvergedStable || out.status == SolverStatus::ConvergedUnstable) &&
                  out.gradient_norm <= out.tolerance;
  if (options.relax.check_topology) out.alexander_preserved = alexander(out.positions) == alexander(model.start);
  out.residual = cyclic_symmetry_residual(out.positions, out.symmetry);
  out.contacts = full.active_pairs();
  out.threshold = options.index_threshold.value_or(1e3 * model.newton.shift_epsilon * model.system.lambda_min());
  morse_index(full, out.symmetry, options.max_modes, out.threshold, out);
  out.subspace_index = subspace_index(model.reduced, options.max_modes, symmetry.order * out.threshold);
  out.seconds = t0.seconds();
  return out;
}

}  // namespace ek
