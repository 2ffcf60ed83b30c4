// The stratified sample of the table (ek/knots/selection.hpp), on the
// KnotInfo table: 11 and 12 crossings, 10% of every stratum, every BB knot.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include "ek/core/errors.hpp"
#include "ek/knots/selection.hpp"

using namespace ek;

namespace {
using Stratum = std::tuple<int, int, int>;
Stratum stratum_of(const KnotRecord& k) {
  return {k.crossing_number, k.alternating ? static_cast<int>(*k.alternating) : -1, k.bridge_index.value_or(-1)};
}
}  // namespace

TEST(StratifiedSample, EveryStratumAtItsShareAndEveryBBKnot) {
  const KnotTable& table = KnotTable::global();
  const std::vector<const KnotRecord*> sample = stratified_sample(table, {});
  std::map<Stratum, int> size, taken;
  std::map<int, int> by_crossings, sampled_by_crossings;
  int bb = 0, bb_taken = 0;
  for (const KnotRecord* k : table.up_to_crossings(12)) {
    if (k->crossing_number < 11) continue;
    ++size[stratum_of(*k)];
    ++by_crossings[k->crossing_number];
    bb += is_bb_knot(*k);
  }
  for (const KnotRecord* k : sample) {
    ASSERT_GE(k->crossing_number, 11);
    ASSERT_LE(k->crossing_number, 12);
    ++taken[stratum_of(*k)];
    ++sampled_by_crossings[k->crossing_number];
    bb_taken += is_bb_knot(*k);
  }
  // the KnotInfo table: 552 knots with 11 crossings, 2,176 with 12, in 10
  // strata (alternating or not, bridge index 2, 3 or 4); 17 + 119 BB knots
  EXPECT_EQ(by_crossings[11], 552);
  EXPECT_EQ(by_crossings[12], 2176);
  EXPECT_EQ(size.size(), 10u);
  EXPECT_EQ(bb, 136);
  EXPECT_EQ(bb_taken, bb);  // every BB knot
  for (const auto& [s, n] : size) EXPECT_GE(taken[s], static_cast<int>(std::ceil(0.1 * n - 1e-9)));
  for (const auto& [c, n] : by_crossings) EXPECT_GE(sampled_by_crossings[c], 0.1 * n) << c << " crossings";
  // in table order, each knot once, and the same sample every time
  EXPECT_TRUE(std::is_sorted(sample.begin(), sample.end(), [](auto a, auto b) { return a->row < b->row; }));
  EXPECT_EQ(std::adjacent_find(sample.begin(), sample.end()), sample.end());
  EXPECT_EQ(stratified_sample(table, {}), sample);
  // without the BB knots: exactly ⌈10%⌉ of every stratum, 57 + 220 knots
  StratifiedSampleOptions o;
  o.all_bb_knots = false;
  EXPECT_EQ(stratified_sample(table, o).size(), 57u + 220u);
  o.fraction = 1.0;  // everything
  EXPECT_EQ(stratified_sample(table, o).size(), 552u + 2176u);
  o.fraction = 0.0;
  EXPECT_THROW(stratified_sample(table, o), InputError);
  o = {};
  o.min_crossings = 13;
  EXPECT_THROW(stratified_sample(table, o), InputError);
}
