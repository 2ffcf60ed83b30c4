// Rotational symmetry, symmetry axes, p-fold averages and crossing p-gons
// (ek/analysis/symmetry.hpp) on curves with known answers: torus knots
// T(s, p) are p-fold symmetric about z and close the braid (σ1···σ_{s-1})^p;
// the flat coil of (σ1σ2⁻¹)^p has its 2p crossings on two rings, rotated by π/p.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include "ek/analysis/symmetry.hpp"
#include "ek/geometry/polyline.hpp"
#include "ek/embedding/embedding.hpp"
#include "ek/knots/codes.hpp"
#include "testing.hpp"

using namespace ek;

namespace {

Points rotated(const Points& P, const Mat3& R) { return (P * R.transpose()).eval(); }

/// The flat coil of (σ1σ2⁻¹)^p: a multi-covered circle, n = 100 p.
Points coil(int p) {
  BraidWord w;
  w.strands = 3;
  for (int k = 0; k < p; ++k) w.letters.insert(w.letters.end(), {1, -2});
  EmbeddingOptions o;
  o.vertices = 100 * p;
  o.strand_spacing = 1.0 / (o.vertices / (2.0 * M_PI * 3));
  return embed_braid(w, o).points;
}

}  // namespace

// T(2, 3) (n divisible by 3) maps vertex i onto vertex i + n/3 under the
// rotation by 2π/3 about z: error 0. A 4-fold or 2-fold rotation does not
// map it onto itself: error of order one.
TEST(Symmetry, TorusKnotIsExactlyPFoldSymmetric) {
  const Points P = fixtures::torus_knot(300, 2, 3);
  EXPECT_LT(rotational_symmetry_error(P, Vec3::Zero(), Vec3::UnitZ(), 3), 1e-12);
  EXPECT_GT(rotational_symmetry_error(P, Vec3::Zero(), Vec3::UnitZ(), 4), 0.05);
  EXPECT_GT(rotational_symmetry_error(P, Vec3::Zero(), Vec3::UnitZ(), 2), 0.05);
  // about a wrong axis the 3-fold rotation fails too
  EXPECT_GT(rotational_symmetry_error(P, Vec3::Zero(), Vec3::UnitX(), 3), 0.05);
  // scale-free: the same error for a scaled copy
  const Points Q = 3.0 * fixtures::torus_knot(300, 2, 5);
  EXPECT_NEAR(rotational_symmetry_error(Q, Vec3::Zero(), Vec3::UnitZ(), 4),
              rotational_symmetry_error(Q / 3.0, Vec3::Zero(), Vec3::UnitZ(), 4), 1e-12);
}

// A rigidly moved T(2, 5): the search finds the moved z axis (up to sign)
// and the moved centre, error 0.
TEST(Symmetry, AxisSearchFindsTheRotatedAxis) {
  const Mat3 R = fixtures::random_rotation(7);
  const Vec3 t(0.3, -1.2, 2.0);
  const Points P = (rotated(fixtures::torus_knot(250, 2, 5), R).rowwise() + t.transpose()).eval();
  const SymmetryAxis s = find_symmetry_axis(P, 5);
  EXPECT_LT(s.error, 1e-10);
  EXPECT_NEAR(std::fabs(s.axis.dot(R * Vec3::UnitZ())), 1.0, 1e-12);
  EXPECT_LT((s.center - t).norm(), 1e-12);
}

// The symmetry axis of a p-fold symmetric curve (p >= 2) is one of its
// principal axes, so the search without tilts (max_tilt 0) finds it too; the
// default grid keeps it (its tilts only score worse). Misuse throws.
TEST(Symmetry, AxisSearchOnThePrincipalAxes) {
  const Points T = fixtures::torus_knot(300, 2, 3);
  const double tilt = 0.05;
  const Mat3 R = Eigen::AngleAxisd(tilt, Vec3::UnitX()).toRotationMatrix();
  const Points P = rotated(T, R);
  SymmetryAxisOptions coarse;
  coarse.max_tilt = 0.0;  // principal axes only
  const SymmetryAxis c = find_symmetry_axis(P, 3, coarse);
  EXPECT_LT(c.error, 1e-10);
  EXPECT_NEAR(std::fabs(c.axis.dot(R * Vec3::UnitZ())), 1.0, 1e-12);
  const SymmetryAxis s = find_symmetry_axis(P, 3);
  EXPECT_NEAR(std::fabs(s.axis.dot(R * Vec3::UnitZ())), 1.0, 1e-12);
  EXPECT_THROW(find_symmetry_axis(P, 1), std::invalid_argument);
  SymmetryAxisOptions bad;
  bad.step = 0.0;
  EXPECT_THROW(find_symmetry_axis(P, 3, bad), std::invalid_argument);
}

