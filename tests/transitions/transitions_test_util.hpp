#pragma once
// Helpers shared by the transition tests: the knots' vertex count, their unit
// rest lengths and the similarity of two states (reversal allowed).
#include "ek/analysis/similarity.hpp"
#include "ek/geometry/types.hpp"

namespace ek::transitionstest {

/// Vertices of the test knots (unit edges): small enough for a few seconds per search.
constexpr int kVertices = 120;

/// Unit rest lengths of the kVertices edges.
inline VecX unit_rest() { return VecX::Ones(kVertices); }

/// The similarity of two states, a curve or its reversal (1 = the same state).
inline double sim(const Points& a, const Points& b) {
  SimilarityOptions o;
  o.reversal = true;
  return similarity(a, b, o);
}

}  // namespace ek::transitionstest
