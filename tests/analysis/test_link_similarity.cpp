// Link similarity (best pairing of components) on links with known answers:
// the Borromean rings as three ellipses against themselves (1, identity
// pairing, placement 0), against a renumbered, re-indexed and rotated copy (1,
// the renumbering found), against a copy with one ring moved away (1, the
// placement sees it); a (2, 4) torus link against its mirror image (below 1,
// and 1 as a whole mirror image when mirror images count); links of
// different component counts refused.
#include <gtest/gtest.h>

#include <cmath>

#include "ek/analysis/link_similarity.hpp"
#include "ek/core/errors.hpp"

using namespace ek;

namespace {

Points ellipse(const Vec3& u, const Vec3& v, double a, double b, int n = 96) {
  Points P(n, 3);
  for (int i = 0; i < n; ++i) {
    const double s = 2.0 * M_PI * i / n;
    P.row(i) = (a * std::cos(s) * u + b * std::sin(s) * v).transpose();
  }
  return P;
}

Link borromean() {
  const Vec3 x = Vec3::UnitX(), y = Vec3::UnitY(), z = Vec3::UnitZ();
  return {ellipse(x, y, 2.0, 1.0), ellipse(y, z, 2.0, 1.2), ellipse(z, x, 2.0, 1.4)};
}

Points torus_component(int j, int n = 160) {
  Points P(n, 3);
  for (int i = 0; i < n; ++i) {
    const double s = 2.0 * M_PI * i / n, psi = 2 * s + M_PI * j;
    const double r = 2.0 + 0.7 * std::cos(psi);
    P.row(i) << r * std::cos(s), r * std::sin(s), 0.7 * std::sin(psi);
  }
  return P;
}

Points shifted_rows(const Points& P, int k) {
  Points Q(P.rows(), 3);
  for (Eigen::Index i = 0; i < P.rows(); ++i) Q.row(i) = P.row((i + k) % P.rows());
  return Q;
}

}  // namespace

TEST(LinkSimilarity, ALinkAgainstItselfAndARenumberedRotatedCopy) {
  const Link b = borromean();
  const LinkSimilarityResult self = compare_links(b, b);
  EXPECT_NEAR(self.similarity, 1.0, 1e-12);
  EXPECT_EQ(self.pairing, (std::vector<int>{0, 1, 2}));
  EXPECT_NEAR(self.placement, 0.0, 1e-12);
  const Mat3 R = Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, 3.0).normalized()).toRotationMatrix();
  Link copy{shifted_rows(b[2], 17), shifted_rows(b[0], 5), shifted_rows(b[1], 40)};
  for (Points& P : copy) P = (P * R.transpose()).rowwise() + Eigen::RowVector3d(3.0, -1.0, 2.0);
  const LinkSimilarityResult r = compare_links(b, copy);
  EXPECT_NEAR(r.similarity, 1.0, 1e-9);
  EXPECT_EQ(r.pairing, (std::vector<int>{1, 2, 0}));  // A's ring 0 is the copy's ring 1, ...
  EXPECT_NEAR(r.placement, 0.0, 1e-9);
}

TEST(LinkSimilarity, PlacementSeesARingMovedAway) {
  const Link b = borromean();
  Link apart = b;
  apart[1].col(0).array() += 20.0;
  const LinkSimilarityResult r = compare_links(b, apart);
  EXPECT_NEAR(r.similarity, 1.0, 1e-12);  // the shapes alone are the same
  EXPECT_GT(r.placement, 1.0);            // 20 lengths away over a mean length of about 10
}

TEST(LinkSimilarity, MirrorImageOnlyWhenAllowed) {
  const Link t{torus_component(0), torus_component(1)};
  Link mirror = t;
  for (Points& P : mirror) P.col(2) *= -1.0;
  const LinkSimilarityResult plain = compare_links(t, mirror);
  EXPECT_LT(plain.similarity, 0.95);
  SimilarityOptions o;
  o.mirror = true;
  const LinkSimilarityResult with = compare_links(t, mirror, o);
  EXPECT_NEAR(with.similarity, 1.0, 1e-9);
  EXPECT_TRUE(with.mirrored);
}

TEST(LinkSimilarity, DifferentComponentCountsAreBadInput) {
  const Link b = borromean();
  EXPECT_THROW(compare_links(b, Link{b[0], b[1]}), InputError);
}
