// Paper Section 8.3, Fig. 14: knot puzzles are pairs of distinct stable states
// of one knot with the same writhe (the joined wire cannot change its link;
// twist-free states have Lk = Wr). The experiment lists them from the data
// sets; the checks verify each listed pair against the data set itself.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "ek/dataset/dataset_file.hpp"
#include "results.hpp"

TEST(PaperPuzzles, ListedPairsAreDistinctStatesWithEqualWrithe) {
  const auto s = ek::paper::summary("puzzles");
  const double tol = s.at("writhe_tolerance").get<double>();
  const auto rows = ek::paper::csv(ek::paper::results("puzzles") + "/puzzles.csv");
  std::cout << "[ measured ] " << s.at("puzzles") << " puzzles in " << s.at("knots_with_puzzles") << " knots"
            << std::endl;
  EXPECT_GT(rows.size(), 0u);  // the paper finds puzzles (Fig. 14); so must the data sets
  for (const auto& r : rows) {
    const double wa = std::atof(r.at("writhe_a").c_str()), wb = std::atof(r.at("writhe_b").c_str());
    EXPECT_LE(std::fabs(wa - wb), tol) << r.at("knot");        // same link within the stated tolerance
    EXPECT_NE(r.at("state_a"), r.at("state_b")) << r.at("knot");  // representatives of two different clusters
    // and visibly different themselves: distance 1 - similarity above the cut
    EXPECT_GT(1.0 - std::atof(r.at("similarity").c_str()), s.at("cut").get<double>()) << r.at("knot");
    EXPECT_NEAR(std::atof(r.at("link").c_str()), 0.5 * (wa + wb), 1e-9) << r.at("knot");
  }
}
