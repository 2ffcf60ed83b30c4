// Knots in time (ek/mechanics/dynamics.hpp): the inertia and friction terms
// against finite differences, and runs with known answers: a ring's in-plane
// bending frequency, backward Euler's first-order dissipation, exact uniform
// motion, a ring sliding to a stop at v²/(2μg) on a plate, the static limit
// of strong damping, and the knot type kept under violent motion.
#include <gtest/gtest.h>

#include <cmath>

#include "ek/contact/barrier.hpp"
#include "ek/core/errors.hpp"
#include "ek/geometry/polyline.hpp"
#include "ek/geometry/rigid.hpp"
#include "ek/mechanics/dynamics.hpp"
#include "ek/solver/energy.hpp"
#include "testing.hpp"

using namespace ek;

namespace {

/// The upper triangle assembled by `term` at x, made symmetric.
Eigen::MatrixXd dense_hessian(Potential& term, const VecX& x) {
  term.set_dofs(x);
  SparseAssembler A;
  A.begin(static_cast<int>(x.size()));
  A.segment(0, term.hessian_structure());
  term.add_hessian(A, HessianKind::Exact);
  A.end();
  return Eigen::MatrixXd(Eigen::SparseMatrix<double>(A.matrix().selfadjointView<Eigen::Upper>()));
}

/// The term's gradient against central differences of its energy, and its
/// Hessian against central differences of its gradient.
void check_derivatives(Potential& term, const VecX& x0, double h = 1e-6) {
  const auto n = x0.size();
  const auto energy = [&](const VecX& x) {
    term.set_dofs(x);
    return term.energy();
  };
  const auto gradient = [&](const VecX& x) {
    term.set_dofs(x);
    VecX g = VecX::Zero(n);
    term.add_gradient(g);
    return g;
  };
  const VecX g = gradient(x0);
  EXPECT_GT(g.norm(), 1e-6);  // not trivially zero
  EXPECT_LT((g - fixtures::fd_gradient(energy, x0, h)).norm(), 1e-6 * (1.0 + g.norm()));
  const Eigen::MatrixXd H = dense_hessian(term, x0);
  Eigen::MatrixXd fd(n, n);
  for (Eigen::Index j = 0; j < n; ++j) {
    VecX xp = x0, xm = x0;
    xp(j) += h;
    xm(j) -= h;
    fd.col(j) = (gradient(xp) - gradient(xm)) / (2 * h);
  }
  EXPECT_LT((H - fd).norm(), 1e-5 * (1.0 + H.norm()));
}

/// Total mechanical energy of a frame.
double total(const DynamicsFrame& f) { return f.kinetic + f.elastic + f.gravity; }

/// Mode-2 in-plane amplitude of X about the ring R (radial displacement
/// projected on cos 2φ; the ring's vertex i is at angle φ_i = 2πi/n).
double mode2(const Points& X, const Points& R) {
  const int n = static_cast<int>(X.rows());
  double a = 0.0;
  for (int i = 0; i < n; ++i) {
    const Vec3 radial = R.row(i).normalized();
    a += (X.row(i).dot(radial) - R.row(i).norm()) * std::cos(4.0 * M_PI * i / n);
  }
  return 2.0 * a / n;
}

/// A ring of n unit edges with the inextensional in-plane mode 2 of
/// amplitude eps: u_r = eps cos 2φ, u_φ = −(eps/2) sin 2φ.
Points ring_mode2(int n, double eps) {
  const Points R = fixtures::unit_ring(n);
  Points X = R;
  for (int i = 0; i < n; ++i) {
    const double phi = 2.0 * M_PI * i / n;
    const Vec3 er(std::cos(phi), std::sin(phi), 0.0), ephi(-std::sin(phi), std::cos(phi), 0.0);
    X.row(i) += (eps * std::cos(2 * phi) * er - 0.5 * eps * std::sin(2 * phi) * ephi).transpose();
  }
  return X;
}

/// The angular frequency of mode 2 of a thin ring (inextensible, no rotary
/// inertia): ϖ² = EI/(ρA R⁴) · k²(k² − 1)²/(k² + 1) at k = 2.
double ring_mode2_frequency(const RodMaterial& m, double density, double R) {
  const double rhoA = density * M_PI * m.radius * m.radius;
  return std::sqrt(m.bending_stiffness() / (rhoA * std::pow(R, 4))) * 6.0 / std::sqrt(5.0);
}

/// Times where a(t) crosses zero (linear interpolation between frames).
std::vector<double> zero_crossings(const DynamicsResult& r, const Points& R) {
  std::vector<double> t;
  for (size_t k = 1; k < r.frames.size(); ++k) {
    const double a0 = mode2(r.frames[k - 1].positions, R), a1 = mode2(r.frames[k].positions, R);
    if ((a0 > 0) != (a1 > 0)) t.push_back(r.frames[k - 1].time + (r.frames[k].time - r.frames[k - 1].time) * a0 / (a0 - a1));
  }
  return t;
}

}  // namespace

