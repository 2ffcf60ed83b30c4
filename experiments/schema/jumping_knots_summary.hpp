#pragma once
// summary.json of exp_jumping_knots (docs/results.md, "jumping_knots").
#include <optional>
#include <string>
#include <vector>

#include "json_fields.hpp"

namespace ek::results {

struct JumpingKnotsSummary {
  std::string scale;
  double threedim_threshold = 0.0;         ///< [1] kJumpThreedim: the released state is 3D at or above it
  double planar_threshold = 0.0;  ///< [1] kPlanarThreedim: the flat stage is below it
  int tested = 0;                          ///< [1] knots whose flat and released stages ran
  std::vector<std::string> jumping;        ///< the knots that jump, in table order
  double radius = 0.0;            ///< [length] wire radius r of the curves
};
EK_JSON_FIELDS(JumpingKnotsSummary, scale, threedim_threshold, planar_threshold, tested, jumping, radius)

}  // namespace ek::results
