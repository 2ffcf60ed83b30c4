#pragma once
/// \file
/// The far end of Fig.\ 9 (paper Section 8.2): "the knot types with large
/// distance to Milnor's bound [...] are all knots with two bridges". Each
/// knot's ratio is its smallest total curvature over its equilibria divided
/// by 2π · bridge index, a minimum over its samples: more samples of the same
/// lattice walk can only lower it. A knot sampled below the full budget (an
/// adaptive stop) therefore only gives an upper bound of its ratio at the
/// full budget, and may hold its place at the far end by having been sampled
/// little. The certificate below decides the claim at the full budget from
/// such partly sampled results, and names the knots whose sampling at the
/// full budget would decide it when they do not.
#include <string>
#include <vector>

namespace ek {

/// One knot's Milnor ratio as measured.
struct KnotRatio {
  std::string name;         ///< the knot
  double ratio = 0.0;       ///< [1] smallest total curvature / (2π · bridge index) over its equilibria
  bool two_bridge = false;  ///< bridge index 2 (the (2, q) torus knots included)
  int samples = 0;          ///< [samples] lattice samples it was relaxed from
};

/// The claim "the k knots of largest ratio at the full budget are all
/// 2-bridge", decided from ratios of which those with samples < budget are
/// upper bounds.
///
/// Let M be the largest ratio among the knots that are not 2-bridge: an
/// upper bound of every such knot's ratio at the full budget. The claim
/// holds when at least k 2-bridge knots, each sampled at the
/// full budget (its ratio exact), have a ratio above M: those k then lie
/// above every knot that is not 2-bridge. When it is not certified,
/// `to_sample` names the knots whose sampling at the full budget would decide
/// it, in this order:
///  - the knot that sets M, when it is below the budget and fewer than k
///    2-bridge knots lie above M even counting those below the budget (only
///    lowering M can then certify the claim);
///  - the 2-bridge knots below the budget with ratio above M, by
///    decreasing ratio, as many as the certified ones fall short of k.
/// Sampling them and deciding again converges: every knot in the list
/// reaches the budget, so each round leaves fewer knots below it. An empty
/// list with `certified` false means the claim is false at the full budget
/// (M is exact and fewer than k 2-bridge knots lie above it).
struct FarEndCertificate {
  bool certified = false;          ///< the claim holds at the full budget
  double other_max_ratio = 0.0;    ///< [1] M (0 when every knot is 2-bridge)
  std::string other_max_knot;      ///< the knot that sets M (empty when none)
  int certified_two_bridge = 0;    ///< [1] 2-bridge knots at the budget with ratio > M
  std::vector<std::string> to_sample;  ///< the knots to sample at the full budget (see above); empty once decided
};

/// The certificate for the k knots of largest ratio with the full budget
/// `budget` [samples]. Throws std::invalid_argument for k < 1 or budget < 1.
FarEndCertificate far_end_certificate(const std::vector<KnotRatio>& knots, int k, int budget);

}  // namespace ek
