#pragma once
// summary.json of exp_puzzles (docs/results.md, "puzzles").
#include <optional>
#include <string>
#include <vector>

#include "json_fields.hpp"

namespace ek::results {

struct PuzzleLink {
  std::string knot;
  double link = 0.0;  ///< [1] the puzzle's link (mean writhe of its two states)
};
EK_JSON_FIELDS(PuzzleLink, knot, link)

struct PuzzlesSummary {
  std::string scale;
  double writhe_tolerance = 0.0;  ///< [1] kWritheTolerance
  double cut = 0.0;               ///< [1] kClusterCut
  int puzzles = 0;                ///< [1] pairs listed in puzzles.csv
  int knots_with_puzzles = 0;     ///< [1]
  std::vector<PuzzleLink> links;  ///< one per pair, in puzzles.csv's order
  double radius = 0.0;   ///< [length] wire radius r of the data sets' curves
  double dhat = 0.0;     ///< [length] their contact distance d̂
};
EK_JSON_FIELDS(PuzzlesSummary, scale, writhe_tolerance, cut, puzzles, knots_with_puzzles, links, radius, dhat)

}  // namespace ek::results
