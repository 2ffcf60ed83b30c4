// Knots under load (not a claim of the paper: Section 8.5 names the analysis
// of knots under load as future work): the puzzle pairs pressed between
// plates and pulled by exp_loads. The checks verify its tables and stored
// curves again: the knot type of every stored curve, the naming of every
// snap's released state by the knot's similarity, a flip exactly where a
// snap's released state is the pair's other state, positive jumps and
// energy drops; the flip forces and works are reported beside the
// transitions' barriers, not asserted (a barrier computed by the transitions
// module bounds the true barrier from above, and only the true barrier is a
// lower bound of a flip's work).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "ek/geometry/curve_io.hpp"
#include "ek/knots/alexander.hpp"
#include "ek/transitions/run.hpp"
#include "loads_summary.hpp"
#include "results.hpp"

using ek::paper::number;

namespace {

using Row = std::map<std::string, std::string>;

/// The curve file of state `state` of `knot` in exp_puzzles' table.
std::string puzzle_curve(const std::vector<Row>& puzzles, const std::string& knot, const std::string& state) {
  for (const Row& p : puzzles) {
    if (p.at("knot") != knot) continue;
    if (p.at("state_a") == state) return ek::paper::results("puzzles") + "/" + p.at("curve_a");
    if (p.at("state_b") == state) return ek::paper::results("puzzles") + "/" + p.at("curve_b");
  }
  return "";
}

ek::Points curve(const std::string& relative) { return ek::read_curve(ek::paper::results("loads") + "/" + relative); }

}  // namespace

// The summary counts the tables' rows, reached runs, runs with snaps and flips.
TEST(PaperLoads, SummaryAgreesWithTheTables) {
  const auto s = ek::paper::summary<ek::results::LoadsSummary>("loads");
  const auto runs = ek::paper::csv(ek::paper::results("loads") + "/loads.csv");
  const auto snaps = ek::paper::csv(ek::paper::results("loads") + "/snaps.csv");
  EXPECT_GE(s.pairs, 1);  // exp_puzzles finds puzzles (Fig. 14) and exp_transitions lists them
  EXPECT_EQ(static_cast<int>(runs.size()), s.runs);
  EXPECT_EQ(static_cast<int>(snaps.size()), s.snaps);
  int reached = 0, with_snaps = 0, flips = 0;
  for (const Row& r : runs) {
    reached += r.at("status") == "reached";
    with_snaps += r.at("snaps") != "0";
    flips += r.at("flip") == "true";
    EXPECT_EQ(r.at("alexander_preserved"), "true") << "run " << r.at("run");
  }
  EXPECT_EQ(reached, s.runs_reached);
  EXPECT_EQ(with_snaps, s.runs_with_snaps);
  EXPECT_EQ(flips, s.flips);
  std::cout << "[ measured ] " << s.runs << " runs on " << s.pairs << " pairs: " << s.runs_reached << " reached, "
            << s.runs_with_snaps << " with snaps, " << s.snaps << " snaps, " << s.flips << " flips" << std::endl;
}

// Every stored curve (each run's relaxed start, each snap's state before it
// and its released state) has the Alexander polynomial of the pair's state;
// a run without a start curve is one that stalled at its start, with no point.
TEST(PaperLoads, EveryStoredCurveKeepsTheKnotType) {
  const auto runs = ek::paper::csv(ek::paper::results("loads") + "/loads.csv");
  const auto snaps = ek::paper::csv(ek::paper::results("loads") + "/snaps.csv");
  const auto puzzles = ek::paper::csv(ek::paper::results("puzzles") + "/puzzles.csv");
  for (const Row& r : runs) {
    const std::string from = puzzle_curve(puzzles, r.at("knot"), r.at("state_from"));
    ASSERT_FALSE(from.empty()) << "run " << r.at("run");
    const ek::AlexanderPolynomial expected = ek::alexander(ek::read_curve(from));
    if (r.at("curve_start").empty()) {  // no equilibrium under the load at its start: no point, no snap
      EXPECT_EQ(r.at("status"), "stalled") << "run " << r.at("run");
      EXPECT_EQ(r.at("points"), "0") << "run " << r.at("run");
    } else {
      EXPECT_EQ(ek::alexander(curve(r.at("curve_start"))), expected) << "run " << r.at("run");
    }
    for (const Row& z : snaps) {
      if (z.at("run") != r.at("run")) continue;
      for (const char* key : {"curve_before", "curve_released"})
        EXPECT_EQ(ek::alexander(curve(z.at(key))), expected) << "run " << r.at("run") << " " << z.at(key);
    }
  }
}

