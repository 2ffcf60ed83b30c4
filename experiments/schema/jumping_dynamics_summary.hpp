#pragma once
// summary.json of exp_jumping_dynamics (docs/results.md, "jumping_dynamics").
#include <optional>
#include <string>
#include <vector>

#include "json_fields.hpp"

namespace ek::results {

/// One knot's friction bracket: it jumps at mu_jumps and rests flat at mu_flat.
struct FrictionBracket {
  std::string knot;
  std::optional<double> mu_jumps;  ///< [1] the largest friction coefficient at which it jumped (null: none)
  std::optional<double> mu_flat;   ///< [1] the smallest at which it came to rest flat (null: none up to the grid's end)
};
EK_JSON_FIELDS(FrictionBracket, knot, mu_jumps, mu_flat)

/// The same release at half the time step: does the jump end in the same state?
struct StepCheck {
  std::string knot;
  double time_step = 0.0;       ///< [time] the halved step
  double similarity = 0.0;      ///< [1] of the two end states (each relaxed statically)
  double rest_time = 0.0;       ///< [time] at the halved step (null runs are not step checks)
  double rest_time_full = 0.0;  ///< [time] at the experiment's step
};
EK_JSON_FIELDS(StepCheck, knot, time_step, similarity, rest_time, rest_time_full)

struct JumpingDynamicsSummary {
  std::string scale;
  double time_step = 0.0;          ///< [time] h
  double duration = 0.0;           ///< [time] a run ends here unless at rest first
  double damping = 0.0;            ///< [1/time] γ (air drag)
  double density = 0.0;            ///< [mass/length³] ρ
  double friction_velocity = 0.0;  ///< [length/time] ε_v
  double rest_speed = 0.0;         ///< [length/time] at rest below it
  std::vector<double> mu_grid;     ///< [1] the friction coefficients of every knot
  int bisection_steps = 0;         ///< [1] halvings of each knot's bracket after the grid
  double threedim_threshold = 0.0; ///< [1] kJumpThreedim: it jumped when its end state is 3D at or above it
  double planar_threshold = 0.0;   ///< [1] kPlanarThreedim: it stayed flat when its end state is below it
  double cut = 0.0;                ///< [1] kClusterCut: the same state when 1 − similarity is at most it
  std::vector<std::string> knots;  ///< the knots released, in table order
  std::vector<std::string> jumping_without_friction;  ///< those that jumped at μ = 0
  std::vector<FrictionBracket> brackets;              ///< one per knot
  std::string figure_knot;         ///< the knot whose frictionless release has frames (frames/)
  std::optional<StepCheck> step_check;  ///< the figure knot at μ = 0 and h/2 (null at the ci scale)
  int runs = 0;                    ///< [1] rows of dynamics.csv
  double seconds = 0.0;            ///< [s]
  double radius = 0.0;             ///< [length] wire radius r of the curves
};
EK_JSON_FIELDS(JumpingDynamicsSummary, scale, time_step, duration, damping, density, friction_velocity, rest_speed,
               mu_grid, bisection_steps, threedim_threshold, planar_threshold, cut, knots, jumping_without_friction,
               brackets, figure_knot, step_check, runs, seconds, radius)

}  // namespace ek::results
