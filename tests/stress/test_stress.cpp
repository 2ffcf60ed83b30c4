// Numerical stress tests that fit in `make test`: thickness,
// near-contact starts, perturbed equilibria, extreme parameters, and a small
// volume of lattice samples. Pass: no NaN or Inf, no crash, no hang (every run
// ends with a status within its iteration budget), the Alexander polynomial
// always preserved. The counts are printed for the report.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "ek/geometry/polyline.hpp"
#include "ek/geometry/resample.hpp"
#include "ek/knots/alexander.hpp"
#include "ek/lattice/sampling.hpp"
#include "stress_common.hpp"
#include "testing.hpp"

using namespace ek;

namespace {

Points lattice_sample(const std::string& knot, int n, std::uint64_t seed) {
  SampleOptions so;
  so.vertices = n;
  so.count = 1;
  so.seed = seed;
  return to_points(sample_knot(KnotTable::global().at(knot), so).samples.front());
}

}  // namespace

// Wire length / diameter 100, 1,000 and 10,000 (n = 400 unit edges: r = 2, 0.2, 0.02).
TEST(Stress, Thickness) {
  stress::Tally tally;
  for (double ratio : {100.0, 1000.0, 10000.0})
    for (const char* knot : {"3_1", "5_2"}) {
      RelaxOptions o;
      o.material.radius = 400.0 / ratio / 2.0;
      const Points P = lattice_sample(knot, 400, 11);
      const RelaxResult r = relax(P, o);
      tally.add(r, std::string(knot) + " L/d " + std::to_string(ratio));
      // the wire never overlaps itself by more than the barrier allows
      EXPECT_GT(r.min_distance, 0.5 * 2.0 * o.material.radius) << knot << " L/d " << ratio;
    }
  tally.print("thickness");
}

// Non-adjacent segments that start 1e-6·d̂ apart, and exactly parallel
// segments touching the barrier zone.
TEST(Stress, NearContactStarts) {
  stress::Tally tally;
  const double dhat = 0.4;
  // A stadium folded onto itself: two long straight strands at distance
  // 1e-6·d̂ (crossing in projection nowhere: an unknot).
  for (double gap : {1e-6 * dhat, 0.5 * dhat, dhat}) {
    const int m = 40;
    Points P(2 * m + 4, 3);
    int k = 0;
    for (int i = 0; i <= m; ++i) P.row(k++) << i, 0.0, 0.0;
    P.row(k++) << m + 1.0, 0.5 * gap, 0.0;
    for (int i = m; i >= 0; --i) P.row(k++) << i, gap, 0.0;
    P.row(k++) << -1.0, 0.5 * gap, 0.0;
    P.conservativeResize(k, 3);
    RelaxOptions o;
    o.max_iterations = 3000;
    const RelaxResult r = relax(P, o);
    tally.add(r, "parallel strands at gap " + std::to_string(gap));
    EXPECT_GT(r.min_distance, 0.0);
  }
  // A trefoil whose strands are pushed to 1e-6·d̂ at one crossing.
  {
    Points P = fixtures::torus_knot(200, 2, 3, 20.0, 0.3);
    const Clearance c = clearance(P, 5);
    // squeeze the two closest non-neighbouring edges together along z
    const Vec3 a = 0.5 * (P.row(c.edge_a) + P.row((c.edge_a + 1) % 200)).transpose();
    const Vec3 b = 0.5 * (P.row(c.edge_b) + P.row((c.edge_b + 1) % 200)).transpose();
    const double s = (c.distance - 1e-6 * dhat) / c.distance;
    for (int v : {c.edge_a, (c.edge_a + 1) % 200}) P.row(v) += 0.5 * s * (b - a).transpose();
    for (int v : {c.edge_b, (c.edge_b + 1) % 200}) P.row(v) -= 0.5 * s * (b - a).transpose();
    ASSERT_EQ(alexander(P).coefficients, (std::vector<std::int64_t>{1, -1, 1}));
    const RelaxResult r = relax(P);
    tally.add(r, "trefoil squeezed to 1e-6 dhat");
  }
  tally.print("near contact");
}

