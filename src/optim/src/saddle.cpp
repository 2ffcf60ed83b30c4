#include "ek/optim/saddle.hpp"

#include <Eigen/SparseCholesky>
#include <Spectra/SymEigsSolver.h>

#include <cstdio>
#include <cmath>
#include <limits>

#include "ek/core/errors.hpp"
#include "ek/core/sparse_assembler.hpp"
#include "ek/core/stopwatch.hpp"
#include "ek/optim/cholesky.hpp"
#include "shift_invert.hpp"

namespace ek {
namespace {

using SpMat = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;
using Ldlt = Eigen::SimplicialLDLT<SpMat, Eigen::Upper, Eigen::AMDOrdering<int>>;

/// Halvings of the complement step before it is given up (relax_complement).
constexpr int kMaxBacktracks = 40;

/// The complement step of the file comment of saddle.hpp (item 3). The
/// shift ladder starts one rung below `shift` (in/out: the rung used).
/// False when no rung up to σ₀·10¹² gives a usable factorisation.
struct Complement {
  Ldlt ldlt;
  std::uint64_t analysed = ~std::uint64_t(0);
  int size = -1;

  bool step(const SpMat& H, std::uint64_t version, const VecX& g, const Eigen::MatrixXd& C, double base,
            double& shift, VecX& d) {
    if (version != analysed || size != H.rows()) {
      ldlt.analyzePattern(H);
      analysed = version;
      size = static_cast<int>(H.rows());
    }
    const int m = static_cast<int>(C.cols());
    int rung = std::max(0, static_cast<int>(std::lround(std::log10(std::max(shift, base) / base))) - 1);
    for (; rung <= 12; ++rung) {
      const double sigma = base * std::pow(10.0, rung);
      ldlt.setShift(sigma);
      ldlt.factorize(H);
      if (ldlt.info() != Eigen::Success) continue;
      const int negative = static_cast<int>((ldlt.vectorD().array() < 0.0).count());
      const Eigen::MatrixXd Y = ldlt.solve(C);
      const VecX w = ldlt.solve(g);
      if (!Y.allFinite() || !w.allFinite()) continue;
      Eigen::MatrixXd S = C.transpose() * Y;
      S = 0.5 * (S + S.transpose());
      const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(S);
      const int positive = static_cast<int>((es.eigenvalues().array() > 0.0).count());
      if (negative + positive - m != 0) continue;  // M is not positive definite on C^⊥
      const VecX eta = -es.eigenvectors() * (es.eigenvalues().cwiseInverse().asDiagonal() *
                                             (es.eigenvectors().transpose() * (C.transpose() * w)));
      d = -(w + Y * eta);
      if (!d.allFinite()) continue;
      shift = sigma;
      return true;
    }
    return false;
  }
};

/// Partitioned rational-function step along the followed mode (maximising).
double prfo_along(double lambda, double gv) {
  const double denom = std::sqrt(0.25 * lambda * lambda + gv * gv) - 0.5 * lambda;
  if (denom <= 0.0) return 0.0;
  return gv / denom;
}

/// The exact Hessian (Objective::assemble_hessian begins and ends the pass).
void assemble(Objective& f, SparseAssembler& A) { f.assemble_hessian(A, HessianKind::Exact); }

}  // namespace

std::string to_string(SaddleStatus s) {
  switch (s) {
    case SaddleStatus::Converged: return "converged";
    case SaddleStatus::MaxIterations: return "max-iterations";
    case SaddleStatus::Stalled: return "stalled";
    case SaddleStatus::LeftBasin: return "left-basin";
    case SaddleStatus::Degenerate: return "degenerate";
  }
  return "?";
}

void SaddleSearchOptions::validate() const {
  require(gradient_tolerance > 0.0 && std::isfinite(gradient_tolerance), "saddle search: gradient_tolerance > 0");
  require(max_iterations >= 1, "saddle search: max_iterations >= 1");
  require(trust_radius > 0.0 && max_trust_radius >= trust_radius && min_trust_radius > 0.0 &&
              min_trust_radius < trust_radius,
          "saddle search: 0 < min_trust_radius < trust_radius <= max_trust_radius");
  require(max_energy_rise > 0.0, "saddle search: max_energy_rise > 0");
  require(base_shift > 0.0 && std::isfinite(base_shift), "saddle search: base_shift > 0");
  require(eigen_count >= 2, "saddle search: eigen_count >= 2");
  require(eigen_tolerance > 0.0 && eigen_tolerance < 1e-2, "saddle search: eigen_tolerance in (0, 1e-2)");
}

namespace {

/// Small problems: P H P dense, its eigenvectors outside span(Q).
LowestModes lowest_modes_dense(const SpMat& upper, const Eigen::MatrixXd& Q, int count) {
  const Eigen::Index n = upper.rows();
  Eigen::MatrixXd H = Eigen::MatrixXd(SpMat(upper.selfadjointView<Eigen::Upper>()));
  Eigen::MatrixXd P = Eigen::MatrixXd::Identity(n, n);
  if (Q.cols() > 0) P -= Q * Q.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(P * H * P);
  LowestModes out;
  out.values.resize(count);
  out.vectors.resize(n, count);
  int k = 0;
  for (Eigen::Index i = 0; i < n && k < count; ++i) {
    const VecX u = es.eigenvectors().col(i);
    if (Q.cols() > 0 && (Q.transpose() * u).norm() > 0.5) continue;  // a rigid mode
    out.values(k) = es.eigenvalues()(i);
    out.vectors.col(k++) = u;
  }
  out.converged = (k == count);
  out.tau = out.converged ? out.values(0) : 0.0;
  return out;
}

}  // namespace

int max_modes(int dofs, int rigid) { return dofs <= kDenseModes ? dofs - rigid : dofs - rigid - 1; }

LowestModes lowest_modes(const SpMat& upper, const Eigen::MatrixXd& Q, int count, double guess, double scale,
                         double tolerance) {
  const Eigen::Index n = upper.rows();
  require(count >= 1 && count <= max_modes(static_cast<int>(n), static_cast<int>(Q.cols())),
          "lowest_modes: count must be in [1, max_modes(dofs, rigid modes)]");
  require(scale > 0.0, "lowest_modes: scale must be positive");
  if (n <= kDenseModes) return lowest_modes_dense(upper, Q, count);
  LowestModes out;
  CholeskySolver chol(CholeskyMode::Block);
  double tau = guess, step = scale;
  bool ok = false;
  for (int attempt = 0; attempt < 60 && !ok; ++attempt) {
    ok = chol.factorize(upper, -tau, 0);
    if (!ok) {
      tau -= step;
      step *= 4.0;
    }
  }
  if (!ok) return out;
  out.tau = tau;
  detail::ShiftInvertOp op(chol, Q, n);
  const int ncv = static_cast<int>(std::min<Eigen::Index>(n - Q.cols(), std::max(2 * count + 8, 20)));
  if (ncv <= count) return out;
  Spectra::SymEigsSolver<detail::ShiftInvertOp> solver(op, count, ncv);
  solver.init();
  solver.compute(Spectra::SortRule::LargestAlge, 1000, tolerance, Spectra::SortRule::LargestAlge);
  if (solver.info() != Spectra::CompInfo::Successful) return out;
  const VecX mu = solver.eigenvalues();  // descending μ -> ascending λ
  if ((mu.array() <= 0.0).any()) return out;
  out.values = tau + mu.cwiseInverse().array();
  out.vectors = solver.eigenvectors();
  out.converged = true;
  return out;
}

HessianIndex hessian_index(Objective& f, int count, double threshold, double eigen_tolerance) {
  require(count >= 2, "hessian_index: count >= 2");
  require(threshold > 0.0, "hessian_index: threshold > 0");
  SparseAssembler A;
  assemble(f, A);
  const Eigen::MatrixXd Q = f.rigid_modes();
  const int available = max_modes(f.num_dofs(), static_cast<int>(Q.cols()));
  HessianIndex out;
  for (int k = std::min(count, available); k <= std::min(8, available); k += 2) {
    const LowestModes m = lowest_modes(A.matrix(), Q, k, -threshold, threshold, eigen_tolerance);
    if (!m.converged) return out;
    out.converged = true;
    out.values = m.values;
    out.vectors = m.vectors;
    out.negative = static_cast<int>((m.values.array() < -threshold).count());
    out.near_zero = static_cast<int>((m.values.array().abs() <= threshold).count());
    if (out.negative < k) break;
  }
  return out;
}

namespace {

/// The state of one search (saddle.hpp's file comment).
struct Search {
  Objective& f;
  const SaddleSearchOptions& o;
  SaddleSearchResult result;
  SparseAssembler A;
  Complement complement;
  VecX x, v;
  double E0 = 0.0, radius = 0.0, lambda = 0.0, shift = 0.0;
  bool have_lambda = false;

