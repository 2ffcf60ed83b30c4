// Fitting a curve by k circles: three unit circles in the coordinate planes
// traversed as one closed curve are found exactly; a torus knot, a flat
// triple-covered circle and a two-circle curve are not three intertwined
// circles; rigid motions and re-indexing do not change the fit.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "ek/analysis/circles.hpp"
#include "testing.hpp"

using namespace ek;

namespace {

/// Appends the arc of the circle with centre c and orthonormal in-plane axes
/// (a, b) from angle t0 over `turn` radians, `per_turn` vertices per full turn
/// (the end point excluded).
void arc(std::vector<Vec3>& out, const Vec3& a, const Vec3& b, double t0, double turn, int per_turn,
         double radius = 1.0, const Vec3& c = Vec3::Zero()) {
  const int m = static_cast<int>(std::lround(std::fabs(turn) / (2.0 * M_PI) * per_turn));
  for (int q = 0; q < m; ++q) {
    const double t = t0 + turn * q / m;
    out.push_back(c + radius * (std::cos(t) * a + std::sin(t) * b));
  }
}

Points to_points(const std::vector<Vec3>& v) {
  Points P(static_cast<Eigen::Index>(v.size()), 3);
  for (size_t i = 0; i < v.size(); ++i) P.row(static_cast<Eigen::Index>(i)) = v[i].transpose();
  return P;
}

/// One closed curve over three unit circles in the planes z = 0, y = 0, x = 0:
/// the xy-circle from (1,0,0) all the way round, a quarter of the xz-circle to
/// (0,0,1), the yz-circle all the way round, the other three quarters of the
/// xz-circle back to (1,0,0). 120 vertices per circle.
Points three_circles() {
  std::vector<Vec3> v;
  const Vec3 X = Vec3::UnitX(), Y = Vec3::UnitY(), Z = Vec3::UnitZ();
  arc(v, X, Y, 0.0, 2 * M_PI, 120);
  arc(v, X, Z, 0.0, M_PI / 2, 120);
  arc(v, Z, Y, 0.0, 2 * M_PI, 120);  // from (0,0,1) round the yz-circle
  arc(v, X, Z, M_PI / 2, 3 * M_PI / 2, 120);
  return to_points(v);
}

}  // namespace

TEST(Circles, FindsThreeCirclesInTheCoordinatePlanes) {
  const Points P = three_circles();
  const CircleFit f = fit_circles(P);
  ASSERT_EQ(f.circles.size(), 3u);
  EXPECT_LT(f.rms_distance, 1e-9);
  EXPECT_LT(f.max_distance, 1e-9);
  EXPECT_NEAR(f.mean_radius, 1.0, 1e-9);
  EXPECT_NEAR(f.min_plane_angle, M_PI / 2, 1e-9);
  for (const Circle3& c : f.circles) {
    EXPECT_NEAR(c.radius, 1.0, 1e-9);
    EXPECT_LT(c.center.norm(), 1e-9);
    EXPECT_NEAR(c.normal.cwiseAbs().maxCoeff(), 1.0, 1e-9);  // a coordinate axis
  }
  for (double s : f.share) EXPECT_NEAR(s, 1.0 / 3.0, 0.02);  // vertices on two circles go to either
  EXPECT_TRUE(meets(f));
  // moved and re-indexed: the same fit
  const Points Q = fixtures::rigid_copy(P, fixtures::random_rotation(8), Vec3(3, -1, 2), 101);
  const CircleFit g = fit_circles(Q);
  EXPECT_LT(g.rms_distance, 1e-9);
  EXPECT_NEAR(g.min_plane_angle, M_PI / 2, 1e-9);
  // with noise of 1% of the radius, the RMS distance is about the noise
  Points N = P;
  std::mt19937_64 rng(3);
  std::normal_distribution<double> G(0.0, 0.01);
  for (Eigen::Index i = 0; i < N.rows(); ++i)
    for (int c = 0; c < 3; ++c) N(i, c) += G(rng);
  const CircleFit h = fit_circles(N);
  EXPECT_LT(h.relative_rms(), 0.02);
  EXPECT_GT(h.relative_rms(), 0.003);
  EXPECT_TRUE(meets(h));
}

// Circles of different radii and centres in tilted planes: recovered.
TEST(Circles, RecoversRadiiAndPlanes) {
  std::vector<Vec3> v;
  const Vec3 a1 = Vec3(1, 0, 0), b1 = Vec3(0, 1, 1).normalized();
  const Vec3 a2 = Vec3(1, 0, 0), b2 = Vec3(0, 1, -1).normalized();
  // two circles through the origin's neighbourhood: radius 2 about (0, 2b1) and radius 1 about (0, -b2)
  arc(v, -b1, a1, 0.0, 2 * M_PI, 200, 2.0, 2.0 * b1);
  arc(v, b2, a2, 0.0, 2 * M_PI, 200, 1.0, -1.0 * b2);
  CircleFitOptions o;
  o.circles = 2;
  const CircleFit f = fit_circles(to_points(v), o);
  EXPECT_LT(f.rms_distance, 1e-9);
  // equal shares: either order
  EXPECT_NEAR(std::min(f.circles[0].radius, f.circles[1].radius), 1.0, 1e-9);
  EXPECT_NEAR(std::max(f.circles[0].radius, f.circles[1].radius), 2.0, 1e-9);
  EXPECT_NEAR(f.min_plane_angle, std::acos(std::fabs(b1.cross(a1).normalized().dot(b2.cross(a2).normalized()))), 1e-9);
}

// Not three intertwined circles: a trefoil torus knot (three circles fit
// it with an RMS distance of 0.068 of their radius, above the bound), a
// flat triple-covered circle (three coplanar turns: the planes coincide),
// and two circles fitted with three (one circle carries too little or the
// planes coincide).
TEST(Circles, OtherCurvesFailTheCriterion) {
  const CircleFit torus = fit_circles(fixtures::torus_knot(400, 2, 3));
  EXPECT_NEAR(torus.relative_rms(), 0.068, 0.001);
  EXPECT_FALSE(meets(torus));
  EXPECT_GT(torus.relative_rms(), CircleCriterion{}.max_relative_rms);
  std::vector<Vec3> coil;
  for (int i = 0; i < 600; ++i) {
    const double t = 6.0 * M_PI * i / 600.0, r = 1.0 + 0.02 * std::sin(t / 3.0);
    coil.push_back(Vec3(r * std::cos(t), r * std::sin(t), 0.01 * std::sin(t / 3.0)));
  }
  const CircleFit flat = fit_circles(to_points(coil));
  EXPECT_LT(flat.relative_rms(), 0.05);  // it does lie near circles ...
  EXPECT_LT(flat.min_plane_angle, 0.5);  // ... but all in one plane
  EXPECT_FALSE(meets(flat));
  std::vector<Vec3> two;
  arc(two, Vec3::UnitX(), Vec3::UnitY(), 0.0, 2 * M_PI, 200);
  arc(two, Vec3::UnitX(), Vec3::UnitZ(), 0.0, 2 * M_PI, 200);
  EXPECT_FALSE(meets(fit_circles(to_points(two))));
}

TEST(Circles, MisuseThrows) {
  CircleFitOptions o;
  o.circles = 0;
  EXPECT_THROW(fit_circles(fixtures::circle(40, 1.0), o), std::invalid_argument);
  o = {};
  o.window = 0.5;
  EXPECT_THROW(fit_circles(fixtures::circle(40, 1.0), o), std::invalid_argument);
  EXPECT_THROW(fit_circles(fixtures::circle(8, 1.0)), std::invalid_argument);  // fewer than 4 per circle
}