TEST(Dynamics, LumpedMassesAreTheWiresMass) {
  const VecX rest = (VecX(4) << 1.0, 2.0, 3.0, 4.0).finished();
  const VecX m = lumped_masses(rest, 2.0, 0.5);
  const double rhoA = 2.0 * M_PI * 0.25;
  EXPECT_NEAR(m(0), rhoA * 2.5, 1e-14);  // (4 + 1)/2
  EXPECT_NEAR(m(2), rhoA * 2.5, 1e-14);  // (2 + 3)/2
  EXPECT_NEAR(m.sum(), rhoA * rest.sum(), 1e-12);
}

TEST(Dynamics, InertiaTermMatchesFiniteDifferences) {
  const int n = 12;
  const Points x0 = fixtures::unit_ring(n), v = fixtures::random_fourier_curve(n, 3, 7, 0.3);
  InertiaTerm inertia(lumped_masses(VecX::Ones(n), 1.3, 0.2), 0.7, 0.4, Vec3(0.1, -0.2, -9.8));
  inertia.start_step(x0, v);
  const VecX x = as_vector(x0) + 0.05 * as_vector(fixtures::random_fourier_curve(n, 2, 3));
  check_derivatives(inertia, x);
  // At x̂ without damping the gradient vanishes: x̂ = x^t + h v^t + h² g.
  InertiaTerm free_fall(lumped_masses(VecX::Ones(n), 1.0, 0.2), 0.5, 0.0, Vec3(0, 0, -2));
  free_fall.start_step(x0, v);
  Points target = x0 + 0.5 * v;
  target.col(2).array() -= 0.25 * 2.0;
  free_fall.set_dofs(as_vector(target));
  VecX g = VecX::Zero(3 * n);
  free_fall.add_gradient(g);
  EXPECT_LT(g.norm(), 1e-12);
}

TEST(Dynamics, SmoothedFrictionIsC1AndCoulombAboveItsVelocity) {
  const double eps = 0.3;
  EXPECT_NEAR(friction_f0(eps, eps), eps, 1e-15);        // continuous at eps
  EXPECT_NEAR(friction_f1(eps * (1 - 1e-12), eps), 1.0, 1e-9);  // f₁ continuous at eps
  EXPECT_DOUBLE_EQ(friction_f1(0.0, eps), 0.0);
  EXPECT_DOUBLE_EQ(friction_f1(2.0, eps), 1.0);
  for (const double y : {0.01, 0.1, 0.29, 0.5}) {
    const double d = 1e-7;
    EXPECT_NEAR((friction_f0(y + d, eps) - friction_f0(y - d, eps)) / (2 * d), friction_f1(y, eps), 1e-7);
  }
}

TEST(Dynamics, FrictionTermMatchesFiniteDifferencesAndIsConvex) {
  // Two crossing edge pairs of a small curve plus a plate contact; slow
  // (|u| < ε_v h) and sliding (|u| > ε_v h) contacts both.
  const int n = 8;
  const Points start = fixtures::random_fourier_curve(n, 2, 11);
  std::vector<FrictionContact> contacts(3);
  contacts[0].vertices = {0, 1, 4, 5};
  contacts[0].weights = {0.7, 0.3, -0.4, -0.6};
  contacts[0].normal = Vec3(1, 2, 2) / 3.0;
  contacts[0].normal_force = 2.0;
  contacts[1].vertices = {2, 3, 6, 7};
  contacts[1].weights = {0.5, 0.5, -0.1, -0.9};
  contacts[1].normal = Vec3(0, 0.6, 0.8);
  contacts[1].normal_force = 0.5;
  contacts[2].vertices = {3, -1, -1, -1};
  contacts[2].weights = {1, 0, 0, 0};
  contacts[2].normal = Vec3::UnitZ();
  contacts[2].normal_force = 1.5;
  for (const double scale : {0.01, 1.0}) {  // eps = 0.05: the slow and the sliding regime
    FrictionTerm friction(0.4, 0.05, start, contacts);
    const VecX x = as_vector(start) + scale * as_vector(fixtures::random_fourier_curve(n, 2, 5, 0.1));
    check_derivatives(friction, x, 1e-7);
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(dense_hessian(friction, x));
    EXPECT_GT(eig.eigenvalues().minCoeff(), -1e-10);
  }
}

