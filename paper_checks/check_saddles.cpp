// Transitions between stable states (paper Section 8.5, an open direction):
// every saddle exp_saddles reports is verified again from its stored curves,
// independently of the search that found it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "ek/analysis/similarity.hpp"
#include "ek/dataset/dataset_file.hpp"
#include "ek/dataset/pipeline.hpp"
#include "ek/geometry/curve_io.hpp"
#include "ek/knots/alexander.hpp"
#include "ek/transitions/saddles.hpp"
#include "results.hpp"
#include "saddles_summary.hpp"

namespace {

/// [1] relative energy agreement of the stored start with the reported barrier
/// (E_start = E_saddle − barrier; the start is polished to the tolerance).
constexpr double kSaddleEnergyTolerance = 1e-8;
/// [1] the descent's minimum is the start at this similarity or more (the
/// verification's threshold).
constexpr double kStartSimilarity = 0.99;

double sim(const ek::Points& a, const ek::Points& b) {
  ek::SimilarityOptions o;
  o.reversal = true;
  return ek::similarity(a, b, o);
}

}  // namespace

// Each reported saddle: ||∇E|| <= the solver's tolerance; exactly one
// eigenvalue of H without rigid modes below −ε·λ_min and none within
// ±ε·λ_min (ε·λ_min: the index tolerance, the Newton solver's shift scale);
// both ends of its path converged-stable (||∇E|| <= tolerance, lowest
// eigenvalue above ε·λ_min); the start end similar (>= 0.99) to the state it
// was searched from, with E_saddle − E_start equal to the reported barrier
// (1e-8 relative) and > 0; the saddle the highest image of the path; 4_1's
// Alexander polynomial on every image.
TEST(PaperSaddles, EveryReportedSaddleIsVerified) {
  const auto s = ek::paper::summary<ek::results::SaddlesSummary>("saddles");
  const std::string dir = ek::paper::results("saddles");
  const ek::DatasetReader reader(ek::paper::results("multistability") + "/multistability.h5");
  const ek::KnotEntry e = reader.read(s.knot);
  const std::vector<ek::StateCluster> clusters = ek::clusters_at_cut(e, s.cut);
  const ek::AlexanderPolynomial expected = ek::alexander(e.equilibria.front());
  std::cout << "[ measured ] " << s.saddles << " saddles of " << s.knot << " (" << s.saddles_to_other_states
            << " to another state), " << s.seconds_per_saddle << " s per saddle" << std::endl;
  for (const ek::results::VerifiedSaddle& v : s.verified_saddles) {
    const std::string at = v.folder + ": ";
    const ek::Points saddle = ek::read_curve(dir + "/" + v.folder + "/saddle.obj");
    const ek::VecX rest = ek::VecX::Constant(saddle.rows(), s.edge_length);
    const ek::PointCheck c = ek::check_point(saddle, rest, ek::RelaxOptions{});
    EXPECT_LE(c.gradient_norm, c.tolerance) << at;
    ASSERT_TRUE(c.index.converged) << at;
    EXPECT_EQ(c.index.negative, 1) << at << "eigenvalues " << c.index.values.transpose();
    EXPECT_EQ(c.index.near_zero, 0) << at << "within " << c.threshold << " of zero";
    EXPECT_NEAR(c.energy, v.energy, kSaddleEnergyTolerance * std::abs(v.energy)) << at;
    EXPECT_GT(v.barrier, 0.0) << at;
    std::vector<double> energies;
    const std::vector<ek::Points> path = ek::read_path_obj(dir + "/" + v.folder + "/path.obj", energies);
    for (const ek::Points* end : {&path.front(), &path.back()}) {
      const ek::PointCheck m = ek::check_point(*end, rest, ek::RelaxOptions{});
      EXPECT_LE(m.gradient_norm, m.tolerance) << at << "an end is no equilibrium";
      ASSERT_TRUE(m.index.converged) << at;
      EXPECT_GT(m.index.values(0), m.threshold) << at << "an end is not stable";
    }
    const ek::PointCheck start = ek::check_point(path.front(), rest, ek::RelaxOptions{});
    EXPECT_NEAR(v.energy - start.energy, v.barrier, kSaddleEnergyTolerance * std::abs(v.energy)) << at;
    const ek::Points& state = e.equilibria[static_cast<size_t>(clusters.at(static_cast<size_t>(v.state)).representative)];
    EXPECT_GE(sim(path.front(), state), kStartSimilarity) << at;
    for (size_t k = 0; k < path.size(); ++k) {
      EXPECT_LE(energies[k], v.energy + 1e-12 * std::abs(v.energy)) << at << "image " << k;
      EXPECT_EQ(ek::alexander(path[k]), expected) << at << "image " << k;
    }
  }
}

// The summary agrees with the searches table; every start was a stable
// equilibrium; at least one saddle is found at the scale (measured at ci:
// 3 distinct saddles from 3 states, 2 modes each).
TEST(PaperSaddles, SummaryAgreesWithTheSearches) {
  const auto s = ek::paper::summary<ek::results::SaddlesSummary>("saddles");
  const auto rows = ek::paper::csv(ek::paper::results("saddles") + "/searches.csv");
  EXPECT_EQ(static_cast<int>(rows.size()), s.searches);
  EXPECT_EQ(s.searches, 2 * s.modes * (s.states - s.states_refused));
  EXPECT_EQ(s.states_refused, 0);
  int verified = 0, distinct = 0;
  for (const auto& r : rows) {
    const bool ok = ek::paper::flag(r.at("verified"));
    verified += ok;
    distinct += ok && r.at("duplicate_of") == "-1";
    if (ok) {
      EXPECT_EQ(r.at("index"), "1");
    }
    EXPECT_EQ(ok, ek::from_string<ek::SearchStatus>(r.at("status")).verified());
  }
  EXPECT_EQ(verified, s.verified);
  EXPECT_EQ(distinct, s.saddles);
  EXPECT_EQ(static_cast<int>(s.verified_saddles.size()), s.saddles);
  EXPECT_GE(s.saddles, 1);
}
