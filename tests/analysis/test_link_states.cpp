// The link state distance (distance distributions of the components, best
// pairing) on links with known answers: a round circle's quantile function
// sin(πp/2)/π; zero for a rigid motion, mirror image, renumbering and any
// placement of the same components; the floor left by re-indexing and
// reversal, which move the resampled points;
// a ring against an ellipse; bad input.
#include <gtest/gtest.h>

#include <cmath>

#include "ek/analysis/link_states.hpp"
#include "ek/core/errors.hpp"
#include "testing.hpp"

using namespace ek;
using namespace ek::fixtures;

namespace {

Points ellipse(const Vec3& c, const Vec3& u, const Vec3& v, double a, double b, int n = 200) {
  Points P(n, 3);
  for (int i = 0; i < n; ++i) {
    const double s = 2.0 * M_PI * i / n;
    P.row(i) = (c + a * std::cos(s) * u + b * std::sin(s) * v).transpose();
  }
  return P;
}

Link three_ellipses() {
  const Vec3 x = Vec3::UnitX(), y = Vec3::UnitY(), z = Vec3::UnitZ(), o = Vec3::Zero();
  return {ellipse(o, x, y, 2.0, 1.0), ellipse(o, y, z, 2.0, 1.2), ellipse(o, z, x, 2.0, 1.4)};
}

Points reversed(const Points& P) { return P.colwise().reverse(); }

}  // namespace

TEST(LinkStates, ARoundCircleHasTheChordQuantiles) {
  // Chord of arc separation u on a circle of length L: (L/π) sin(πu/L), u/L
  // uniform on [0, ½], so F⁻¹(p) = sin(πp/2)/π in units of L.
  // q points put the separations on multiples of L/q, a bias below 1/q in
  // u/L; with q = 1024 it is below 1e-3 in the chord.
  LinkShapeOptions o;
  o.samples = 1024;
  o.quantiles = 100;
  const LinkShape s = link_shape({circle(4000, 3.0)}, o);
  ASSERT_EQ(s.components.size(), 1u);
  const Eigen::VectorXd& q = s.components[0];
  ASSERT_EQ(q.size(), 100);
  for (int k = 0; k < q.size(); ++k)
    EXPECT_NEAR(q[k], std::sin(M_PI * (k + 0.5) / 100.0 / 2.0) / M_PI, 1e-3) << "quantile " << k;
}

TEST(LinkStates, RigidMotionMirrorImageAndRenumberingGiveZero) {
  const Link a = three_ellipses();
  const Mat3 R = random_rotation(7);
  Link b{mirror_x(a[2]), mirror_x(a[0]), mirror_x(a[1])};
  for (Points& P : b) P = rigid_copy(P, R, Vec3(4.0, -1.0, 2.0), 0);
  const LinkStateDistance d = link_state_distance(link_shape(a), link_shape(b));
  EXPECT_LT(d.distance, 1e-12);
  EXPECT_EQ(d.pairing, (std::vector<int>{1, 2, 0}));  // A's 0 is B's 1, A's 1 is B's 2, A's 2 is B's 0
}

TEST(LinkStates, PlacementOfTheSameComponentsIsNotSeen) {
  const Link a = three_ellipses();
  Link moved = a;
  moved[1] = rigid_copy(a[1], random_rotation(3), Vec3(10.0, 0.0, 0.0), 0);
  EXPECT_LT(link_state_distance(link_shape(a), link_shape(moved)).distance, 1e-12);
}

TEST(LinkStates, ReIndexingLeavesASmallFloorAndAnEllipseIsFarAboveIt) {
  const Link a = three_ellipses();
  Link shifted = a;
  for (size_t c = 0; c < shifted.size(); ++c)
    shifted[c] = rigid_copy(a[c], Mat3::Identity(), Vec3::Zero(), 37 + 11 * static_cast<int>(c));
  shifted[1] = reversed(shifted[1]);
  const double floor = link_state_distance(link_shape(a), link_shape(shifted)).distance;
  EXPECT_GT(floor, 0.0);
  EXPECT_LT(floor, 2e-4);
  // One ring made rounder (aspect 2.0 : 1.2 against 2.0 : 1.0, same place):
  // the pairing cannot hide it.
  Link rounder = a;
  rounder[0] = ellipse(Vec3::Zero(), Vec3::UnitX(), Vec3::UnitY(), 2.0, 1.2);
  EXPECT_GT(link_state_distance(link_shape(a), link_shape(rounder)).distance, 20 * floor);
}

TEST(LinkStates, SimilarityMatrixIsOneMinusTheDistance) {
  const Link a = three_ellipses();
  Link b = a;
  b[2] = ellipse(Vec3::Zero(), Vec3::UnitZ(), Vec3::UnitX(), 2.0, 1.7);
  const std::vector<LinkShape> shapes{link_shape(a), link_shape(b)};
  const Eigen::MatrixXd s = link_state_similarity_matrix(shapes);
  ASSERT_EQ(s.rows(), 2);
  EXPECT_EQ(s(0, 0), 1.0);
  EXPECT_EQ(s(0, 1), s(1, 0));
  EXPECT_DOUBLE_EQ(s(0, 1), 1.0 - link_state_distance(shapes[0], shapes[1]).distance);
  EXPECT_LT(s(0, 1), 1.0);
}

TEST(LinkStates, BadInputIsRefused) {
  const Link a = three_ellipses();
  const Link two{a[0], a[1]};
  expect_input_error([&] { link_state_distance(link_shape(a), link_shape(two)); }, "different numbers of components");
  LinkShapeOptions o;
  o.quantiles = 64;
  expect_input_error([&] { link_state_distance(link_shape(a), link_shape(a, o)); }, "quantile counts");
  o.samples = 3;
  expect_input_error([&] { link_shape(a, o); }, "at least 4");
  expect_input_error([&] { link_shape({}); }, "at least one component");
}
