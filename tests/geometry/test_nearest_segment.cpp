// The nearest segment through the bounding-sphere tree: known answers, and the
// exact answer of a scan over every segment (same squared distance to the
// last bit, same segment on ties) on smooth curves, lattice polygons (many
// ties), open polylines, links and far-away or degenerate queries.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "ek/geometry/nearest_segment.hpp"
#include "ek/geometry/segment_distance.hpp"
#include "testing.hpp"

using namespace ek;

namespace {

/// The scan the tree replaces: every segment in order, the first at the minimum.
NearestSegmentHit scan(const Link& link, const Vec3& x, bool closed = true) {
  NearestSegmentHit best;
  best.distance_squared = std::numeric_limits<double>::infinity();
  for (size_t c = 0; c < link.size(); ++c) {
    const Points& P = link[c];
    const Eigen::Index n = P.rows(), segments = closed ? n : n - 1;
    for (Eigen::Index j = 0; j < segments; ++j) {
      double t = 0.0;
      const double d2 = point_segment_distance_squared(x, P.row(j).transpose(), P.row((j + 1) % n).transpose(), &t);
      if (d2 < best.distance_squared) best = {d2, static_cast<int>(c), j, t};
    }
  }
  return best;
}

void expect_same(const NearestSegmentHit& tree, const NearestSegmentHit& brute) {
  EXPECT_EQ(tree.distance_squared, brute.distance_squared);
  EXPECT_EQ(tree.component, brute.component);
  EXPECT_EQ(tree.segment, brute.segment);
  EXPECT_EQ(tree.t, brute.t);
}

/// A closed lattice walk: unit steps, so many points are equidistant from several segments.
Points lattice_walk(int half, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<Vec3> steps;
  for (int k = 0; k < half; ++k) {
    Vec3 s = Vec3::Zero();
    s(static_cast<int>(rng() % 3)) = (rng() % 2) ? 1.0 : -1.0;
    steps.push_back(s);
  }
  for (int k = 0; k < half; ++k) steps.push_back(-steps[static_cast<size_t>(k)]);
  std::shuffle(steps.begin(), steps.end(), rng);
  Points P(2 * half, 3);
  Vec3 x = Vec3::Zero();
  for (int k = 0; k < 2 * half; ++k) {
    P.row(k) = x.transpose();
    x += steps[static_cast<size_t>(k)];
  }
  return P;
}

}  // namespace

