// transition_search() (double-ended): the vertex alignment recovers a moved,
// re-indexed and reversed copy exactly; a copy of A is "same-state"; the
// mirror image of a trefoil (same Alexander polynomial, but no path without
// a strand passage) is never reached; between two relaxed samples of 4_1
// that a single-ended search joins, the double-ended search reaches B and
// every verified saddle passes the checks again on its own.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "ek/analysis/similarity.hpp"
#include "ek/core/errors.hpp"
#include "ek/knots/alexander.hpp"
#include "ek/knots/table.hpp"
#include "ek/lattice/lattice_polygon.hpp"
#include "ek/lattice/sampling.hpp"
#include "ek/transitions/double_ended.hpp"
#include "testing.hpp"
#include "transitions_test_util.hpp"

using namespace ek;
using namespace ek::transitionstest;

namespace {

/// The stable states of `count` BFACF samples of a knot (seed 1, unit edges),
/// relaxed by the eigen-projected method: the Gauss–Newton default reaches
/// the same states of 4_1 (energies 2.70252 and 2.70296 for samples 1 and 2)
/// at positions that differ within the tolerance, and the double-ended search
/// between these two is sensitive to that much (from the default's positions
/// its saddle descends to other minima), so the inputs are pinned.
std::vector<Points> relaxed_samples(const std::string& knot, int count) {
  SampleOptions so;
  so.vertices = kVertices;
  so.count = count;
  const SampleBatch batch = sample_knot(KnotTable::global().at(knot), so);
  std::vector<Points> s;
  for (const auto& p : batch.samples) {
    const RelaxResult r = relax(to_points(p), with_method(RelaxOptions{}, "eigen-projected"));
    EXPECT_EQ(r.status(), RelaxStatus::ConvergedStable);
    s.push_back(r.positions);
  }
  return s;
}

const std::vector<Points>& states41() {
  static const std::vector<Points> s = relaxed_samples("4_1", 3);
  return s;
}

/// p reversed, re-indexed by `shift`, rotated about an oblique axis and moved.
Points moved_copy(const Points& p, int shift) {
  const Eigen::Index n = p.rows();
  Points q(n, 3);
  for (Eigen::Index i = 0; i < n; ++i) q.row(i) = p.row((n - 1 - i + shift) % n);
  const Mat3 R = Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, -0.5).normalized()).toRotationMatrix();
  return (q * R.transpose()).rowwise() + Eigen::RowVector3d(3.0, -1.0, 2.5);
}

}  // namespace

TEST(TransitionSearch, AlignmentRecoversAMovedCopy) {
  const Points& a = states41()[0];
  for (int shift : {0, 17, 61}) {
    double d = -1.0;
    const Points b = align_vertices(a, moved_copy(a, shift), d);
    EXPECT_LT(d, 1e-9) << "shift " << shift;
    EXPECT_LT((b - a).cwiseAbs().maxCoeff(), 1e-9) << "shift " << shift;
  }
  double d = 0.0;
  fixtures::expect_input_error([&] { align_vertices(a, a.topRows(100), d); }, "same number of vertices");
}

TEST(TransitionSearch, ACopyOfTheStartIsTheSameState) {
  const Points& a = states41()[0];
  const TransitionSearch t = transition_search(a, moved_copy(a, 33), unit_rest(), {}, sim);
  EXPECT_EQ(t.status.outcome, SearchOutcome::SameState);
  EXPECT_FALSE(t.verified);
  EXPECT_EQ(t.seeds_tried, 0);
  EXPECT_LT(t.alignment_distance, 1e-6);
  EXPECT_NEAR(t.energy_a, t.energy_b, 1e-10 * t.energy_a);
}