// The search tries the untilted axes first and stops an axis's error once it
// exceeds the best so far; its answer must be the plain grid scan's (every
// axis in order, rotational_symmetry_error() whole, the first smallest), to
// the last bit: on symmetric, nearly symmetric and asymmetric curves, and on
// a point (every error 0: the first axis of the grid).
TEST(Symmetry, AxisSearchIsThePlainGridScan) {
  auto scan = [](const Points& P, int p, const SymmetryAxisOptions& o) {
    SymmetryAxis out;
    out.center = centroid(P);
    const Mat3 axes = principal_axes(P);
    const int k = static_cast<int>(std::lround(o.max_tilt / o.step));
    out.error = 1e300;
    for (int axis = 0; axis < 3; ++axis) {
      const Vec3 e0 = axes.col(axis), e1 = e0.unitOrthogonal(), e2 = e0.cross(e1);
      for (int i = -k; i <= k; ++i)
        for (int q = -k; q <= k; ++q) {
          const Vec3 ax = (e0 + o.step * i * e1 + o.step * q * e2).normalized();
          const double err = rotational_symmetry_error(P, out.center, ax, p);
          if (err < out.error) {
            out.error = err;
            out.axis = ax;
          }
        }
    }
    return out;
  };
  std::mt19937_64 rng(12);
  std::normal_distribution<double> N(0.0, 0.02);
  Points noisy = fixtures::torus_knot(200, 2, 3);
  for (Eigen::Index i = 0; i < noisy.rows(); ++i) noisy.row(i) += Vec3(N(rng), N(rng), N(rng)).transpose();
  const Points point = Points::Ones(5, 3);
  SymmetryAxisOptions coarse;
  coarse.max_tilt = 0.05;
  coarse.step = 0.01;
  const std::vector<std::pair<Points, int>> cases = {
      {rotated(fixtures::torus_knot(150, 2, 5), fixtures::random_rotation(3)), 5},
      {noisy, 3},
      {fixtures::random_fourier_curve(120, 4, 5), 2},
      {fixtures::random_fourier_curve(120, 4, 6), 3},
      {coil(2), 2},
      {point, 2}};
  for (size_t c = 0; c < cases.size(); ++c)
    for (const SymmetryAxisOptions& o : {coarse, SymmetryAxisOptions{}}) {
      const SymmetryAxis a = find_symmetry_axis(cases[c].first, cases[c].second, o), b = scan(cases[c].first, cases[c].second, o);
      EXPECT_EQ(a.error, b.error) << c;
      EXPECT_EQ(a.axis, b.axis) << c;
      EXPECT_EQ(a.center, b.center) << c;
    }
}

// symmetrize() keeps a symmetric closure of (σ1)^3 on 2 strands (T(2, 3))
// and makes a perturbed one exactly symmetric, moving each vertex by at most
// the perturbation.
TEST(Symmetry, SymmetrizeAveragesThePeriods) {
  const Points T = fixtures::torus_knot(300, 2, 3);
  EXPECT_LT((symmetrize(T, Vec3::Zero(), Vec3::UnitZ(), 3, 2) - T).cwiseAbs().maxCoeff(), 1e-12);
  std::mt19937_64 rng(3);
  std::normal_distribution<double> noise(0.0, 1e-2);
  Points P = T;
  for (Eigen::Index i = 0; i < P.size(); ++i) P.data()[i] += noise(rng);
  const double before = rotational_symmetry_error(P, Vec3::Zero(), Vec3::UnitZ(), 3);
  const Points S = symmetrize(P, Vec3::Zero(), Vec3::UnitZ(), 3, 2);
  EXPECT_GT(before, 1e-3);
  EXPECT_LT(rotational_symmetry_error(S, Vec3::Zero(), Vec3::UnitZ(), 3), 1e-12);
  EXPECT_LT((S - T).rowwise().norm().maxCoeff(), (P - T).rowwise().norm().maxCoeff());
  EXPECT_THROW(symmetrize(fixtures::torus_knot(301, 2, 3), Vec3::Zero(), Vec3::UnitZ(), 3, 2), std::invalid_argument);
}

