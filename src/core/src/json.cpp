#include "ek/core/json.hpp"

#include <cmath>

namespace ek {

Json json_number(double x) { return std::isfinite(x) ? Json(x) : Json(nullptr); }

}  // namespace ek
