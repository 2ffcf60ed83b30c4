// compare_datasets (ek/dataset/compare.hpp) on hand-made data sets of one
// knot whose states are known curves: two torus-knot shapes, each stored
// several times rigidly moved and re-indexed (similarity 1 within a state).
#include <gtest/gtest.h>

#include <filesystem>

#include "ek/dataset/compare.hpp"
#include "ek/dataset/pipeline.hpp"
#include "testing.hpp"

using namespace ek;

namespace {

/// `counts[s]` copies of state s (0: torus (2,3), 1: torus (2,5)), energies
/// 1.0 and 1.5 (+ `energy_shift`), 3D-ness 0.05 and 0.5.
KnotEntry entry(const std::vector<int>& counts, double energy_shift = 0.0) {
  KnotEntry e;
  e.name = "test";
  e.crossing_number = 3;
  e.alexander = {1, -1, 1};
  e.attribute_names = dataset_attribute_names();
  const int energy = 0, threedim = e.attribute_column("threedim");
  int m = 0;
  for (int c : counts) m += c;
  e.attributes = Eigen::MatrixXd::Zero(m, static_cast<Eigen::Index>(e.attribute_names.size()));
  int row = 0;
  for (size_t s = 0; s < counts.size(); ++s)
    for (int k = 0; k < counts[s]; ++k, ++row) {
      const Points base = fixtures::torus_knot(120, 2, s == 0 ? 3 : 5);
      e.equilibria.push_back(fixtures::rigid_copy(base, fixtures::random_rotation(17 * row + 1), Vec3(row, 0, 1), 7 * k));
      e.attributes(row, energy) = (s == 0 ? 1.0 : 1.5) + energy_shift;
      e.attributes(row, threedim) = s == 0 ? 0.05 : 0.5;
    }
  SimilarityOptions so;
  so.reversal = true;
  cluster_entry(e, so);
  return e;
}

std::string write(const std::string& name, const KnotEntry& e) {
  // one file per test: CTest runs the tests of this file in parallel processes
  const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  const std::string path = (std::filesystem::temp_directory_path() / ("compare_" + test + "_" + name + ".h5")).string();
  DatasetMetadata meta = dataset_metadata(ExploreOptions{});
  meta.created = "2026-01-01T00:00:00Z";
  DatasetWriter w(path, meta);
  w.add(e);
  w.commit();
  return path;
}

DatasetComparison compare(const KnotEntry& a, const KnotEntry& b, const CompareOptions& o = {}) {
  const DatasetReader ra(write("a", a)), rb(write("b", b));
  return compare_datasets(ra, rb, o);
}

}  // namespace

// The same two states in other proportions: every state has its counterpart,
// the lowest energies agree; the planar shares (10/20 and 15/20) differ by
// 0.25, beyond the tolerance 0.05, within 0.3.
TEST(Compare, SameStatesInOtherProportions) {
  const DatasetComparison d = compare(entry({10, 10}), entry({15, 5}));
  ASSERT_EQ(d.knots.size(), 1u);
  const KnotComparison& k = d.knots[0];
  EXPECT_EQ(k.clusters_a, 2);
  EXPECT_EQ(k.clusters_b, 2);
  EXPECT_TRUE(k.counterparts_ok);
  for (const auto& c : k.a_in_b) EXPECT_GT(c.similarity, 0.999);
  EXPECT_TRUE(k.energy_ok);
  EXPECT_EQ(k.energy_difference, 0.0);
  EXPECT_DOUBLE_EQ(d.planar_share_a, 0.5);
  EXPECT_DOUBLE_EQ(d.planar_share_b, 0.75);
  EXPECT_FALSE(d.planar_ok);
  EXPECT_FALSE(d.ok());
  CompareOptions loose;
  loose.planar_tolerance = 0.3;
  EXPECT_TRUE(compare(entry({10, 10}), entry({15, 5}), loose).ok());
}

// A state of 25% in one data set and absent in the other has no counterpart;
// one of 1 in 40 (2.5%, below the 3% share) needs none.
TEST(Compare, AMissingStateNeedsACounterpartAboveTheShare) {
  CompareOptions o;
  o.planar_tolerance = 1.0;
  const DatasetComparison missing = compare(entry({15, 5}), entry({20, 0}), o);
  EXPECT_FALSE(missing.knots[0].counterparts_ok);
  EXPECT_FALSE(missing.ok());
  const DatasetComparison rare = compare(entry({39, 1}), entry({20, 0}), o);
  EXPECT_TRUE(rare.knots[0].counterparts_ok);
  ASSERT_EQ(rare.knots[0].a_in_b.size(), 2u);
  EXPECT_FALSE(rare.knots[0].a_in_b[1].needs_counterpart);
  EXPECT_FALSE(rare.knots[0].a_in_b[1].found);
  EXPECT_TRUE(rare.ok());
}

// Lowest energies 1.0 and 1.0002: 2e-4 relative, beyond 1e-4.
TEST(Compare, LowestEnergiesMustAgree) {
  CompareOptions o;
  o.planar_tolerance = 1.0;
  const DatasetComparison d = compare(entry({10, 10}), entry({10, 10}, 2e-4), o);
  EXPECT_NEAR(d.knots[0].energy_difference, 2e-4, 1e-12);
  EXPECT_FALSE(d.knots[0].energy_ok);
  EXPECT_FALSE(d.ok());
  CompareOptions bad;
  bad.counterpart = 1.5;
  EXPECT_THROW(compare(entry({1}), entry({1}), bad), InputError);
}
