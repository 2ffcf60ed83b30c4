#include <gtest/gtest.h>

#include <random>
#include <tuple>

#include "ek/analysis/search.hpp"
#include "ek/core/errors.hpp"
#include "testing.hpp"

using namespace ek;

namespace {

Points add_noise(const Points& P, double sigma, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> G(0.0, sigma);
  Points Q = P;
  for (Eigen::Index i = 0; i < Q.rows(); ++i)
    for (int c = 0; c < 3; ++c) Q(i, c) += G(rng);
  return Q;
}

}  // namespace

TEST(Alignment, RecoversARigidCopy) {
  // a generic curve (no rigid symmetry), so the motion is unique
  const Points P = fixtures::random_fourier_curve(300, 4, 12);
  const Mat3 R = fixtures::random_rotation(21);
  const Vec3 t(4.0, -1.0, 2.5);
  const Points Q = fixtures::rigid_copy(P, R, t, 123);
  // aligning Q onto P: the motion is the inverse of (R, t)
  const Alignment a = align_curves(P, Q);
  EXPECT_LT(a.distance, 1e-6);
  EXPECT_LT((a.rotation - R.transpose()).norm(), 1e-6);
  EXPECT_LT((a.translation + R.transpose() * t).norm(), 1e-5);
  EXPECT_FALSE(a.reversed);
  EXPECT_FALSE(a.mirrored);
  // the aligned copy lies on the query, vertex by vertex after the shift
  const Points moved = (Q * a.rotation.transpose()).rowwise() + a.translation.transpose();
  EXPECT_LT((moved - fixtures::rigid_copy(P, Mat3::Identity(), Vec3::Zero(), 123)).cwiseAbs().maxCoeff(), 1e-5);
  // a symmetric curve (the trefoil torus knot, 3-fold): aligned onto itself
  const Points T = fixtures::torus_knot(300, 2, 3);
  EXPECT_LT(align_curves(T, fixtures::rigid_copy(T, R, t, 77)).distance, 1e-6);
}

TEST(Alignment, ReversalAndMirror) {
  const Points P = fixtures::random_fourier_curve(200, 4, 5);
  const Points Rv = fixtures::rigid_copy(Points(P.colwise().reverse()), fixtures::random_rotation(2), Vec3(1, 0, 0), 30);
  AlignmentOptions o;
  o.reversal = true;
  const Alignment a = align_curves(P, Rv, o);
  EXPECT_LT(a.distance, 1e-6);
  EXPECT_TRUE(a.reversed);
  o.reversal = false;
  const Alignment b = align_curves(P, Rv, o);
  EXPECT_GT(b.distance, 0.1);  // measured 0.35 (the curve's size is ~2)
  // mirror image of a chiral curve
  const Points T = fixtures::torus_knot(200, 2, 3);
  const Points M = fixtures::rigid_copy(fixtures::mirror_x(T), fixtures::random_rotation(3), Vec3(0, 2, 0), 17);
  AlignmentOptions m;
  m.mirror = true;
  const Alignment c = align_curves(T, M, m);
  EXPECT_LT(c.distance, 1e-6);
  EXPECT_TRUE(c.mirrored);
  // aligned_candidate applies the symmetry and the motion: it lies on the query
  // (Hausdorff-close, vertex by vertex up to the cyclic shift)
  for (const auto& [query, cand, al] : {std::tuple{P, Rv, a}, std::tuple{T, M, c}}) {
    const Points moved = aligned_candidate(cand, al);
    double worst = 0.0;
    for (Eigen::Index i = 0; i < moved.rows(); ++i) {
      double best = 1e300;
      for (Eigen::Index j = 0; j < query.rows(); ++j) best = std::min(best, (moved.row(i) - query.row(j)).norm());
      worst = std::max(worst, best);
    }
    EXPECT_LT(worst, 1e-5);
  }
  const Alignment d = align_curves(T, M);
  EXPECT_GT(d.distance, 0.05);  // the mirror trefoil cannot be aligned rigidly
  EXPECT_FALSE(d.mirrored);
}

