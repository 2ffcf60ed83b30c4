#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include <unistd.h>

#include "ek/core/errors.hpp"
#include "ek/dataset/run.hpp"
#include "ek/knots/alexander.hpp"

using namespace ek;

namespace {

/// A fixed-budget run small enough for a unit test: n = 100, no stiffness.
ExploreOptions small_fixed_run(int samples, int jobs) {
  ExploreOptions o;
  o.sampling.vertices = 100;
  o.samples = samples;
  o.stiffness = false;
  o.jobs = jobs;
  return o;
}

}  // namespace

TEST(Adaptive, ImportanceScoreByHand) {
  // One earlier state; a batch of two: the first repeats the earlier state
  // (similarity 1), the second is new (similarity 0.7 < 1 - δ with δ = 0.1)
  // at twice the minimum energy: S = max(0·1, 1·0.5) = 0.5.
  Eigen::MatrixXd sim(2, 3);
  sim << 1.0, 0.0, 0.0,  //
      0.7, 0.6, 0.0;
  EXPECT_DOUBLE_EQ(importance_score(sim, 1, {1.0, 2.0}, 1.0, 0.1), 0.5);
  // a state at distance 0.05 = δ/2 from the nearest earlier one, at the minimum energy: 0.5
  Eigen::MatrixXd near(1, 3);
  near << 0.95, 0.2, 1.0;  // the last column (itself) is ignored
  EXPECT_NEAR(importance_score(near, 2, {3.0}, 3.0, 0.1), 0.5, 1e-12);
  // nothing new: 0
  Eigen::MatrixXd same(1, 2);
  same << 1.0, 1.0;
  EXPECT_DOUBLE_EQ(importance_score(same, 1, {1.0}, 1.0, 0.1), 0.0);
  // the first batch: no earlier state, its lowest state is new at the minimum: 1
  Eigen::MatrixXd first(2, 2);
  first << 1.0, 0.0, 0.99, 1.0;
  EXPECT_DOUBLE_EQ(importance_score(first, 0, {1.0, 1.5}, 1.0, 0.1), 1.0);
  EXPECT_THROW(importance_score(first, 1, {1.0, 1.5}, 1.0, 0.1), std::invalid_argument);
}

TEST(Adaptive, SeedsDependOnNameAndRunSeed) {
  EXPECT_NE(knot_seed(1, "3_1"), knot_seed(1, "4_1"));
  EXPECT_NE(knot_seed(1, "3_1"), knot_seed(2, "3_1"));
  EXPECT_EQ(knot_seed(7, "12a_1019"), knot_seed(7, "12a_1019"));
}

TEST(Pipeline, ExploreKnotStoresRunsEquilibriaAndClusters) {
  ExploreOptions o;
  o.sampling.vertices = 100;
  o.samples = 6;
  o.jobs = 2;
  const KnotRecord& k = KnotTable::global().at("5_2");
  const KnotEntry e = explore_knot(k, o);
  EXPECT_EQ(e.runs.size(), 6u);
  EXPECT_EQ(e.samples_used, 6);
  EXPECT_EQ(e.alexander, alexander(*k.pd).coefficients);
  int stable = 0;
  for (const auto& r : e.runs) {
    EXPECT_TRUE(r.alexander_preserved);
    if (r.status == "converged-stable") {
      ASSERT_GE(r.equilibrium, 0);
      ++stable;
    } else {
      EXPECT_EQ(r.equilibrium, -1);
    }
  }
  ASSERT_EQ(static_cast<int>(e.equilibria.size()), stable);
  ASSERT_GT(stable, 0);
  ASSERT_EQ(e.attributes.rows(), stable);
  ASSERT_EQ(e.attributes.cols(), static_cast<Eigen::Index>(dataset_attribute_names().size()));
  EXPECT_TRUE(e.attributes.allFinite());
  for (const auto& P : e.equilibria) {
    EXPECT_EQ(P.rows(), 100);
    EXPECT_EQ(alexander(P), alexander(*k.pd));  // every stored equilibrium keeps the knot type
  }
  // Milnor: total curvature above 2π · bridge index for every equilibrium
  const int tc = e.attribute_column("total_curvature");
  for (Eigen::Index i = 0; i < e.attributes.rows(); ++i) EXPECT_GT(e.attributes(i, tc), 2 * M_PI * 2);
  ASSERT_EQ(e.similarity.rows(), stable);
  EXPECT_LT((e.similarity - e.similarity.transpose()).cwiseAbs().maxCoeff(), 1e-12);
  for (int i = 0; i < stable; ++i) EXPECT_DOUBLE_EQ(e.similarity(i, i), 1.0);
  EXPECT_EQ(e.linkage.rows(), stable - 1);

  // clusters_at_cut: a partition, sorted by energy, lowest-energy representative,
  // members of one cluster within the cut of each other (complete linkage)
  for (double cut : {0.0, 0.05, 0.3, 2.0}) {
    std::vector<int> rank;
    const auto clusters = clusters_at_cut(e, cut, &rank);
    ASSERT_EQ(rank.size(), static_cast<size_t>(stable));
    const int ec = e.attribute_column("energy");
    size_t total = 0;
    for (size_t c = 0; c < clusters.size(); ++c) {
      const auto& cl = clusters[c];
      total += cl.members.size();
      if (c > 0) {
        EXPECT_LE(clusters[c - 1].energy_min, cl.energy_min);
      }
      EXPECT_EQ(e.attributes(cl.representative, ec), cl.energy_min);
      for (int i : cl.members) {
        EXPECT_EQ(rank[static_cast<size_t>(i)], static_cast<int>(c));
        EXPECT_GE(e.attributes(i, ec), cl.energy_min);
        EXPECT_LE(e.attributes(i, ec), cl.energy_max);
        for (int j : cl.members) EXPECT_LE(1.0 - e.similarity(i, j), cut + 1e-12);
      }
    }
    EXPECT_EQ(total, static_cast<size_t>(stable));
    if (cut >= 2.0) {
      EXPECT_EQ(clusters.size(), 1u);  // distances are at most 2
    }
  }
}

