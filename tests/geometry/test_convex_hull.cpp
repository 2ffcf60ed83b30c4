// The convex hull's boundary points (Qhull): known answers on a cube with
// points on its faces, edges and inside, on a sphere and on degenerate input;
// and the property the minimal bounding box relies on: along any direction
// the extremes of the boundary points are those of all points, to the last bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <random>

#include "ek/geometry/convex_hull.hpp"
#include "ek/geometry/curve_io.hpp"
#include "testing.hpp"

using namespace ek;

namespace {

bool contains(const std::vector<Eigen::Index>& v, Eigen::Index i) { return std::binary_search(v.begin(), v.end(), i); }

std::vector<Eigen::Index> all_of(Eigen::Index n) {
  std::vector<Eigen::Index> v;
  for (Eigen::Index i = 0; i < n; ++i) v.push_back(i);
  return v;
}

/// Extremes along 500 random directions: the same doubles from the subset as from all points.
void expect_same_extremes(const Points& P, const std::vector<Eigen::Index>& S, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> N;
  for (int k = 0; k < 500; ++k) {
    const Vec3 u = Vec3(N(rng), N(rng), N(rng)).normalized();
    double lo = std::numeric_limits<double>::infinity(), hi = -lo, slo = lo, shi = -lo;
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
      const double h = u.dot(P.row(i).transpose());
      lo = std::min(lo, h);
      hi = std::max(hi, h);
    }
    for (const Eigen::Index i : S) {
      const double h = u.dot(P.row(i).transpose());
      slo = std::min(slo, h);
      shi = std::max(shi, h);
    }
    ASSERT_EQ(slo, lo) << "direction " << k;
    ASSERT_EQ(shi, hi) << "direction " << k;
  }
}

}  // namespace

TEST(ConvexHull, CubeKeepsCornersFacesAndEdgesAndDropsTheInside) {
  // corners 0-7, then the face centres, the edge midpoints, then interior points
  std::vector<Vec3> pts;
  for (int c = 0; c < 8; ++c) pts.emplace_back(c & 1, (c >> 1) & 1, (c >> 2) & 1);
  for (int a = 0; a < 3; ++a)
    for (double s : {0.0, 1.0}) {
      Vec3 f = Vec3::Constant(0.5);
      f(a) = s;
      pts.push_back(f);
    }
  for (int a = 0; a < 3; ++a)
    for (double s : {0.0, 1.0})
      for (double t : {0.0, 1.0}) {
        Vec3 e = Vec3::Constant(0.5);
        e((a + 1) % 3) = s;
        e((a + 2) % 3) = t;
        pts.push_back(e);
      }
  const size_t boundary = pts.size();  // 8 + 6 + 12
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> U(0.05, 0.95);
  for (int k = 0; k < 200; ++k) pts.emplace_back(U(rng), U(rng), U(rng));
  Points P(static_cast<Eigen::Index>(pts.size()), 3);
  for (size_t i = 0; i < pts.size(); ++i) P.row(static_cast<Eigen::Index>(i)) = pts[i].transpose();
  const Points Q = fixtures::rigid_copy(P, fixtures::random_rotation(4), Vec3(2, -1, 3), 0);
  for (const Points* X : std::initializer_list<const Points*>{&P, &Q}) {
    const std::vector<Eigen::Index> S = convex_hull_boundary_points(*X);
    ASSERT_TRUE(std::is_sorted(S.begin(), S.end()));
    for (Eigen::Index i = 0; i < static_cast<Eigen::Index>(boundary); ++i) EXPECT_TRUE(contains(S, i)) << i;
    EXPECT_EQ(S.size(), boundary);  // none of the 200 interior points
    expect_same_extremes(*X, S, 5);
  }
}

TEST(ConvexHull, EveryPointOfASphereIsOnTheBoundary) {
  std::mt19937_64 rng(6);
  std::normal_distribution<double> N;
  Points P(300, 3);
  for (Eigen::Index i = 0; i < P.rows(); ++i) P.row(i) = Vec3(N(rng), N(rng), N(rng)).normalized().transpose();
  EXPECT_EQ(convex_hull_boundary_points(P), all_of(P.rows()));
}

TEST(ConvexHull, DegenerateInputKeepsEveryPoint) {
  EXPECT_EQ(convex_hull_boundary_points(fixtures::circle(50, 1.0)), all_of(50));  // flat
  Points line(20, 3);
  for (Eigen::Index i = 0; i < 20; ++i) line.row(i) << 0.1 * static_cast<double>(i), 0.2 * static_cast<double>(i), 1.0;
  EXPECT_EQ(convex_hull_boundary_points(line), all_of(20));
  Points few(4, 3);
  few << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  EXPECT_EQ(convex_hull_boundary_points(few), all_of(4));
  Points bad = fixtures::random_fourier_curve(30, 3, 1);
  bad(7, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(convex_hull_boundary_points(bad), all_of(30));
  EXPECT_TRUE(convex_hull_boundary_points(Points(0, 3)).empty());
}

TEST(ConvexHull, ExtremesOfTheBoundaryAreThoseOfEveryPoint) {
  // smooth curves, a torus knot, integer lattice points (many coplanar and
  // collinear ones) and the peer's relaxed and lattice curves
  std::vector<Points> curves;
  for (std::uint64_t seed = 1; seed <= 4; ++seed) curves.push_back(fixtures::random_fourier_curve(400, 4, seed));
  curves.push_back(fixtures::torus_knot(300, 2, 3));
  curves.push_back(fixtures::random_lattice_walk(600, 8));
  for (const char* name : {"4_1-smooth.obj", "12n_838-braid.obj", "9_47-cubiclattice.txt"})
    curves.push_back(read_curve(fixtures::peer_dir() + "/" + name));
  for (size_t c = 0; c < curves.size(); ++c) {
    const std::vector<Eigen::Index> S = convex_hull_boundary_points(curves[c]);
    EXPECT_LT(S.size(), static_cast<size_t>(curves[c].rows())) << c;  // something is left out
    expect_same_extremes(curves[c], S, 10 + c);
  }
}