TEST(Search, NoisyRigidCopyRanksFirst) {
  const Points query = fixtures::torus_knot(400, 2, 3);
  std::vector<Points> candidates;
  candidates.push_back(fixtures::torus_knot(400, 2, 5));
  candidates.push_back(fixtures::torus_knot(400, 3, 2, 2.0, 0.5));
  for (std::uint64_t s = 1; s <= 5; ++s) candidates.push_back(fixtures::random_fourier_curve(350, 3, s, 2.0));
  candidates.push_back(fixtures::circle(300, 2.5));
  // the copy: another vertex count, rotated, translated, re-indexed, with noise
  const int copy_index = 4;
  candidates.insert(candidates.begin() + copy_index,
                    add_noise(fixtures::rigid_copy(fixtures::torus_knot(500, 2, 3), fixtures::random_rotation(7),
                                                   Vec3(10, 20, -5), 211),
                              0.01, 3));
  const std::vector<SearchHit> hits = search_similar(query, candidates, {});
  ASSERT_EQ(hits.size(), std::min<size_t>(10, candidates.size()));
  EXPECT_EQ(hits[0].index, copy_index);
  EXPECT_LT(hits[0].distance, 0.03);  // noise 0.01 per coordinate
  EXPECT_GT(hits[1].distance, 3 * hits[0].distance);
  for (size_t k = 1; k < hits.size(); ++k) EXPECT_GE(hits[k].distance, hits[k - 1].distance);

  // pre-filter by attributes around the query (noise-robust ones: the vertex noise
  // multiplies the total curvature): the copy passes, the circle does not
  const Attributes qa = compute_attributes(query);
  SearchOptions so;
  so.filters = ranges_around(qa, {"threedim", "diameter"}, 0.1);
  so.max_results = 0;
  const std::vector<SearchHit> filtered = search_similar(query, candidates, {}, so);
  ASSERT_FALSE(filtered.empty());
  EXPECT_EQ(filtered[0].index, copy_index);
  for (const SearchHit& h : filtered) EXPECT_NE(h.index, static_cast<int>(candidates.size()) - 1);
  EXPECT_LT(filtered.size(), candidates.size());
  // precomputed attributes give the same result; a filter that excludes the copy removes it
  std::vector<Attributes> attrs;
  for (const Points& c : candidates) attrs.push_back(compute_attributes(c));
  EXPECT_EQ(search_similar(query, candidates, attrs, so).size(), filtered.size());
  so.filters = {{"threedim", 0.0, 0.5 * qa.geometric.threedim}};
  for (const SearchHit& h : search_similar(query, candidates, attrs, so)) EXPECT_NE(h.index, copy_index);
}

TEST(Search, FiltersAndMisuse) {
  Attributes a;
  a.geometric.threedim = 0.3;
  EXPECT_TRUE(passes_filters(a, {{"threedim", 0.2, 0.4}}));
  EXPECT_TRUE(passes_filters(a, {{"threedim", 0.3, 0.3}}));  // closed range
  EXPECT_FALSE(passes_filters(a, {{"threedim", 0.31}}));
  EXPECT_FALSE(passes_filters(a, {{"energy", -1e300, 1e300}}));  // unset attribute: excluded
  EXPECT_THROW(passes_filters(a, {{"bogus", 0.0, 1.0}}), InputError);
  const std::vector<AttributeRange> r = ranges_around(a, {"threedim"}, 0.1, 0.05);
  EXPECT_NEAR(r[0].min, 0.25, 1e-15);  // absolute width 0.05 > 10% of 0.3
  EXPECT_NEAR(r[0].max, 0.35, 1e-15);
  EXPECT_THROW(ranges_around(a, {"energy"}, 0.1), std::invalid_argument);
  AlignmentOptions bad;
  bad.samples = 3;
  EXPECT_THROW(align_curves(fixtures::circle(10, 1), fixtures::circle(10, 1), bad), std::invalid_argument);
  EXPECT_THROW(search_similar(fixtures::circle(10, 1), {fixtures::circle(10, 1)}, std::vector<Attributes>(2)),
               std::invalid_argument);
}