TEST(Pipeline, AdaptiveSamplingStopsAndRecordsScores) {
  ExploreOptions o;
  o.sampling.vertices = 100;
  o.adaptive = true;
  o.initial_samples = 4;
  o.batch_samples = 2;
  o.max_samples = 10;
  o.jobs = 2;
  const KnotEntry e = explore_knot(KnotTable::global().at("4_1"), o);
  ASSERT_FALSE(e.score_history.empty());
  EXPECT_EQ(e.samples_used, 4 + 2 * (static_cast<int>(e.score_history.size()) - 1));
  EXPECT_LE(e.samples_used, 10);
  for (double S : e.score_history) {
    EXPECT_GE(S, 0.0);
    EXPECT_LE(S, 1.0);
  }
  // stopped because of the score or the cap
  EXPECT_TRUE(e.score_history.back() <= o.score_threshold || e.samples_used == o.max_samples);
  for (size_t b = 0; b + 1 < e.score_history.size(); ++b) EXPECT_GT(e.score_history[b], o.score_threshold);
}

TEST(Pipeline, SameSeedSameEquilibriaWhateverTheJobs) {
  ExploreOptions o = small_fixed_run(4, 1);
  const KnotEntry a = explore_knot(KnotTable::global().at("3_1"), o);
  o.jobs = 3;
  const KnotEntry b = explore_knot(KnotTable::global().at("3_1"), o);
  ASSERT_EQ(a.equilibria.size(), b.equilibria.size());
  for (size_t i = 0; i < a.equilibria.size(); ++i) EXPECT_EQ(a.equilibria[i], b.equilibria[i]);
  o.seed = 2;
  const KnotEntry c = explore_knot(KnotTable::global().at("3_1"), o);
  ASSERT_FALSE(c.runs.empty());
  EXPECT_NE(c.runs[0].seed, a.runs[0].seed);
}

// Burn-in: sample k of a run with burn-in B is sample B + k of the same walk
// without burn-in (same seed, same curve, so the same equilibrium), and the
// burn-in is part of the sampling description (so a data set, journal or
// work part made with another burn-in is not reused: see the next test).
TEST(Pipeline, BurnInDropsTheWalksFirstSamples) {
  ExploreOptions o = small_fixed_run(5, 2);
  const KnotRecord& k = KnotTable::global().at("3_1");
  const KnotEntry plain = explore_knot(k, o);
  o.burn_in = 3;
  o.samples = 2;
  const KnotEntry burnt = explore_knot(k, o);
  ASSERT_EQ(burnt.runs.size(), 2u);
  for (int s = 0; s < 2; ++s) {
    const RunRecord& a = burnt.runs[static_cast<size_t>(s)];
    const RunRecord& b = plain.runs[static_cast<size_t>(3 + s)];
    EXPECT_EQ(a.sample, s);
    EXPECT_EQ(a.seed, b.seed) << s;
    EXPECT_EQ(a.status, b.status) << s;
    EXPECT_EQ(a.energy, b.energy) << s;
    ASSERT_GE(a.equilibrium, 0);
    ASSERT_GE(b.equilibrium, 0);
    EXPECT_EQ(burnt.equilibria[static_cast<size_t>(a.equilibrium)], plain.equilibria[static_cast<size_t>(b.equilibrium)]);
  }
  EXPECT_NE(burnt.runs[0].seed, plain.runs[0].seed);
  EXPECT_EQ(o.sampling_description(), "fixed:2,burn-in=3");
  o.burn_in = 0;
  EXPECT_EQ(o.sampling_description(), "fixed:2");  // unchanged without burn-in
  o.burn_in = -1;
  EXPECT_THROW(o.validate(), InputError);
}

