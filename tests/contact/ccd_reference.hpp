#pragma once
// Independent reference for segment-pair CCD: adversarial random motions and
// a checker with its own segment distance (long double, accurate also for
// nearly parallel segments; neither the contact kernels nor the geometry
// module) and exact contact times:
//  (1) a touch at time s is either an interior-interior contact of
//      non-parallel segments, when the four endpoints are coplanar (a root of
//      the cubic det[a1 − a0, b0 − a0, b1 − a0](s)), or an endpoint lying on
//      the other segment ((p − e0) × e = 0, a root of each non-vanishing
//      quadratic component); the roots in [0, t] are isolated between critical
//      points and bisected, and the exact distance is evaluated there;
//  (2) the floor d >= δ is checked at 128 uniform samples and at the refined
//      sampled minimum;
//  (3) motions where an endpoint stays on a line (no isolated contact times)
//      are certified by adaptive sampling with the Lipschitz bound.
#include <cstdint>
#include <random>
#include <string>

#include "ek/contact/ccd.hpp"
#include "ek/geometry/types.hpp"

namespace ek::ccdtest {

struct Motion {
  Vec3 a0, a1, b0, b1;      // positions at s = 0
  Vec3 da0, da1, db0, db1;  // displacements over s ∈ [0, 1]
};

inline constexpr int kCategories = 10;
const char* category_name(int c);
/// A random motion of category c: 0 crossing, 1 grazing, 2 parallel approach
/// (and pass-through), 3 endpoint-endpoint, 4 endpoint-interior, 5 nearly
/// touching start, 6 rotating, 7 random, 8 parallel sliding, 9 tiny motion.
Motion random_motion(std::mt19937_64& rng, int c);

struct Verdict {
  bool touches = false;      // d(s) = 0 (touch or crossing) found in [0, t]: a real failure
  bool below_floor = false;  // some sampled d(s) < floor (the contract) in [0, t]
  bool uncertified = false;  // the Lipschitz certification could not close an interval
  double min_sampled = 0;    // smallest sampled distance on [0, t]
  int roots = 0;             // candidate contact times in [0, t] checked
};

/// Checks the motion on [0, t] against the floor δ.
Verdict check(const Motion& m, double t, double floor);

/// Segment distance at time s of the motion (positions x + s·dx rounded to
/// double, as a solver computes them; distance in long double).
double distance_at(const Motion& m, double s);

struct Stats {
  long motions = 0, touches = 0, below_floor = 0, uncertified = 0, capped = 0, full_step = 0;
  long per_category[kCategories] = {};
  long roots = 0;
  double mean_t = 0;
  std::string summary() const;
};

/// Runs `count` adversarial motions (categories in turn) through edge_edge_ccd
/// and the checker.
Stats run_adversarial(std::uint64_t seed, long count, const CcdParams& params);

}  // namespace ek::ccdtest
