// Paper Section 8.3, Fig. 14: knot puzzles are pairs of distinct stable states
// of one knot with the same writhe (the joined wire cannot change its link;
// twist-free states have Lk = Wr). The experiment lists them from the data
// sets; the checks verify each listed pair against the data set itself.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <set>

#include "ek/dataset/dataset_file.hpp"
#include "ek/dataset/pipeline.hpp"
#include "ek/geometry/writhe.hpp"
#include "ek/knots/table.hpp"
#include "puzzles_summary.hpp"
#include "results.hpp"

TEST(PaperPuzzles, ListedPairsAreDistinctStatesWithEqualWrithe) {
  const auto s = ek::paper::summary<ek::results::PuzzlesSummary>("puzzles");
  const double tol = s.writhe_tolerance;
  const auto rows = ek::paper::csv(ek::paper::results("puzzles") + "/puzzles.csv");
  std::cout << "[ measured ] " << s.puzzles << " puzzles in " << s.knots_with_puzzles << " knots" << std::endl;
  EXPECT_GT(rows.size(), 0u);  // the paper finds puzzles (Fig. 14); so must the data sets
  EXPECT_EQ(static_cast<int>(rows.size()), s.puzzles);
  EXPECT_EQ(s.links.size(), rows.size());
  EXPECT_DOUBLE_EQ(tol, ek::results::kWritheTolerance);
  for (const auto& r : rows) {
    const double wa = std::atof(r.at("writhe_a").c_str()), wb = std::atof(r.at("writhe_b").c_str());
    EXPECT_LE(std::fabs(wa - wb), tol) << r.at("knot");        // same link within the stated tolerance
    EXPECT_NE(r.at("state_a"), r.at("state_b")) << r.at("knot");  // representatives of two different clusters
    // and visibly different themselves: distance 1 - similarity above the cut
    EXPECT_GT(1.0 - std::atof(r.at("similarity").c_str()), s.cut) << r.at("knot");
    EXPECT_NEAR(std::atof(r.at("link").c_str()), 0.5 * (wa + wb), 1e-9) << r.at("knot");
  }
}

// Each listed pair against the data set itself, recomputed from the stored
// curves: the writhe of both states (exact Gauss sum) within the tolerance,
// the similarity of the two curves (with the knot's symmetry options, as the
// pipeline compares them) above the cut in distance, and the two states in
// different clusters of the stored dendrogram at the cut.
TEST(PaperPuzzles, ListedPairsHoldOnTheStoredCurves) {
  const auto s = ek::paper::summary<ek::results::PuzzlesSummary>("puzzles");
  const double tol = s.writhe_tolerance, cut = s.cut;
  const auto rows = ek::paper::csv(ek::paper::results("puzzles") + "/puzzles.csv");
  std::set<std::string> listed;
  for (const auto& r : rows) listed.insert(r.at("knot"));
  std::map<std::string, ek::KnotEntry> entries;  // the listed knots, same search order as exp_puzzles
  for (const std::string& file : {ek::paper::results("multistability") + "/multistability.h5",
                                  ek::paper::results("dataset") + "/dataset.h5"}) {
    ek::DatasetReader reader(file);
    for (const auto& name : reader.knot_names())
      if (listed.count(name) && !entries.count(name)) entries.emplace(name, reader.read(name));
  }
  std::map<std::string, std::vector<int>> ranks;
  int checked = 0;
  for (const auto& r : rows) {
    const std::string knot = r.at("knot");
    ASSERT_TRUE(entries.count(knot)) << knot << " is in no data set";
    const ek::KnotEntry& e = entries.at(knot);
    const int a = std::atoi(r.at("state_a").c_str()), b = std::atoi(r.at("state_b").c_str());
    ASSERT_LT(std::max(a, b), static_cast<int>(e.equilibria.size())) << knot;
    const ek::Points& A = e.equilibria[static_cast<size_t>(a)];
    const ek::Points& B = e.equilibria[static_cast<size_t>(b)];
    EXPECT_LE(std::fabs(ek::writhe(A) - ek::writhe(B)), tol + 1e-9) << knot;  // equal link within the tolerance
    const ek::ExploreOptions o = ek::options_for_knot(ek::ExploreOptions{}, ek::KnotTable::global().at(knot));
    const double sim = ek::similarity(A, B, o.similarity);
    EXPECT_GT(1.0 - sim, cut) << knot << " " << a << "/" << b;  // visibly different states
    auto found = ranks.find(knot);  // cluster ranks, once per knot
    if (found == ranks.end()) {
      std::vector<int> rank;
      ek::clusters_at_cut(e, cut, &rank);
      found = ranks.emplace(knot, std::move(rank)).first;
    }
    const std::vector<int>& rank = found->second;
    EXPECT_NE(rank[static_cast<size_t>(a)], rank[static_cast<size_t>(b)]) << knot;  // different clusters
    ++checked;
  }
  std::cout << "[ measured ] " << checked << " listed pairs recomputed from the stored curves" << std::endl;
}
