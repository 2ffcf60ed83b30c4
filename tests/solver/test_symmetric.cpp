// Newton restricted to p-fold rotationally symmetric curves (symmetric.hpp):
// the symmetry of torus knots (a known answer), the reduced gradient and
// Hessian against finite differences, the Fourier classes of vector fields,
// and symmetric critical points that are critical points of the full model.
#include <gtest/gtest.h>

#include <cmath>

#include "ek/core/errors.hpp"
#include "ek/geometry/polyline.hpp"
#include "ek/knots/alexander.hpp"
#include "ek/optim/saddle.hpp"
#include "ek/solver/rod_model.hpp"
#include "ek/solver/symmetric.hpp"
#include "testing.hpp"

using namespace ek;

namespace {

/// T(2, 3) on the torus (R, r) = (12, 4), n = 120: shifting the parameter
/// by a third turns the curve by 2·2π/3 about z.
Points trefoil(int n = 120) { return fixtures::torus_knot(n, 2, 3, 12.0, 4.0); }

}  // namespace

TEST(CyclicSymmetry, TorusKnotsHaveTheirKnownSymmetry) {
  // T(p, q) (parameter s): s -> s + 2π/q turns by 2πp/q about z, and the
  // vertex shift by n/q is that parameter shift. So T(2,3) has 3-fold
  // symmetry with angle 4π/3 (k = 2) and T(3,2) 2-fold with angle 3π ≡ π.
  const CyclicSymmetry s = fit_cyclic_symmetry(trefoil(), 3, Vec3::Zero(), Vec3::UnitZ());
  EXPECT_NEAR(s.angle, 4.0 * M_PI / 3.0, 1e-12);
  EXPECT_LT(cyclic_symmetry_residual(trefoil(), s), 1e-12);
  const Points t32 = fixtures::torus_knot(120, 3, 2, 12.0, 4.0);
  const CyclicSymmetry s2 = fit_cyclic_symmetry(t32, 2, Vec3::Zero(), Vec3::UnitZ());
  EXPECT_NEAR(s2.angle, M_PI, 1e-12);
  EXPECT_LT(cyclic_symmetry_residual(t32, s2), 1e-12);
  // a wrong angle leaves a residual of the curve's size
  CyclicSymmetry wrong = s;
  wrong.angle = 2.0 * M_PI / 3.0;
  EXPECT_GT(cyclic_symmetry_residual(trefoil(), wrong), 1.0);
  // a perturbed curve is projected back onto the subspace, and the
  // projection is the identity on symmetric curves
  Points noisy = trefoil() + 0.1 * fixtures::random_fourier_curve(120, 5, 7);
  EXPECT_GT(cyclic_symmetry_residual(noisy, s), 1e-3);
  const Points projected = project_symmetric(noisy, s);
  EXPECT_LT(cyclic_symmetry_residual(projected, s), 1e-12);
  EXPECT_LT((project_symmetric(projected, s) - projected).norm(), 1e-12);
  EXPECT_THROW(fit_cyclic_symmetry(trefoil(121), 3, Vec3::Zero(), Vec3::UnitZ()), std::invalid_argument);
}

TEST(CyclicSymmetry, FourierClassesOfVectorFields) {
  // On the 3-fold trefoil: the velocity of a rotation about z is
  // equivariant (class 0); a field that is rotated with the curve and
  // multiplied by cos(2πt/3) on period t lies in class 1 (wavenumber 1);
  // their sum splits in the ratio of their squared norms.
  const Points P = trefoil();
  const CyclicSymmetry s = fit_cyclic_symmetry(P, 3, Vec3::Zero(), Vec3::UnitZ());
  const int n = 120, m = 40;
  VecX rotation(3 * n), wave(3 * n);
  for (int i = 0; i < n; ++i) {
    rotation.segment<3>(3 * i) = Vec3::UnitZ().cross(P.row(i).transpose());
    const int t = i / m;
    const Vec3 base(1.0 + 0.1 * (i % m), 0.5, -0.2);
    wave.segment<3>(3 * i) = std::cos(2.0 * M_PI * t / 3.0) * (s.rotation(t) * base);
  }
  const std::vector<double> c0 = symmetry_classes(rotation, s), c1 = symmetry_classes(wave, s);
  ASSERT_EQ(c0.size(), 2u);
  EXPECT_NEAR(c0[0], 1.0, 1e-12);
  EXPECT_NEAR(c1[1], 1.0, 1e-12);
  const VecX sum = rotation + wave;
  const std::vector<double> cs = symmetry_classes(sum, s);
  EXPECT_NEAR(cs[0], rotation.squaredNorm() / sum.squaredNorm(), 1e-9);
  EXPECT_NEAR(cs[0] + cs[1], 1.0, 1e-12);
}