TEST(Dynamics, FrictionForceIsMuLambdaAgainstTheSlip) {
  // One plate contact sliding by u: −∇D = −μλ u/|u| (sliding regime).
  const Points start = fixtures::unit_ring(4);
  std::vector<FrictionContact> contacts(1);
  contacts[0].vertices = {2, -1, -1, -1};
  contacts[0].weights = {1, 0, 0, 0};
  contacts[0].normal_force = 3.0;
  FrictionTerm friction(0.25, 1e-3, start, contacts);
  VecX x = as_vector(start);
  x.segment<3>(6) += Vec3(0.3, 0.4, 0.7);  // the normal component does not count
  friction.set_dofs(x);
  VecX g = VecX::Zero(12);
  friction.add_gradient(g);
  EXPECT_LT((g.segment<3>(6) - 0.25 * 3.0 * Vec3(0.6, 0.8, 0.0)).norm(), 1e-12);
  EXPECT_NEAR(friction.energy(), 0.25 * 3.0 * 0.5, 1e-12);
}

TEST(Dynamics, RingOscillatesAtItsInPlaneBendingFrequency) {
  const int n = 40;
  DynamicsOptions o;
  const double R = 0.5 / std::sin(M_PI / n);
  const double w = ring_mode2_frequency(o.model.material, o.density, R), period = 2 * M_PI / w;
  o.time_step = period / 200;
  o.duration = 2.2 * period;
  o.frame_every = 1;
  const DynamicsResult r = simulate(ring_mode2(n, 1e-3 * R), VecX::Ones(n), o);
  ASSERT_EQ(r.status, DynamicsStatus::Duration);
  const std::vector<double> t = zero_crossings(r, fixtures::unit_ring(n));
  ASSERT_GE(t.size(), 4u);
  const double measured = 2.0 * (t.back() - t.front()) / static_cast<double>(t.size() - 1);
  // [2%] the discrete ring against the thin-ring formula (discretisation
  // O((2π/n)²), backward Euler's period error (ϖh)²/3 ≈ 3e-4).
  EXPECT_NEAR(measured / period, 1.0, 0.02) << "period " << measured << " expected " << period;
}

TEST(Dynamics, BackwardEulerDissipatesAtFirstOrderInTheTimeStep) {
  const int n = 40;
  const double R = 0.5 / std::sin(M_PI / n);
  const Points start = ring_mode2(n, 1e-3 * R);
  DynamicsOptions o;
  const double w = ring_mode2_frequency(o.model.material, o.density, R), period = 2 * M_PI / w;
  CurveEnergyOptions eo;
  eo.rest_length = 1.0;
  const double base = curve_energy(fixtures::unit_ring(n), eo).energy.total;  // the unperturbed ring's bending energy
  std::vector<double> lost;
  for (const double steps : {100.0, 200.0}) {
    o.time_step = period / steps;
    o.duration = period;
    const DynamicsResult r = simulate(start, VecX::Ones(n), o);
    ASSERT_EQ(r.status, DynamicsStatus::Duration);
    const double e0 = total(r.frames.front()) - base, e1 = total(r.frames.back()) - base;
    ASSERT_GT(e0, 0.0);
    lost.push_back(1.0 - e1 / e0);
    // [15%] the share lost against a mode of frequency ϖ: 1 − (1 + ϖ²h²)^(−T/h)
    const double h = o.time_step;
    EXPECT_NEAR(lost.back(), 1.0 - std::pow(1.0 + w * w * h * h, -period / h), 0.15 * lost.back());
  }
  EXPECT_NEAR(lost[0] / lost[1], 1.8, 0.2);  // first order: halving h about halves the loss
}