  /// Eigenpairs and the followed mode at x; false when the eigen-solve failed.
  bool follow(SaddleIteration& it, int& rank) {
    const Eigen::MatrixXd Q = f.rigid_modes();
    const int count = std::min(o.eigen_count, max_modes(f.num_dofs(), static_cast<int>(Q.cols())));
    const double guess = have_lambda ? std::min(lambda, 0.0) - 0.5 * std::abs(lambda) - o.base_shift : -o.base_shift;
    const LowestModes m = lowest_modes(A.matrix(), Q, count, guess, std::max(o.base_shift, 0.1 * std::abs(lambda)),
                                       o.eigen_tolerance);
    if (!m.converged) return false;
    Eigen::Index j = 0;
    const VecX overlaps = (m.vectors.transpose() * v).cwiseAbs();
    overlaps.maxCoeff(&j);
    rank = static_cast<int>(j);
    const double sign = m.vectors.col(j).dot(v) < 0.0 ? -1.0 : 1.0;
    v = sign * m.vectors.col(j);
    lambda = m.values(j);
    have_lambda = true;
    it.eigenvalue = lambda;
    it.mode_rank = rank;
    it.overlap = overlaps(j);
    return true;
  }

  /// Tries d (shortened to the trust radius and the collision-free bound);
  /// false when the radius fell below its minimum (stalled).
  bool take(const VecX& g, double E, const VecX& d, SaddleIteration& it) {
    const auto H = A.matrix().selfadjointView<Eigen::Upper>();
    const double dmax = d.cwiseAbs().maxCoeff();
    while (radius >= o.min_trust_radius) {
      const double t = dmax > radius ? radius / dmax : 1.0;
      VecX dd = t * d;
      dd *= f.max_step(x, dd);
      const double gd = g.dot(dd), dHd = dd.dot(H * dd);
      f.set_dofs(x + dd);
      const double E1 = f.energy();
      const double err = std::abs(E1 - E - gd - 0.5 * dHd), scale = std::abs(gd) + 0.5 * std::abs(dHd);
      if (std::isfinite(E1) && err <= 0.5 * scale + 1e-11 * std::max(1.0, std::abs(E))) {
        x += dd;
        f.accept();
        if (t < 1.0 && err <= 0.1 * scale) radius = std::min(2.0 * radius, o.max_trust_radius);
        it.accepted = true;
        return true;
      }
      ++result.rejected;
      radius = 0.25 * std::min(radius, dmax * t);
    }
    f.set_dofs(x);
    return false;
  }

