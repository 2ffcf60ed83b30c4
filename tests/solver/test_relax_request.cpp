// RelaxRequest (the options of `knots relax` and of the Python relax()) and
// curve_energy (`knots energy`): the options they make, their errors, and
// energies with known values.
#include <gtest/gtest.h>

#include <cmath>

#include "ek/core/errors.hpp"
#include "ek/solver/energy.hpp"
#include "ek/solver/relax_request.hpp"
#include "testing.hpp"

using namespace ek;

namespace {

/// The message of the InputError that `f` throws ("" when it throws none).
template <typename F>
std::string input_error(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(RelaxRequest, DefaultsAreTheLibraryDefaults) {
  const RelaxOptions o = RelaxRequest{}.options();
  const RelaxOptions d;
  EXPECT_EQ(o.method, RelaxMethod::Multilevel);
  EXPECT_EQ(o.tolerance, d.tolerance);
  EXPECT_EQ(o.max_iterations, d.max_iterations);
  EXPECT_EQ(o.material.radius, d.material.radius);
  EXPECT_EQ(o.material.young, d.material.young);
  EXPECT_EQ(o.material.poisson, d.material.poisson);
  EXPECT_EQ(o.contact_stiffness, d.contact_stiffness);
  EXPECT_EQ(o.coarse_levels, d.coarse_levels);
  EXPECT_EQ(o.newton.cholesky.mode, d.newton.cholesky.mode);
  EXPECT_EQ(o.newton.hessian, d.newton.hessian);
  EXPECT_FALSE(o.link || o.slab || o.release_slab || o.full_model || o.smallest_eigenvalue);
  EXPECT_TRUE(o.contact_continuation.empty());
}

TEST(RelaxRequest, EveryOptionReachesTheRelaxOptions) {
  RelaxRequest q;
  q.link = 2.5;
  q.planar = 0.75;
  q.release = true;
  q.tol = 1e-7;
  q.max_iter = 123;
  q.radius = 0.3;
  q.young = 1000.0;
  q.poisson = 0.4;
  q.contact_stiffness = 50.0;
  q.continuation = {1e-3, 1e-1};
  q.full_model = true;
  q.method = "exact";
  q.coarse_levels = 2;
  q.factorization = "cholmod";
  q.eigen = true;
  q.stop_at_saddle = true;
  q.trace = true;
  const RelaxOptions o = q.options();
  EXPECT_EQ(o.link, 2.5);
  ASSERT_TRUE(o.slab);
  EXPECT_EQ(o.slab->half_thickness, 0.75);
  EXPECT_TRUE(o.release_slab);
  EXPECT_EQ(o.tolerance, 1e-7);
  EXPECT_EQ(o.max_iterations, 123);
  EXPECT_EQ(o.material.radius, 0.3);
  EXPECT_EQ(o.material.young, 1000.0);
  EXPECT_EQ(o.material.poisson, 0.4);
  EXPECT_EQ(o.contact_stiffness, 50.0);
  EXPECT_EQ(o.contact_continuation, (std::vector<double>{1e-3, 1e-1}));
  EXPECT_TRUE(o.full_model);
  EXPECT_EQ(o.method, RelaxMethod::Direct);
  EXPECT_EQ(o.newton.hessian, HessianMode::Exact);
  EXPECT_EQ(o.coarse_levels, 2);
  EXPECT_EQ(o.newton.cholesky.mode, CholeskyMode::Simplicial);
  EXPECT_TRUE(o.smallest_eigenvalue);
  EXPECT_TRUE(o.stop_at_critical_point);
  EXPECT_TRUE(o.newton.record_trace);
  RelaxRequest paper;
  paper.method = "paper";
  paper.trace = true;
  EXPECT_TRUE(paper.options().newton.record_trace);  // the named method keeps the trace setting
}

TEST(RelaxRequest, BadValuesAreInputErrorsNamingTheOption) {
  auto with = [](auto set) {
    RelaxRequest q;
    set(q);
    return input_error([&] { q.options(); });
  };
  EXPECT_EQ(with([](RelaxRequest& q) { q.release = true; }), "--release needs --planar H");
  EXPECT_EQ(with([](RelaxRequest& q) { q.factorization = "lu"; }), "--factorization must be block or cholmod, not 'lu'");
  EXPECT_NE(with([](RelaxRequest& q) { q.method = "fast"; }).find("'fast'"), std::string::npos);
  EXPECT_NE(with([](RelaxRequest& q) { q.continuation = {1.5}; }).find("(0, 1)"), std::string::npos);
  EXPECT_NE(with([](RelaxRequest& q) { q.radius = -1.0; }), "");
  EXPECT_NE(with([](RelaxRequest& q) { q.coarse_levels = 9; }), "");
  EXPECT_EQ(with([](RelaxRequest&) {}), "");
}

TEST(RelaxRequest, TopologyChangeMessage) {
  RelaxResult r;
  EXPECT_EQ(topology_change(r), "");
  r.alexander_preserved = false;
  r.alexander.coefficients = {1, -1, 1};
  r.result_alexander.coefficients = {1};
  EXPECT_EQ(topology_change(r), "the Alexander polynomial changed from [1, -1, 1] to [1]");
}

// A link's message names what changed, in the order of the checks.
TEST(RelaxRequest, LinkTopologyChangeMessage) {
  RelaxResult r;
  r.link_type = LinkType{};
  EXPECT_EQ(topology_change(r), "");
  r.linking_preserved = false;
  EXPECT_EQ(topology_change(r), "a linking number of the link changed");
  EXPECT_EQ(r.status(), RelaxStatus::TopologyChanged);
  r.conway_preserved = false;
  EXPECT_EQ(topology_change(r), "a linking number and the Conway polynomial of the link changed");
  r.alexander_preserved = false;
  EXPECT_EQ(topology_change(r),
            "a component's Alexander polynomial, a linking number and the Conway polynomial of the link changed");
}

// A regular n-gon of unit edges: every turning angle is 2π/n, so
// E_bend = n · EI/2 · (2 tan(π/n))² / 1, and nothing else (no stretching,
// no contact, twist-free).
TEST(CurveEnergy, RegularPolygonHasTheDiscreteBendingEnergy) {
  const int n = 64;
  const double R = 0.5 / std::sin(M_PI / n);  // unit edges
  const Points P = fixtures::circle(n, R);
  const CurveEnergy e = curve_energy(P);
  const double EI = RodMaterial{}.bending_stiffness();
  const double t = std::tan(M_PI / n);
  EXPECT_NEAR(e.energy.bend, n * EI / 2.0 * 4.0 * t * t, 1e-12 * e.energy.bend);
  EXPECT_EQ(e.energy.stretch, 0.0);
  EXPECT_EQ(e.energy.twist, 0.0);
  EXPECT_EQ(e.energy.contact, 0.0);
  EXPECT_EQ(e.contacts, 0);
  EXPECT_EQ(e.energy.total, e.energy.bend);
  EXPECT_EQ(e.model, TwistModel::TwistFree);
  EXPECT_NEAR(e.writhe, 0.0, 1e-12);
  // not an equilibrium: at its own rest lengths the bending energy pushes the polygon outwards
  EXPECT_GT(e.gradient_norm, 0.0);
}

TEST(CurveEnergy, PrescribedLinkAndRestLength) {
  const Points P = fixtures::circle(48, 8.0);
  CurveEnergyOptions o;
  o.link = 1.25;
  const CurveEnergy e = curve_energy(P, o);
  EXPECT_EQ(e.model, TwistModel::FixedLink);
  EXPECT_NEAR(e.link, 1.25, 1e-12);
  EXPECT_NEAR(e.twist, 1.25, 1e-12);  // a planar circle has no writhe
  // uniform twist density Tw = 1.25 over length L: E_twist = GJ/2 (2π·Tw)² / L
  const double L = 48 * 2.0 * 8.0 * std::sin(M_PI / 48);
  const double GJ = RodMaterial{}.twisting_stiffness();
  EXPECT_NEAR(e.energy.twist, GJ / 2.0 * std::pow(2.0 * M_PI * 1.25, 2) / L, 1e-9 * e.energy.twist);
  CurveEnergyOptions s;
  s.rest_length = 1.0;
  const double edge = 2.0 * 8.0 * std::sin(M_PI / 48);
  const double EA = RodMaterial{}.stretching_stiffness();
  const double stretch = 48 * EA / 2.0 * (edge - 1.0) * (edge - 1.0);
  EXPECT_NEAR(curve_energy(P, s).energy.stretch, stretch, 1e-12 * stretch);
  CurveEnergyOptions bad;
  bad.rest_length = 0.0;
  EXPECT_EQ(input_error([&] { curve_energy(P, bad); }), "--rest-length must be positive");
}
