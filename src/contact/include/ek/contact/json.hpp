#pragma once
/// \file
/// JSON description of a motion check: the object of `knots ccd --json`
/// (docs/cli.md) after the keys `start` and `end` that name the files.
#include "ek/contact/motion.hpp"
#include "ek/core/json.hpp"

namespace ek {

/// vertices, t, full_step (t = 1), separation, dhat, candidates,
/// limiting_edges ([a, b] or null), clearance_start, clearance_at_t,
/// clearance_end, min_clearance_sampled.
Json motion_check_json(const MotionCheck& check);

}  // namespace ek
