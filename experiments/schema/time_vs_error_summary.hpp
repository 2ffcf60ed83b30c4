#pragma once
// summary.json of exp_time_vs_error (docs/results.md, "time_vs_error").
#include <string>
#include <vector>

#include "json_fields.hpp"

namespace ek::results {

/// Michell's critical link at one resolution.
struct MichellPoint {
  int n = 0;                    ///< [1] vertices
  double critical_link = 0.0;   ///< [1] Lk_c found by bisection
  double relative_error = 0.0;  ///< [1] against √3 (1 + ν)
};
EK_JSON_FIELDS(MichellPoint, n, critical_link, relative_error)

struct TimeVsErrorSummary {
  std::string scale;
  std::vector<MichellPoint> michell;
};
EK_JSON_FIELDS(TimeVsErrorSummary, scale, michell)

}  // namespace ek::results