// Random noise on equilibria: the solver returns to a nearby equilibrium or
// reports why not.
TEST(Stress, PerturbedEquilibria) {
  stress::Tally tally;
  const RelaxResult base = relax(lattice_sample("4_1", 400, 5));
  ASSERT_TRUE(base.stable());
  std::mt19937 rng(3);
  std::normal_distribution<double> N(0.0, 1.0);
  for (double amplitude : {1e-8, 1e-4, 1e-2, 0.1}) {
    Points P = base.positions;
    for (Eigen::Index k = 0; k < P.size(); ++k) P.data()[k] += amplitude * N(rng);
    RelaxOptions o;
    o.rest_lengths = edge_lengths(base.positions);  // same rod
    const RelaxResult r = relax(P, o);
    tally.add(r, "noise " + std::to_string(amplitude));
    if (r.stable() && amplitude <= 1e-4) {
      // small noise: back to the same equilibrium (energy within 1e-6 relative)
      EXPECT_NEAR(r.energy.total, base.energy.total, 1e-6 * base.energy.total) << amplitude;
    }
  }
  tally.print("perturbed equilibria");
}

// Prescribed link up to ±20, E from 1 to 1e9, edges of mixed lengths (ratio 100).
TEST(Stress, ExtremeParameters) {
  stress::Tally tally;
  const Points ring = fixtures::circle(120, 0.5 / std::sin(M_PI / 120));
  for (double lk : {-20.0, -5.0, 5.0, 20.0}) {
    RelaxOptions o;
    o.link = lk;
    o.max_iterations = 3000;
    const RelaxResult r = relax(ring, o);
    tally.add(r, "ring link " + std::to_string(lk));
    EXPECT_NEAR(r.link, lk, 1e-6 * std::max(1.0, std::fabs(lk))) << "link must be preserved";
  }
  const Points P = lattice_sample("3_1", 200, 7);
  for (double E : {1.0, 1e3, 1e6, 1e9}) {
    RelaxOptions o;
    o.material.young = E;
    const RelaxResult r = relax(P, o);
    tally.add(r, "E " + std::to_string(E));
  }
  {
    // mixed edge lengths: along a large trefoil, nine edges of length ~0.1
    // then one of length ~10 (ratio 100), repeated; rest lengths = these
    const Points dense = resample_arclength(fixtures::torus_knot(20000, 2, 3, 60.0, 20.0), 20000);
    const VecX len = edge_lengths(dense);
    std::vector<Vec3> pts;
    double next = 0.0, arc = 0.0;
    int k = 0;
    for (Eigen::Index i = 0; i < dense.rows(); ++i) {
      if (arc >= next) {
        pts.push_back(dense.row(i).transpose());
        next = arc + ((k++ % 10 == 9) ? 10.0 : 0.1);
      }
      arc += len(i);
    }
    Points M(static_cast<Eigen::Index>(pts.size()), 3);
    for (size_t i = 0; i < pts.size(); ++i) M.row(static_cast<Eigen::Index>(i)) = pts[i].transpose();
    const VecX ml = edge_lengths(M);
    EXPECT_GT(ml.maxCoeff() / ml.minCoeff(), 50.0);
    RelaxOptions o;
    o.max_iterations = 4000;
    const RelaxResult r = relax(M, o);
    tally.add(r, "mixed edge lengths (ratio 100)");
  }
  tally.print("extremes");
}

// A small volume of lattice samples over knots up to 12 crossings (the
// 1,000 and 10,000 volumes are in test_stress_long: `make stress`).
TEST(Stress, SmallVolume) {
  stress::Tally tally;
  const auto& table = KnotTable::global();
  const std::vector<std::string> names = {"3_1", "5_1", "6_2", "7_4", "8_19", "9_40", "10_100", "11a_1", "12a_1019",
                                          "12n_838"};
  for (size_t k = 0; k < names.size(); ++k)
    for (int s = 0; s < 3; ++s) {
      const Points P = lattice_sample(names[k], 400, 100 + s);
      const RelaxResult r = relax(P);
      tally.add(r, names[k] + " sample " + std::to_string(s));
    }
  (void)table;
  tally.print("small volume (30 samples, n = 400)");
  EXPECT_EQ(tally.topology_changes, 0);
}