  /// The complement step d⊥ (⊥ v and the rigid modes, a descent direction
  /// since M is positive definite there) with a backtracking line search on
  /// the energy (Armijo, 1e-4), at most the largest trust radius long and cut
  /// by the CCD. The quadratic model of a rod is accurate only over short
  /// steps (a linear step stretches the edges at second order), so a trust
  /// region on d⊥ would keep it a small fraction of Newton's step; the line
  /// search takes what lowers the energy, as Newton's method does. False when
  /// no step lowers it.
  bool relax_complement(const VecX& g, double E, const VecX& dperp) {
    const double dmax = dperp.cwiseAbs().maxCoeff();
    if (!(dmax > 0.0) || !(g.dot(dperp) < 0.0)) return false;
    double t = std::min(1.0, o.max_trust_radius / dmax);
    for (int k = 0; k < kMaxBacktracks; ++k, t *= 0.5) {
      VecX dd = t * dperp;
      dd *= f.max_step(x, dd);
      f.set_dofs(x + dd);
      const double E1 = f.energy();
      if (std::isfinite(E1) && E1 <= E + 1e-4 * g.dot(dd)) {
        x += dd;
        f.accept();
        return true;
      }
    }
    f.set_dofs(x);
    return false;
  }

  /// One iteration; false when the search ends (result.status set).
  bool iterate() {
    SaddleIteration it;
    const double E = f.energy();
    const VecX g = f.gradient();
    assemble(f, A);
    int rank = 0;
    const bool ok = follow(it, rank);
    it.energy = E;
    it.gradient_norm = g.norm();
    it.trust_radius = radius;
    result.energy = E;
    result.gradient_norm = it.gradient_norm;
    if (!ok) return finish(SaddleStatus::Degenerate, it);
    if (it.gradient_norm <= o.gradient_tolerance && lambda < 0.0 && rank == 0)
      return finish(SaddleStatus::Converged, it);
    if (E - E0 > o.max_energy_rise) return finish(SaddleStatus::LeftBasin, it);
    const Eigen::MatrixXd Q = f.rigid_modes();
    Eigen::MatrixXd C(v.size(), 1 + Q.cols());
    C << v, Q;
    VecX dperp;
    if (!complement.step(A.matrix(), A.pattern_version(), g, C, o.base_shift, shift, dperp))
      return finish(SaddleStatus::Degenerate, it);
    it.shift = shift;
    const bool relaxed = relax_complement(g, E, dperp);
    const VecX g1 = relaxed ? f.gradient() : g;
    const double E1 = relaxed ? f.energy() : E;
    const VecX d = prfo_along(lambda, g1.dot(v)) * v;
    if (o.verbose)
      std::fprintf(stderr, "saddle %4d E %.12g |g| %.3e lambda %.4e rank %d overlap %.3f gv %.3e dv %.3e |dperp| %.3e radius %.3e shift %.2e\n",
                   result.iterations, E, it.gradient_norm, lambda, rank, it.overlap, g.dot(v),
                   prfo_along(lambda, g.dot(v)), dperp.cwiseAbs().maxCoeff(), radius, shift);
    if (!take(g1, E1, d, it)) return finish(SaddleStatus::Stalled, it);
    if (o.record_trace) result.trace.push_back(it);
    return true;
  }