// A finished per-knot part left in the work folder by an interrupted run is
// reused only by a run with the same parameters, sampling and seed; a rerun
// with another burn-in or seed recomputes it.
TEST(Pipeline, WorkPartsAreReusedOnlyWithTheSameSamplingAndSeed) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("ek_parts_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string out = (dir / "d.h5").string();
  const KnotRecord& k = KnotTable::global().at("3_1");
  const ExploreOptions made = small_fixed_run(2, 2);
  const KnotEntry entry = explore_knot(k, made);
  auto leave_part = [&]() {  // what an interrupted run leaves behind
    fs::remove(out);
    fs::create_directories(out + ".work");
    DatasetMetadata meta = dataset_metadata(made);
    meta.created = "2026-01-01T00:00:00Z";
    DatasetWriter w(out + ".work/3_1.h5", meta);
    w.add(entry);
    w.commit();
  };
  auto rerun = [&](const ExploreOptions& o) {
    DatasetRunOptions ro;
    ro.explore = o;
    ro.knots = {&k};
    ro.output = out;
    ro.progress = false;
    return run_dataset(ro);
  };
  auto expect_recomputed = [&](const ExploreOptions& o, const char* what) {
    leave_part();
    const DatasetRunSummary r = rerun(o);
    EXPECT_EQ(r.knots_resumed, 0) << what;
    EXPECT_EQ(r.runs, 2) << what;
  };
  leave_part();
  const DatasetRunSummary same = rerun(made);
  EXPECT_EQ(same.knots_resumed, 1);
  EXPECT_EQ(same.runs, 0);
  ExploreOptions burnt = made;
  burnt.burn_in = 3;
  expect_recomputed(burnt, "another burn-in");
  EXPECT_EQ(DatasetReader(out).metadata().sampling, "fixed:2,burn-in=3");
  ExploreOptions reseeded = made;
  reseeded.seed = 2;
  expect_recomputed(reseeded, "another seed");
  fs::remove_all(dir);
}

TEST(Pipeline, BadOptionsAreInputErrors) {
  ExploreOptions o;
  o.sampling.vertices = 101;  // lattice polygons have an even number of edges
  EXPECT_THROW(o.validate(), InputError);
  o = ExploreOptions{};
  o.jobs = 0;
  EXPECT_THROW(o.validate(), InputError);
  EXPECT_THROW(parse_shard("3/2"), InputError);
  EXPECT_THROW(parse_shard("a/b"), InputError);
  EXPECT_EQ(parse_shard("2/8"), std::make_pair(1, 8));
}

TEST(Pipeline, AdaptiveRunIsAPrefixOfTheFixedRunAndReplayAgrees) {
  const ExploreOptions fixed = small_fixed_run(10, 2);
  const KnotRecord& k = KnotTable::global().at("4_1");
  const KnotEntry full = explore_knot(k, fixed);
  ExploreOptions adaptive = fixed;
  adaptive.adaptive = true;
  adaptive.initial_samples = 4;
  adaptive.batch_samples = 2;
  adaptive.max_samples = 10;
  adaptive.score_threshold = 0.0;  // any novelty continues: exercises several batches
  const KnotEntry a = explore_knot(k, adaptive);
  ASSERT_LE(a.samples_used, 10);
  for (int s = 0; s < a.samples_used; ++s) {
    EXPECT_EQ(a.runs[s].status, full.runs[s].status) << s;
    if (a.runs[s].equilibrium >= 0) {
      EXPECT_EQ(a.equilibria[a.runs[s].equilibrium], full.equilibria[full.runs[s].equilibrium]) << s;
    }
  }
  const AdaptiveReplay replay = replay_adaptive(full, adaptive);
  EXPECT_EQ(replay.samples_used, a.samples_used);
  ASSERT_EQ(replay.score_history.size(), a.score_history.size());
  for (size_t b = 0; b < a.score_history.size(); ++b) EXPECT_DOUBLE_EQ(replay.score_history[b], a.score_history[b]);
}

// Section 7.1 "Symmetries": mirror images count as the same state exactly for
// amphicheiral knots (KnotInfo symmetry type); reversal always (a wire has no
// orientation).
TEST(Pipeline, MirrorComparisonsForAmphicheiralKnotsOnly) {
  const ExploreOptions o;
  EXPECT_TRUE(o.similarity.reversal);
  EXPECT_FALSE(o.similarity.mirror);
  for (const auto& [name, mirror] : std::vector<std::pair<std::string, bool>>{
           {"3_1", false}, {"4_1", true}, {"6_3", true}, {"5_2", false}, {"8_17", true}, {"9_32", false}}) {
    const KnotRecord& k = KnotTable::global().at(name);
    EXPECT_EQ(options_for_knot(o, k).similarity.mirror, mirror) << name << " (" << k.symmetry_type << ")";
    EXPECT_TRUE(options_for_knot(o, k).similarity.reversal) << name;
  }
  ExploreOptions off;
  off.mirror_amphicheiral = false;
  EXPECT_FALSE(options_for_knot(off, KnotTable::global().at("4_1")).similarity.mirror);
}