TEST(SymmetricObjective, ReducedGradientAndHessianMatchFiniteDifferences) {
  // E(S y + b) of the knot model (contact active: the trefoil is scaled so
  // that its strands pass within d̂) against central differences in y.
  const Points P = trefoil() * 0.11;
  const CyclicSymmetry s = fit_cyclic_symmetry(P, 3, Vec3::Zero(), Vec3::UnitZ());
  RodModel system(P, edge_lengths(P), RelaxOptions{});
  SymmetricObjective f(system.objective(), s);
  ASSERT_EQ(f.num_dofs(), 3 * 40);
  ASSERT_GT(f.active_pairs(), 0) << "the test needs contact";
  const VecX y0 = f.dofs();
  const auto energy = [&](const VecX& y) {
    f.set_dofs(y);
    return f.energy();
  };
  const VecX g = (f.set_dofs(y0), f.gradient());
  const VecX fd = fixtures::fd_gradient(energy, y0, 1e-6);
  EXPECT_LT((g - fd).norm(), 1e-5 * g.norm());
  EXPECT_GT(g.norm(), 1e-3);  // not trivially zero
  f.set_dofs(y0);
  SparseAssembler A;
  f.assemble_hessian(A, HessianKind::Exact);
  const Eigen::MatrixXd H = Eigen::MatrixXd(Eigen::SparseMatrix<double>(A.matrix().selfadjointView<Eigen::Upper>()));
  const double h = 1e-6;
  double worst = 0.0;
  for (int j = 0; j < f.num_dofs(); ++j) {
    VecX yp = y0, ym = y0;
    yp(j) += h;
    ym(j) -= h;
    f.set_dofs(yp);
    const VecX gp = f.gradient();
    f.set_dofs(ym);
    const VecX gm = f.gradient();
    worst = std::max(worst, ((gp - gm) / (2 * h) - H.col(j)).norm());
  }
  EXPECT_LT(worst, 1e-4 * H.norm());
  EXPECT_GT(H.norm(), 1.0);
  // the reduced gradient is Sᵀ∇E, and at a symmetric point ∇E is
  // equivariant, so ||Sᵀ∇E|| = √p ||∇E||
  f.set_dofs(y0);
  EXPECT_NEAR(f.gradient().norm(), std::sqrt(3.0) * system.objective().gradient().norm(), 1e-9 * g.norm());
  // the symmetric rigid modes (axial translation and rotation) leave E unchanged
  const Eigen::MatrixXd Q = f.rigid_modes();
  ASSERT_EQ(Q.cols(), 2);
  EXPECT_LT((Q.transpose() * Q - Eigen::Matrix2d::Identity()).norm(), 1e-12);
  EXPECT_LT((Q.transpose() * g).norm(), 1e-8 * g.norm());
}

TEST(SymmetricCriticalPoint, CircleIsTheSymmetricMinimumWithTheKnownEnergy) {
  // The unknot as an ellipse (4-fold symmetric, angle π/2): the restricted
  // minimum is the circle, E = 2π²EI/L (bending; the discrete circle's
  // relative error is of order 1/n²: 4.1e-5 at n = 400 in docs/performance.md,
  // so 1.6e-4 at n = 200; tolerance 3e-4), a minimum of the full model (index 0).
  const int n = 200;
  Points P(n, 3);
  for (int i = 0; i < n; ++i) {
    const double t = 2.0 * M_PI * i / n;
    P.row(i) << 36.0 * std::cos(t), 28.0 * std::sin(t), 0.0;
  }
  const VecX rest = VecX::Constant(n, 1.0);
  const CyclicSymmetry s = fit_cyclic_symmetry(P, 4, Vec3::Zero(), Vec3::UnitZ());
  EXPECT_NEAR(s.angle, M_PI / 2.0, 1e-12);
  const SymmetricCriticalPoint c = find_symmetric_critical_point(P, rest, s);
  ASSERT_TRUE(c.converged) << to_string(c.status);
  const RodMaterial mat;
  const double EI = mat.young * M_PI * std::pow(mat.radius, 4) / 4.0;
  EXPECT_NEAR(c.energy, 2.0 * M_PI * M_PI * EI / n, 3e-4 * c.energy);
  EXPECT_LE(c.gradient_norm, c.tolerance);
  EXPECT_LT(c.residual, 1e-9);
  EXPECT_TRUE(c.index_complete);
  EXPECT_EQ(c.index, 0);
  EXPECT_EQ(c.subspace_index, 0);
  EXPECT_TRUE(c.alexander_preserved);
}