// The trefoil and its mirror image have the same Alexander polynomial, so
// nothing but the CCD stands between them: the steered path must stay a
// right-handed (resp. left-handed) trefoil on every image and end
// "not-reached", however stiff the pull.
TEST(TransitionSearch, AStrandPassageIsNeverTaken) {
  const Points a = relaxed_samples("3_1", 1)[0];
  Points b = a;
  b.col(0) = -b.col(0);  // the mirror image: a stable state of the other trefoil
  TransitionSearchOptions o;
  const TransitionSearch t = transition_search(a, b, unit_rest(), o, sim);
  EXPECT_EQ(t.status.outcome, SearchOutcome::NotReached);
  EXPECT_FALSE(t.reached);
  EXPECT_FALSE(t.verified);
  EXPECT_EQ(t.stages, o.max_stages);
  EXPECT_TRUE(t.alexander_preserved);
  const AlexanderPolynomial p = alexander(a);
  ASSERT_GE(t.chain.size(), 2u);
  for (const Points& x : t.chain) EXPECT_EQ(alexander(x), p);
  EXPECT_LT(t.reached_similarity, o.reach);
  const double highest = *std::max_element(t.chain_energies.begin(), t.chain_energies.end());
  std::cout << "[ measured ] mirror trefoil: similarity to B " << t.reached_similarity << " after " << t.stages
            << " stages (k = " << t.final_stiffness << "), aligned distance " << t.alignment_distance
            << ", highest image " << (highest - t.energy_a) / t.energy_scale << " EI/L above A, " << t.seconds
            << " s" << std::endl;
}

// States 1 and 2 of 4_1 are joined by a verified saddle of the single-ended
// search (test_saddles.cpp); the double-ended search reaches B along a chain
// from A and finds a verified saddle between them, which passes the checks
// again on its own.
TEST(TransitionSearch, VerifiedSaddlesJoinAAndB) {
  const Points& a = states41()[1];
  const Points& b = states41()[2];
  const TransitionSearch t = transition_search(a, b, unit_rest(), {}, sim);
  std::cout << "[ measured ] 4_1 states 1 -> 2: " << to_string(t.status) << ", " << t.stages
            << " stages, chain barrier " << t.path_barrier / t.energy_scale << " EI/L, " << t.seconds << " s"
            << std::endl;
  EXPECT_TRUE(t.reached) << to_string(t.status);
  ASSERT_FALSE(t.chain.empty());
  EXPECT_EQ(t.chain.front(), t.a);
  EXPECT_GE(sim(t.chain.back(), t.b), 0.99);
  EXPECT_EQ(t.chain.size(), t.chain_energies.size());
  const AlexanderPolynomial p = alexander(a);
  for (const Points& x : t.chain) EXPECT_EQ(alexander(x), p);
  EXPECT_EQ(t.verified, t.status.verified());
  ASSERT_TRUE(t.verified) << to_string(t.status);  // measured: verified after 3 stages
  const SaddleRecord& s = t.saddle;
  const PointCheck c = check_point(s.saddle, unit_rest(), RelaxOptions{});
  EXPECT_LE(c.gradient_norm, c.tolerance);
  ASSERT_TRUE(c.index.converged);
  EXPECT_EQ(c.index.negative, 1);
  EXPECT_EQ(c.index.near_zero, 0);
  EXPECT_GT(s.energy, std::max(t.energy_a, t.energy_b));
  EXPECT_GE(sim(s.minima[0].positions, t.a), 0.99);
  EXPECT_NEAR(s.minima[0].energy, t.energy_a, 1e-8 * t.energy_a);
  EXPECT_GE(sim(s.minima[1].positions, t.b), 0.99);
  EXPECT_NEAR(s.minima[1].energy, t.energy_b, 1e-8 * t.energy_b);
}

TEST(TransitionSearch, OptionsAreValidated) {
  TransitionSearchOptions o;
  o.growth = 1.0;
  EXPECT_THROW(o.validate(), InputError);
  o = {};
  o.max_images = 2;
  EXPECT_THROW(o.validate(), InputError);
  o = {};
  o.seeds = 0;
  EXPECT_THROW(o.validate(), InputError);
}
