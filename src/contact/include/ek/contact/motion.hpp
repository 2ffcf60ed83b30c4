#pragma once
/// \file
/// Collision detection for the linear motion between two curves, as `knots
/// ccd` reports it (and the Python module's ccd()): vertex i moves on the line
/// from start_i to end_i; the largest certified t ∈ [0, 1] such that up to t
/// no two edges sharing no vertex come closer than
/// separation·min(their distance at the start, 2r) (ContactPotential::
/// max_step_report), so the motion up to t cannot change the knot type; and
/// the clearance along it.
#include "ek/contact/contact_potential.hpp"
#include "ek/geometry/types.hpp"

namespace ek {

/// The wire and the tolerance of check_linear_motion().
struct MotionCheckOptions {
  double radius = 0.2;       ///< [length] wire radius r; the barrier distance d̂ is 2r
  double separation = 0.1;   ///< [1] kept fraction of min(start distance, d̂), in (0, 1)
  /// [1] the clearance is also sampled at t·k/samples, k = 1 .. samples.
  int samples = 64;
  /// Throws InputError for a non-positive radius, a separation outside (0, 1)
  /// or fewer than 1 sample.
  void validate() const;
};

/// What check_linear_motion() reports: the certified step t and the clearance
/// (smallest distance of edges sharing no vertex) along the motion.
struct MotionCheck {
  int vertices = 0;                    ///< [1] n
  StepReport step;                     ///< t, the pairs tested, the limiting pair (-1: none)
  double separation = 0.0;             ///< [1] as given
  double dhat = 0.0;                   ///< [length] 2r
  double clearance_start = 0.0;        ///< [length] at the start
  double clearance_at_t = 0.0;         ///< [length] at t
  double clearance_end = 0.0;          ///< [length] at the end
  double min_clearance_sampled = 0.0;  ///< [length] smallest over the start and the samples of [0, t]
};

/// The check of the motion from `start` to `end` (both n by 3, the same n).
/// Throws InputError for different vertex counts.
MotionCheck check_linear_motion(const Points& start, const Points& end, const MotionCheckOptions& options = {});

}  // namespace ek
