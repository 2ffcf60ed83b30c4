#pragma once
// summary.json of exp_planarity (docs/results.md, "planarity").
#include <string>

#include "json_fields.hpp"

namespace ek::results {

struct PlanaritySummary {
  std::string scale;
  double threshold = 0.0;     ///< [1] kPlanarThreedim: planar below it
  long equilibria = 0;        ///< [1]
  long planar = 0;            ///< [1] equilibria with 3D-ness < threshold
  double planar_share = 0.0;  ///< [1] planar / equilibria (0 without equilibria)
};
EK_JSON_FIELDS(PlanaritySummary, scale, threshold, equilibria, planar, planar_share)

}  // namespace ek::results
