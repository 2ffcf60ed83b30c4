#pragma once
// Helpers shared by the site's translation units (site.cpp, site_knot.cpp).
#include <cmath>
#include <cstring>
#include <string>

#include <nlohmann/json.hpp>

namespace ek::site_detail {

using Json = nlohmann::ordered_json;

/// A finite number, or null.
inline Json number(double x) { return std::isfinite(x) ? Json(x) : Json(nullptr); }

/// Appends the bytes of `value` (the machine's byte order; knot_site_data checks it is little-endian).
template <class T>
void append(std::string& out, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

}  // namespace ek::site_detail