TEST(SymmetricCriticalPoint, SymmetricCriticalPointsAreCriticalInTheFullSpace) {
  // Symmetric criticality: the trefoil's restricted minimum has a full
  // gradient below the tolerance, whatever its index. Its lowest modes carry
  // their Fourier classes (summing to 1), and with index 0 the full model's
  // Newton solver finds nothing to do there.
  const Points P = trefoil();
  const CyclicSymmetry s = fit_cyclic_symmetry(P, 3, Vec3::Zero(), Vec3::UnitZ());
  const SymmetricCriticalPoint c = find_symmetric_critical_point(P, edge_lengths(P), s);
  ASSERT_TRUE(c.converged) << to_string(c.status) << " |g| " << c.gradient_norm;
  EXPECT_LE(c.gradient_norm, c.tolerance);
  EXPECT_LT(c.residual, 1e-9);
  EXPECT_TRUE(c.alexander_preserved);
  EXPECT_EQ(alexander(c.positions), alexander(P));
  ASSERT_FALSE(c.modes.empty());
  for (const SymmetricMode& m : c.modes) {
    double sum = 0.0;
    for (double w : m.classes) sum += w;
    EXPECT_NEAR(sum, 1.0, 1e-9);
  }
  ASSERT_TRUE(c.index_complete);
  if (c.index == 0) {
    // a minimum of the full model: relax() from it stays (energy within 1e-9 relative)
    RelaxOptions o;
    o.rest_lengths = edge_lengths(P);
    o.method = RelaxMethod::Direct;
    const RelaxResult r = relax(c.positions, o);
    EXPECT_EQ(r.status(), RelaxStatus::ConvergedStable);
    EXPECT_NEAR(r.energy.total, c.energy, 1e-9 * c.energy);
  }
}

TEST(SymmetricCriticalPoint, DescentRecordsThePathAndBadInputIsRefused) {
  const Points P = trefoil();
  const CyclicSymmetry s = fit_cyclic_symmetry(P, 3, Vec3::Zero(), Vec3::UnitZ());
  const SymmetricDescent d = descend_symmetric(P, edge_lengths(P), s);
  ASSERT_GE(d.images.size(), 2u);
  ASSERT_EQ(d.energies.size(), d.images.size());
  ASSERT_EQ(d.gradient_norms.size(), d.images.size());
  for (size_t k = 1; k < d.energies.size(); ++k) EXPECT_LE(d.energies[k], d.energies[k - 1] + 1e-12);
  for (const Points& X : d.images) EXPECT_LT(cyclic_symmetry_residual(X, s), 1e-9);
  EXPECT_EQ(d.report.status, SolverStatus::ConvergedStable);
  EXPECT_LE(d.gradient_norms.back(), 1e-8);
  // rest lengths that are not periodic, a vertex count not divisible by p,
  // and models outside the twist-free one are refused
  VecX rest = edge_lengths(P);
  rest(0) *= 1.1;
  EXPECT_THROW(find_symmetric_critical_point(P, rest, s), InputError);
  EXPECT_THROW(find_symmetric_critical_point(trefoil(121), edge_lengths(trefoil(121)), s), InputError);
  SymmetricSearchOptions o;
  o.relax.link = 1.0;
  EXPECT_THROW(find_symmetric_critical_point(P, edge_lengths(P), s, o), InputError);
}