  bool finish(SaddleStatus status, const SaddleIteration& it) {
    result.status = status;
    if (o.record_trace) result.trace.push_back(it);
    return false;
  }
};

}  // namespace

SaddleSearchResult search_saddle(Objective& f, const VecX& direction, const SaddleSearchOptions& o) {
  o.validate();
  const Stopwatch t0;
  require(direction.size() == f.num_dofs(), "search_saddle: the direction must have one entry per dof");
  require(direction.allFinite() && direction.norm() > 0.0, "search_saddle: the direction must be finite and nonzero");
  Search s{f, o, {}, {}, {}, f.dofs(), direction.normalized()};
  s.E0 = f.energy();
  s.radius = o.trust_radius;
  VecX first = s.v * (o.trust_radius / s.v.cwiseAbs().maxCoeff());
  first *= f.max_step(s.x, first);
  s.x += first;
  f.set_dofs(s.x);
  f.accept();
  s.result.status = SaddleStatus::MaxIterations;
  for (int k = 0; k < o.max_iterations; ++k) {
    s.result.iterations = k + 1;
    if (!s.iterate()) break;
  }
  if (s.result.status == SaddleStatus::MaxIterations) {
    s.result.energy = f.energy();
    s.result.gradient_norm = f.gradient().norm();
  }
  s.result.x = s.x;
  s.result.eigenvalue = s.lambda;
  s.result.mode = s.v;
  s.result.seconds = t0.seconds();
  return s.result;
}

namespace {

/// Delegates to an objective and records every accepted iterate.
class Recorder : public Objective {
 public:
  Recorder(Objective& f, Descent& out) : f_(f), out_(out) {}
  int num_dofs() const override { return f_.num_dofs(); }
  VecX dofs() const override { return f_.dofs(); }
  void set_dofs(const VecX& x) override { f_.set_dofs(x); }
  double energy() override { return f_.energy(); }
  VecX gradient() override { return f_.gradient(); }
  void assemble_hessian(SparseAssembler& A, HessianKind kind) override { f_.assemble_hessian(A, kind); }
  double max_step(const VecX& x, const VecX& dx) override { return f_.max_step(x, dx); }
  void accept() override {
    f_.accept();
    out_.images.push_back(f_.dofs());
    out_.energies.push_back(f_.energy());
  }
  Eigen::MatrixXd rigid_modes() override { return f_.rigid_modes(); }
  std::vector<EnergyPart> energy_parts() override { return f_.energy_parts(); }
  int active_pairs() const override { return f_.active_pairs(); }

 private:
  Objective& f_;
  Descent& out_;
};

}  // namespace

Descent descend(Objective& f, const NewtonOptions& options) {
  Descent out;
  out.images.push_back(f.dofs());
  out.energies.push_back(f.energy());
  Recorder r(f, out);
  NewtonSolver solver(options);
  out.report = solver.minimize(r);
  const VecX last = f.dofs();
  if (out.images.back() != last) {  // the solver ends where it accepted last, but keep the result exact
    out.images.push_back(last);
    out.energies.push_back(f.energy());
  }
  return out;
}

}  // namespace ek
