#pragma once
/// \file
/// Locations of external data (the knot table) and run-time configuration.
#include <string>

namespace ek {

/// Path of the KnotInfo table: $KNOT_TABLE if set and non-empty, otherwise the
/// configure-time default (CMake variable EK_KNOT_TABLE, which defaults to
/// ../shared/data/knotinfo_table.csv next to the source tree).
std::string knot_table_path();

/// Project version string (for reports and data-set metadata).
std::string project_version();

/// The current time in UTC as ISO 8601, "2026-12-03T21:08:18Z".
std::string now_iso8601();

}  // namespace ek