// Angles of a regular p-gon at phase φ: the fit returns φ (mod 2π/p) and no
// error; one angle moved by δ moves the circular mean of p·θ to
// ψ = atan2(sin pδ, p - 1 + cos pδ)/p, so the largest deviation is δ - ψ.
TEST(Symmetry, RegularPolygonFit) {
  const int p = 5;
  const double phase = 0.3;
  std::vector<double> angles;
  for (int k = 0; k < p; ++k) angles.push_back(phase + 2 * M_PI * k / p + (k == 2 ? 4 * M_PI : 0.0));
  RegularPolygonFit g = fit_regular_polygon(angles, p);
  EXPECT_EQ(g.count, p);
  EXPECT_NEAR(g.phase, phase, 1e-12);
  EXPECT_LT(g.max_error, 1e-10);
  const double d = 0.04;
  angles[1] += d;
  g = fit_regular_polygon(angles, p);
  const double psi = std::atan2(std::sin(p * d), p - 1 + std::cos(p * d)) / p;
  EXPECT_NEAR(g.phase, phase + psi, 1e-12);
  EXPECT_NEAR(g.max_error, (d - psi) * 180 / M_PI, 1e-9);
  EXPECT_EQ(fit_regular_polygon({}, p).count, 0);
}

// The flat coil of (σ1σ2⁻¹)^p: 2p braid crossings, σ1's on one ring and σ2's
// on the other, each a regular p-gon; consecutive letters are π/p apart, so
// the rings are rotated by 180/p degrees. The embedding offsets the strands
// by ±crossing_height = ±0.5 strand spacings (one edge length) at a crossing:
// their gap along the axis is 1 edge length there. (The split by height
// separates the two letters here: their midpoints differ in height.)
TEST(Symmetry, CoilCrossingsFormTwoRotatedPolygons) {
  for (const int p : {2, 4, 5}) {
    const Points P = coil(p);
    const Vec3 c = P.colwise().mean().transpose();
    const CrossingPolygons g = crossing_polygons(P, c, Vec3::UnitZ(), p, 1.1);
    EXPECT_EQ(g.crossings, 2 * p) << p;
    EXPECT_EQ(g.projected, 2 * p) << p;
    EXPECT_EQ(g.top.count, p) << p;
    EXPECT_EQ(g.bottom.count, p) << p;
    EXPECT_LT(g.error(), 1.0) << p;
    EXPECT_NEAR(g.rotation, 180.0 / p, 1.0) << p;
    // a gap below the crossings' 1 edge length keeps none
    EXPECT_EQ(crossing_polygons(P, c, Vec3::UnitZ(), p, 0.9).crossings, 0) << p;
  }
}

// A link's p-fold symmetry: three rings at 120° about z (each ring in a
// vertical plane through the axis, its centre 3 from it) map onto one another
// under the rotation by 2π/3 (error 0 to round-off, with rings of 60
// vertices), not under 2π/4 or 2π/2; the one-component link agrees with the
// curve's error.
TEST(Symmetry, ThreeRingsAboutAnAxisAreThreeFoldSymmetric) {
  Link rings;
  for (int k = 0; k < 3; ++k) {
    const double phi = 2.0 * M_PI * k / 3.0;
    const Vec3 radial(std::cos(phi), std::sin(phi), 0.0);
    Points P(60, 3);
    for (int i = 0; i < 60; ++i) {
      const double t = 2.0 * M_PI * i / 60;
      P.row(i) = (3.0 * radial + std::cos(t) * radial + std::sin(t) * Vec3::UnitZ()).transpose();
    }
    rings.push_back(P);
  }
  EXPECT_LT(rotational_symmetry_error(rings, Vec3::Zero(), Vec3::UnitZ(), 3), 1e-12);
  EXPECT_GT(rotational_symmetry_error(rings, Vec3::Zero(), Vec3::UnitZ(), 4), 0.05);
  EXPECT_GT(rotational_symmetry_error(rings, Vec3::Zero(), Vec3::UnitZ(), 2), 0.05);
  const Points T = fixtures::torus_knot(300, 2, 3);
  EXPECT_EQ(rotational_symmetry_error(Link{T}, Vec3::Zero(), Vec3::UnitZ(), 4),
            rotational_symmetry_error(T, Vec3::Zero(), Vec3::UnitZ(), 4));
}