TEST(Dynamics, UniformMotionIsExact) {
  const int n = 20;
  DynamicsOptions o;
  o.time_step = 0.5;
  o.duration = 10.0;
  const Points v = Points::Constant(n, 3, 0.0).rowwise() + Eigen::RowVector3d(0.3, -0.1, 0.2);
  const DynamicsResult r = simulate(fixtures::unit_ring(n), VecX::Ones(n), o, v);
  EXPECT_LT((r.positions - (fixtures::unit_ring(n) + 10.0 * v)).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_LT((r.velocities - v).cwiseAbs().maxCoeff(), 1e-9);
}

namespace {

/// A ring lying on the lower plate of the envelope |z| < H under gravity g:
/// its height where the plate's barrier carries each vertex's weight.
struct Floor {
  SlabOptions plates;
  double z = 0.0;
};
Floor floor_for(double mass, double g) {
  Floor f;
  f.plates.half_thickness = 2.0;
  f.plates.activation = 0.5;
  const double dhat = f.plates.activation * f.plates.half_thickness;
  double lo = 1e-6, hi = dhat;  // κ|b'(d)| = m g, decreasing in d
  for (int k = 0; k < 200; ++k) {
    const double d = 0.5 * (lo + hi);
    (f.plates.stiffness * std::abs(barrier_first_derivative(d, dhat)) > mass * g ? lo : hi) = d;
  }
  f.z = -f.plates.half_thickness + 0.5 * (lo + hi);
  return f;
}

double mean_x(const Points& P) { return P.col(0).mean(); }

}  // namespace

TEST(Dynamics, RingSlidingOnAPlateStopsAtTheCoulombDistance) {
  const int n = 24;
  const double g = 1.0, v0 = 1.0;
  DynamicsOptions o;
  const double mass = lumped_masses(VecX::Ones(n), o.density, o.model.material.radius)(0);
  const Floor f = floor_for(mass, g);
  o.envelope = f.plates;
  o.gravity = Vec3(0, 0, -g);
  o.time_step = 0.01;
  const Points start = fixtures::unit_ring(n, f.z);
  const Points v = Points::Constant(n, 3, 0.0).rowwise() + Eigen::RowVector3d(v0, 0, 0);
  for (const double mu : {0.2, 0.4}) {
    o.friction = mu;
    o.duration = 2.0 * v0 / (mu * g);
    o.rest_speed = 1e-6;
    const DynamicsResult r = simulate(start, VecX::Ones(n), o, v);
    ASSERT_EQ(r.status, DynamicsStatus::Rest) << "mu " << mu;
    // [0.1%] v²/(2μg) less backward Euler's v h/2 (each step moves by h times the velocity at its end)
    const double distance = v0 * v0 / (2 * mu * g) - v0 * o.time_step / 2;
    EXPECT_NEAR((mean_x(r.positions) - mean_x(start)) / distance, 1.0, 1e-3) << "mu " << mu;
    // [1%] at rest after v/(μg) and the rest_steps that tell it
    EXPECT_NEAR(*r.rest_time / (v0 / (mu * g) + o.rest_steps * o.time_step), 1.0, 0.01) << "mu " << mu;
  }
  o.friction = 0.0;  // no friction: it slides on at v
  o.duration = 10.0;
  const DynamicsResult r = simulate(start, VecX::Ones(n), o, v);
  EXPECT_EQ(r.status, DynamicsStatus::Duration);
  EXPECT_NEAR(mean_x(r.positions) - mean_x(start), v0 * 10.0, 1e-6);
}

// The envelope's plates moving apart at speed s: a ring pushed up against the
// upper plate by gravity follows it, at the distance below the plate
// z = H + s t where the barrier carries its weight (the reach stays fixed).
TEST(Dynamics, RingFollowsTheOpeningEnvelope) {
  const int n = 24;
  const double g = 1.0, speed = 0.05, duration = 20.0;
  DynamicsOptions o;
  const double mass = lumped_masses(VecX::Ones(n), o.density, o.model.material.radius)(0);
  const Floor f = floor_for(mass, g);  // the distance at which a plate's barrier carries the weight
  o.envelope = f.plates;
  o.envelope_speed = speed;
  o.gravity = Vec3(0, 0, g);  // up, onto the upper plate
  o.damping = 1.0;            // no bouncing
  o.time_step = 0.05;
  o.duration = duration;
  const double gap = f.z + f.plates.half_thickness;
  const DynamicsResult r = simulate(fixtures::unit_ring(n, f.plates.half_thickness - gap), VecX::Ones(n), o);
  ASSERT_EQ(r.status, DynamicsStatus::Duration) << (r.failed_status ? to_string(*r.failed_status) : "");
  // [5% of the distance] the viscous drag γ m s takes 5% of the weight off the barrier (measured 0.0045)
  const double plate = f.plates.half_thickness + speed * duration;
  EXPECT_LT(std::abs(r.positions.col(2).mean() - (plate - gap)), 0.05 * gap);
  EXPECT_GT(r.positions.col(2).mean(), f.plates.half_thickness);  // it rose with the plate
}

TEST(Dynamics, StrongDampingEndsAtTheStaticEquilibrium) {
  const Points P = fixtures::torus_knot(60, 2, 3, 6.0, 2.5);
  const VecX rest = edge_lengths(P);  // relax()'s rest lengths
  const RelaxResult eq = relax(P);
  ASSERT_TRUE(eq.stable());
  const Points start = eq.positions + 0.05 * fixtures::random_fourier_curve(60, 3, 21);
  DynamicsOptions o;
  o.damping = 1.0;  // overdamped: every mode creeps back
  o.time_step = 20.0;
  o.duration = 1e5;
  o.rest_speed = 1e-9;
  const DynamicsResult r = simulate(start, rest, o);
  ASSERT_EQ(r.status, DynamicsStatus::Rest);
  EXPECT_TRUE(r.alexander_preserved);
  // [1e-3 RMS, 1e-6 relative energy] the relaxation's equilibrium, after the best rigid motion
  const Points aligned = align_onto(r.positions, eq.positions);
  EXPECT_LT(std::sqrt((aligned - eq.positions).rowwise().squaredNorm().mean()), 1e-3);
  EXPECT_NEAR(r.frames.back().elastic, eq.energy.total, 1e-6 * eq.energy.total);
}

TEST(Dynamics, ViolentMotionKeepsTheKnotType) {
  const Points P = fixtures::torus_knot(60, 2, 3, 6.0, 2.5);
  const RelaxResult eq = relax(P);
  ASSERT_TRUE(eq.stable());
  DynamicsOptions o;
  o.time_step = 0.05;
  o.duration = 5.0;
  o.friction = 0.3;
  const Points v = 3.0 * fixtures::random_fourier_curve(60, 4, 9);  // strands thrown through each other
  const DynamicsResult r = simulate(eq.positions, edge_lengths(P), o, v);
  EXPECT_EQ(r.status, DynamicsStatus::Duration) << (r.failed_status ? to_string(*r.failed_status) : "");
  EXPECT_TRUE(r.alexander_preserved);
  EXPECT_GT(r.max_speed, 1.0);
  int touching = 0;
  for (const DynamicsFrame& f : r.frames) touching = std::max(touching, f.contacts);
  EXPECT_GT(touching, 0);  // the strands did meet
}

TEST(Dynamics, FullModelKeepsItsLink) {
  const int n = 40;
  const double R = 0.5 / std::sin(M_PI / n);
  DynamicsOptions o;
  o.model.link = 1.0;  // below Michell's threshold: the twisted ring stays a ring
  o.time_step = 1.0;
  o.duration = 20.0;
  const DynamicsResult r = simulate(ring_mode2(n, 0.01 * R), VecX::Ones(n), o);
  EXPECT_EQ(r.status, DynamicsStatus::Duration) << (r.failed_status ? to_string(*r.failed_status) : "");
  EXPECT_EQ(r.model, TwistModel::FixedLink);
  EXPECT_NEAR(r.link, 1.0, 1e-6);
}

TEST(Dynamics, BadOptionsAndStartsAreInputErrors) {
  const Points P = fixtures::unit_ring(12);
  const VecX rest = VecX::Ones(12);
  DynamicsOptions o;
  o.time_step = 0.0;
  fixtures::expect_input_error([&] { simulate(P, rest, o); }, "time step");
  o = DynamicsOptions();
  o.friction = -1.0;
  fixtures::expect_input_error([&] { simulate(P, rest, o); }, "friction");
  o = DynamicsOptions();
  o.envelope = SlabOptions();
  o.envelope->half_thickness = 0.1;  // plates thinner than the wire
  fixtures::expect_input_error([&] { simulate(P, rest, o); }, "thickness 2r = 0.4");
  o.envelope->half_thickness = 0.3;
  fixtures::expect_input_error([&] { simulate(fixtures::unit_ring(12, 0.5), rest, o); }, "inside the envelope");
  o = DynamicsOptions();
  fixtures::expect_input_error([&] { simulate(P, rest, o, Points::Zero(3, 3)); }, "velocities");
}