TEST(NearestSegment, KnownAnswers) {
  const Points square = fixtures::rows3<Points>({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
  const NearestSegment closed(square);
  EXPECT_EQ(closed.size(), 4);
  // the centre is 1/2 from all four sides: the first one wins
  NearestSegmentHit h = closed.nearest(Vec3(0.5, 0.5, 0.0));
  EXPECT_EQ(h.distance_squared, 0.25);
  EXPECT_EQ(h.segment, 0);
  EXPECT_EQ(h.t, 0.5);
  // above the closing side (vertex 3 to vertex 0), 2 away
  h = closed.nearest(Vec3(-2.0, 0.25, 0.0));
  EXPECT_EQ(h.segment, 3);
  EXPECT_DOUBLE_EQ(h.distance_squared, 4.0);
  EXPECT_DOUBLE_EQ(h.t, 0.75);
  // on vertex 0: segments 0 and 3 both touch it, segment 0 comes first
  h = closed.nearest(Vec3::Zero());
  EXPECT_EQ(h.distance_squared, 0.0);
  EXPECT_EQ(h.segment, 0);
  // open: no closing side, so the point left of the square is nearest to vertex 0 of segment 0
  const NearestSegment open(square, false);
  EXPECT_EQ(open.size(), 3);
  h = open.nearest(Vec3(-2.0, 0.25, 0.0));
  EXPECT_EQ(h.segment, 0);
  EXPECT_DOUBLE_EQ(h.distance_squared, 4.0625);
  EXPECT_EQ(h.t, 0.0);
}

TEST(NearestSegment, LinkComponentsAndSegmentsCountFromEachComponent) {
  const Link link = {fixtures::circle(12, Vec3(0, 0, 0), 1.0, Vec3::UnitX(), Vec3::UnitY()),
                     fixtures::circle(12, Vec3(5, 0, 0), 1.0, Vec3::UnitX(), Vec3::UnitY())};
  const NearestSegment tree(link);
  EXPECT_EQ(tree.size(), 24);
  const NearestSegmentHit h = tree.nearest(Vec3(6.5, 0.0, 0.0));
  EXPECT_EQ(h.component, 1);
  EXPECT_LT(h.segment, 12);
  expect_same(h, scan(link, Vec3(6.5, 0.0, 0.0)));
}

TEST(NearestSegment, EqualsTheScanOnSmoothCurvesLatticeWalksAndLinks) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> normal(0.0, 1.0);
  int ties = 0;
  for (int trial = 0; trial < 40; ++trial) {
    Link link;
    const int kind = trial % 3;
    if (kind == 0) link = {fixtures::random_fourier_curve(50 + 37 * trial, 4, 100 + trial)};
    if (kind == 1) link = {lattice_walk(10 + 9 * trial, 200 + trial)};
    if (kind == 2) link = {lattice_walk(12 + trial, 300 + trial), fixtures::random_fourier_curve(40 + trial, 3, 400 + trial)};
    const NearestSegment tree(link);
    double scale = 0.0;
    for (const Points& P : link) scale = std::max(scale, P.cwiseAbs().maxCoeff());
    for (int q = 0; q < 200; ++q) {
      Vec3 x;
      if (q % 4 == 0) {  // a vertex, or a lattice point near the walk (ties)
        const Points& P = link[static_cast<size_t>(q) % link.size()];
        x = P.row(static_cast<Eigen::Index>(rng() % static_cast<std::uint64_t>(P.rows()))).transpose();
        if (q % 8 == 0) x = (x + Vec3(normal(rng), normal(rng), normal(rng))).array().round().matrix();
      } else if (q % 4 == 1) {  // far away
        x = 20.0 * scale * Vec3(normal(rng), normal(rng), normal(rng));
      } else {
        x = scale * Vec3(normal(rng), normal(rng), normal(rng));
      }
      const NearestSegmentHit brute = scan(link, x);
      int at_minimum = 0;
      for (const Points& P : link)
        for (Eigen::Index j = 0; j < P.rows(); ++j)
          at_minimum += point_segment_distance_squared(x, P.row(j).transpose(), P.row((j + 1) % P.rows()).transpose()) ==
                        brute.distance_squared;
      ties += at_minimum > 1;
      expect_same(tree.nearest(x), brute);
    }
  }
  EXPECT_GT(ties, 100);  // the tie rule was exercised
}

TEST(NearestSegment, OpenPolylinesEqualTheScan) {
  for (int trial = 0; trial < 10; ++trial) {
    const Points P = fixtures::random_fourier_curve(30 + 20 * trial, 3, 500 + trial);
    const NearestSegment tree(P, false);
    std::mt19937_64 rng(trial);
    std::normal_distribution<double> normal(0.0, 1.5);
    for (int q = 0; q < 100; ++q) {
      const Vec3 x(normal(rng), normal(rng), normal(rng));
      expect_same(tree.nearest(x), scan({P}, x, false));
    }
  }
}

TEST(NearestSegment, DegenerateInput) {
  // repeated vertices (zero-length segments) are segments like any other
  const Points P = fixtures::rows3<Points>({{0, 0, 0}, {0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {1, 1, 0}});
  const NearestSegment tree(P);
  for (const Vec3& x : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.3, 0.2, 0.1), Vec3(2, 2, 2)})
    expect_same(tree.nearest(x), scan({P}, x));
  // a query that is not finite is nearer to nothing
  EXPECT_EQ(tree.nearest(Vec3(std::nan(""), 0, 0)).distance_squared, std::numeric_limits<double>::infinity());
  EXPECT_THROW(NearestSegment(Points(1, 3)), std::exception);
  EXPECT_THROW(NearestSegment(Link{}), std::exception);
}