// Each snap's released state, compared again with the pair's two stored
// states by the knot's similarity (to 1e-9 of the stored values): named
// "other" when its similarity to the other state is >= reach and above its
// similarity to the start, "start" when that is >= reach, else "neither";
// its relaxation converged-stable; its jump and energy drop positive. A run
// flips exactly when one of its snaps is named "other", and its flip is the
// first such snap.
TEST(PaperLoads, EverySnapIsNamedByItsSimilarity) {
  const auto s = ek::paper::summary<ek::results::LoadsSummary>("loads");
  const auto runs = ek::paper::csv(ek::paper::results("loads") + "/loads.csv");
  const auto snaps = ek::paper::csv(ek::paper::results("loads") + "/snaps.csv");
  const auto puzzles = ek::paper::csv(ek::paper::results("puzzles") + "/puzzles.csv");
  for (const Row& r : runs) {
    const ek::Points start = ek::read_curve(puzzle_curve(puzzles, r.at("knot"), r.at("state_from")));
    const ek::Points other = ek::read_curve(puzzle_curve(puzzles, r.at("knot"), r.at("state_to")));
    const ek::CurveSimilarity sim = ek::knot_similarity(r.at("knot"));
    std::string first_other;
    for (const Row& z : snaps) {
      if (z.at("run") != r.at("run")) continue;
      const std::string at = "run " + r.at("run") + " snap " + z.at("snap");
      const ek::Points x = curve(z.at("curve_released"));
      const double to_start = sim(x, start), to_other = sim(x, other);
      EXPECT_NEAR(to_start, number(z, "similarity_start"), 1e-9) << at;
      EXPECT_NEAR(to_other, number(z, "similarity_other"), 1e-9) << at;
      const std::string name = to_other >= s.reach && to_other > to_start ? "other"
                               : to_start >= s.reach                        ? "start"
                                                                            : "neither";
      EXPECT_EQ(z.at("released_state"), name) << at;
      EXPECT_EQ(z.at("released_status"), "converged-stable") << at;
      EXPECT_GT(number(z, "jump"), 0.0) << at;
      EXPECT_GT(number(z, "energy_drop_scaled"), 0.0) << at;
      if (name == "other" && first_other.empty()) first_other = z.at("snap");
    }
    EXPECT_EQ(r.at("flip"), first_other.empty() ? "false" : "true") << "run " << r.at("run");
    EXPECT_EQ(r.at("flip_snap"), first_other) << "run " << r.at("run");
    std::cout << "[ measured ] run " << r.at("run") << ": " << r.at("knot") << " " << r.at("state_from") << " -> "
              << r.at("state_to") << " by " << r.at("load") << ": " << r.at("status") << ", " << r.at("snaps")
              << " snaps, flip " << r.at("flip")
              << (r.at("flip") == "true" ? " at force " + r.at("flip_reaction") + " with work " +
                                               r.at("flip_work_scaled") + " EI/L"
                                         : "")
              << "; barrier " << (r.at("barrier_scaled").empty() ? "not joined" : r.at("barrier_scaled"))
              << ", upper bound " << (r.at("upper_bound_scaled").empty() ? "-" : r.at("upper_bound_scaled"))
              << " EI/L" << std::endl;
  }
}
