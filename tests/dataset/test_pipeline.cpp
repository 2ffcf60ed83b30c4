#include <gtest/gtest.h>
#include <hdf5.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>

#include "ek/core/errors.hpp"
#include "ek/dataset/run.hpp"
#include "ek/knots/alexander.hpp"
#include "testing.hpp"
#include "unsealed_copy.hpp"

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

// The unseen rule by hand (δ = 0.1, low = 1.1 · lowest, batches of 10).
TEST(Adaptive, UnseenScoreByHand) {
  ExploreOptions o;
  o.stopping = StoppingRule::Unseen;
  o.novelty_distance = 0.1;
  StoppingScore score(o);
  // equilibria 0 and 1 alike (distance 0.02), 2 apart (distance 0.5) at 1.05
  // times the lowest: states {0, 1} and {2}, one low-energy singleton in 3
  // samples: p = 1/3, P = 1 − (2/3)¹⁰
  Eigen::MatrixXd first(3, 3);
  first << 1.0, 0.0, 0.0,  //
      0.98, 1.0, 0.0,      //
      0.5, 0.5, 1.0;
  EXPECT_NEAR(score.add_batch(first, {1.0, 1.0, 1.05}), 1.0 - std::pow(2.0 / 3.0, 10), 1e-12);
  // a second sample of state {2}: no singleton left, P = 0
  Eigen::MatrixXd second(1, 4);
  second << 0.5, 0.5, 0.97, 1.0;
  EXPECT_DOUBLE_EQ(score.add_batch(second, {1.06}), 0.0);
  // a new state at twice the lowest energy is not low: still 0
  Eigen::MatrixXd third(1, 5);
  third << 0.2, 0.2, 0.3, 0.3, 1.0;
  EXPECT_DOUBLE_EQ(score.add_batch(third, {2.0}), 0.0);
  // a batch without a stable equilibrium keeps P; a new low state: 1 singleton in 6 samples
  EXPECT_DOUBLE_EQ(score.add_batch(Eigen::MatrixXd(0, 5), {}), 0.0);
  Eigen::MatrixXd fourth(1, 6);
  fourth << 0.3, 0.3, 0.3, 0.3, 0.3, 1.0;
  EXPECT_NEAR(score.add_batch(fourth, {0.99}), 1.0 - std::pow(5.0 / 6.0, 10), 1e-12);
  EXPECT_THROW(score.add_batch(fourth, {1.0, 2.0}), std::invalid_argument);
}

TEST(Adaptive, StoppingRulesAreNamedInTheParameters) {
  ExploreOptions o;
  o.adaptive = true;
  o.novelty_distance = 0.05;
  EXPECT_EQ(o.sampling_description(), "adaptive:50+10,max=500,S>0.1,delta=0.05");
  o.stopping = parse_stopping_rule("unseen");
  EXPECT_EQ(o.sampling_description(), "adaptive:50+10,max=500,unseen<0.1,low=1.1,delta=0.05");
  EXPECT_EQ(to_string(o.stopping), "unseen");
  EXPECT_THROW(parse_stopping_rule("chao"), InputError);
  o.new_state_threshold = 1.0;
  EXPECT_THROW(o.validate(), InputError);
  o.new_state_threshold = 0.1;
  o.low_energy_factor = 0.9;
  EXPECT_THROW(o.validate(), InputError);
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
    EXPECT_TRUE(r.topology_preserved);
    if (r.status == RunStatus::ConvergedStable) {
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
  // the replay reads the stored similarities (computed pairwise in the other order): equal to rounding
  const AdaptiveReplay replay = replay_adaptive(full, adaptive);
  EXPECT_EQ(replay.samples_used, a.samples_used);
  ASSERT_EQ(replay.score_history.size(), a.score_history.size());
  for (size_t b = 0; b < a.score_history.size(); ++b) EXPECT_NEAR(replay.score_history[b], a.score_history[b], 1e-12);
  // the unseen rule, continuing while any low-energy state is seen once
  adaptive.stopping = StoppingRule::Unseen;
  adaptive.new_state_threshold = 0.0;
  const KnotEntry u = explore_knot(k, adaptive);
  const AdaptiveReplay ur = replay_adaptive(full, adaptive);
  EXPECT_EQ(ur.samples_used, u.samples_used);
  ASSERT_EQ(ur.score_history.size(), u.score_history.size());
  for (size_t b = 0; b < u.score_history.size(); ++b) {
    EXPECT_GE(u.score_history[b], 0.0);
    EXPECT_LE(u.score_history[b], 1.0);
    EXPECT_NEAR(ur.score_history[b], u.score_history[b], 1e-12);
  }
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

namespace {

/// The journal key as earlier versions wrote it (their journals must still
/// resume): a copy of their key function.
std::string earlier_journal_key(const std::string& knot, const ExploreOptions& o) {
  std::ostringstream s;
  s.precision(17);
  const ResolvedModel r = resolve_model(o.relax, 1.0);
  s << "knot=" << knot << " young=" << o.relax.material.young << " poisson=" << o.relax.material.poisson
    << " radius=" << o.relax.material.radius << " n=" << o.sampling.vertices << " tol=" << r.tolerance
    << " omega=" << r.contact_stiffness << " dhat=" << r.dhat << " iterations=" << o.relax.max_iterations
    << " sampling=" << o.sampling_description() << " grow=" << o.sampling.grow_fugacity
    << " shrink=" << o.sampling.shrink_fugacity << " growth=" << o.sampling.growth_factor
    << " decorrelation=" << o.sampling.decorrelation_moves << " seed=" << o.seed << " stiffness=" << o.stiffness;
  if (!o.relax.contact_continuation.empty()) s << " continuation=" << continuation_text(o.relax.contact_continuation);
  return s.str();
}

/// One parameter of a run changed: the field that must name it, and the change.
struct Change {
  std::string field;
  std::function<void(ExploreOptions&)> apply;
};

/// Every field of the table that ExploreOptions reaches, changed in turn
/// (edge_length is fixed by the lattice: unit edges).
std::vector<Change> every_parameter_change() {
  return {
      {"young", [](ExploreOptions& o) { o.relax.material.young = 2500.0; }},
      {"poisson", [](ExploreOptions& o) { o.relax.material.poisson = 0.35; }},
      {"radius", [](ExploreOptions& o) { o.relax.material.radius = 0.15; }},
      {"vertices", [](ExploreOptions& o) { o.sampling.vertices = 120; }},
      {"tolerance", [](ExploreOptions& o) { o.relax.tolerance = 1e-7; }},
      {"contact_stiffness", [](ExploreOptions& o) { o.relax.contact_stiffness = 2000.0; }},
      {"dhat", [](ExploreOptions& o) { o.relax.dhat = 0.5; }},
      {"twist_model", [](ExploreOptions& o) { o.relax.full_model = true; }},
      {"relax_method", [](ExploreOptions& o) { o.relax.method = RelaxMethod::Direct; }},
      {"coarse_levels", [](ExploreOptions& o) { o.relax.coarse_levels = 2; }},
      {"coarse_continuation", [](ExploreOptions& o) { o.relax.coarse_continuation = {1e-2}; }},
      {"coarsening", [](ExploreOptions& o) { o.relax.coarsening.either_parity = true; }},
      {"newton_hessian", [](ExploreOptions& o) { o.relax.newton.hessian = HessianMode::Exact; }},
      {"remove_rigid_motions", [](ExploreOptions& o) { o.relax.newton.remove_rigid_motions = false; }},
      {"contact_hessian", [](ExploreOptions& o) { o.relax.contact_gauss_newton = true; }},
      {"damp_short_steps", [](ExploreOptions& o) { o.relax.newton.damp_short_steps = true; }},
      {"max_iterations", [](ExploreOptions& o) { o.relax.max_iterations = 300; }},
      {"burn_in", [](ExploreOptions& o) { o.burn_in = 2; }},
      {"sampling", [](ExploreOptions& o) { o.samples = 2; }},
      {"sampling", [](ExploreOptions& o) { o.adaptive = true; }},
      {"grow_fugacity", [](ExploreOptions& o) { o.sampling.grow_fugacity = 0.45; }},
      {"shrink_fugacity", [](ExploreOptions& o) { o.sampling.shrink_fugacity = 0.12; }},
      {"growth_factor", [](ExploreOptions& o) { o.sampling.growth_factor = 8.0; }},
      {"decorrelation_moves", [](ExploreOptions& o) { o.sampling.decorrelation_moves = 100; }},
      {"seed", [](ExploreOptions& o) { o.seed = 2; }},
      {"compute_stiffness", [](ExploreOptions& o) { o.stiffness = !o.stiffness; }},
      {"contact_continuation", [](ExploreOptions& o) { o.relax.contact_continuation = {1e-3}; }},
  };
}

DatasetRunSummary run_one_knot(const ExploreOptions& o, const std::string& knot, const std::string& out) {
  DatasetRunOptions ro;
  ro.explore = o;
  ro.knots = {&KnotTable::global().at(knot)};
  ro.output = out;
  ro.progress = false;
  return run_dataset(ro);
}

std::string fresh_dir(const std::string& name) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("ek_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

}  // namespace

// Journals written by earlier versions keep their key, so an interrupted run
// resumes after an upgrade; the parameters added to the key since (model,
// edge length, relaxation method) are left out at the values those keys
// imply. Earlier versions relaxed by the direct method (with eigen-projected
// contact pair Hessians, undamped: the "hybrid" method).
TEST(Pipeline, JournalKeyIsTheEarlierKeyForTheEarlierParameters) {
  ExploreOptions direct = small_fixed_run(3, 1);
  direct.relax = with_method(direct.relax, "hybrid");
  std::vector<ExploreOptions> runs(6, direct);
  runs[1] = ExploreOptions{};
  runs[1].relax = with_method(runs[1].relax, "hybrid");
  runs[2].relax.contact_continuation = {1e-3, 0.1};
  runs[3].adaptive = true;
  runs[3].burn_in = 4;
  runs[4].relax.material.radius = 0.15;
  runs[4].relax.max_iterations = 300;
  runs[5].seed = 12345;
  runs[5].sampling.decorrelation_moves = 1000;
  for (const auto& o : runs)
    EXPECT_EQ("knot=3_1 " + journal_key(dataset_metadata(o)), earlier_journal_key("3_1", o));
  ExploreOptions full = runs[0];
  full.relax.full_model = true;
  EXPECT_NE(journal_key(dataset_metadata(full)).find(" dhat=0.40000000000000002 model=free-theta iterations="),
            std::string::npos);
  // every named method of with_method() has its own key and metadata, but
  // for gauss-newton and two-level, the default's former names
  std::set<std::string> keys;
  for (const std::string& name : method_names()) {
    ExploreOptions o = small_fixed_run(3, 1);
    o.relax = with_method(o.relax, name);
    keys.insert(journal_key(dataset_metadata(o)));
    if (name == "hybrid") {
      EXPECT_EQ(journal_key(dataset_metadata(o)), journal_key(dataset_metadata(direct)));
    }
    const bool the_default = name == "default" || name == "gauss-newton" || name == "two-level";
    if (the_default) {
      EXPECT_EQ(dataset_metadata(o).contact_hessian, "gauss-newton");
      EXPECT_EQ(dataset_metadata(o).damp_short_steps, true);
      EXPECT_NE(journal_key(dataset_metadata(o)).find(" contact=gauss-newton"), std::string::npos);
    }
    if (the_default) {
      EXPECT_EQ(dataset_metadata(o).coarse_levels, 2);
      const std::string rule = "either-parity,recheck-30x6,min-100";
      EXPECT_EQ(dataset_metadata(o).coarsening, rule);
      EXPECT_NE(journal_key(dataset_metadata(o)).find(" levels=2 coarse=0.001 coarsening=" + rule + " "),
                std::string::npos);
    } else {  // one-level and eigen-projected: the multilevel method before two levels, with its earlier keys
      EXPECT_EQ(dataset_metadata(o).coarsening, "even");
      EXPECT_EQ(journal_key(dataset_metadata(o)).find(" coarsening="), std::string::npos);
    }
    if (name == "one-level" || name == "eigen-projected") EXPECT_EQ(dataset_metadata(o).coarse_levels, 1);
    if (name == "eigen-projected") {
      EXPECT_EQ(dataset_metadata(o).contact_hessian, "eigen-projected");
      EXPECT_EQ(dataset_metadata(o).damp_short_steps, false);
      EXPECT_EQ(journal_key(dataset_metadata(o)).find(" contact="), std::string::npos);
    }
  }
  EXPECT_EQ(keys.size(), method_names().size() - 2);
  // the multilevel method (the default) names itself and its settings
  const std::string multilevel = journal_key(dataset_metadata(small_fixed_run(3, 1)));
  EXPECT_NE(multilevel.find(" dhat=0.40000000000000002 method=multilevel levels=2 coarse=0.001 "
                            "coarsening=either-parity,recheck-30x6,min-100 contact=gauss-newton damp=1 iterations=5000 "),
            std::string::npos)
      << multilevel;
  // one-level has the key of the default before two levels
  ExploreOptions one = small_fixed_run(3, 1);
  one.relax = with_method(one.relax, "one-level");
  EXPECT_NE(journal_key(dataset_metadata(one)).find(" dhat=0.40000000000000002 method=multilevel levels=1 coarse=0.001 "
                                                    "contact=gauss-newton damp=1 iterations=5000 "),
            std::string::npos);
}

// Every parameter changed in turn: extending a data set is refused with one
// line naming the parameter, and the file and its folder are left as they were.
// The journal key changes too (an interrupted run's journal is not reused).
TEST(Pipeline, ExtendingNeedsEveryParameterEqual) {
  namespace fs = std::filesystem;
  const std::string dir = fresh_dir("extend");
  const std::string out = dir + "/d.h5";
  ExploreOptions base = small_fixed_run(1, 1);
  // eigen-projected, undamped: so that the damping can change alone (the
  // Gauss–Newton pair Hessians always damp)
  base.relax = with_method(base.relax, "eigen-projected");
  ASSERT_EQ(run_one_knot(base, "3_1", out).runs, 1);
  const std::string before = fixtures::read_bytes(out);
  std::set<std::string> covered = {"edge_length"};
  for (const Change& change : every_parameter_change()) {
    ExploreOptions o = base;
    change.apply(o);
    covered.insert(change.field);
    EXPECT_NE(journal_key(dataset_metadata(o)), journal_key(dataset_metadata(base))) << change.field;
    try {
      run_one_knot(o, "4_1", out);
      ADD_FAILURE() << "extended with another " << change.field;
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("exists with different parameters (" + change.field + " "), std::string::npos) << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
    EXPECT_EQ(fixtures::read_bytes(out), before) << change.field;
    EXPECT_FALSE(fs::exists(out + ".work")) << change.field;
  }
  for (const auto& f : metadata_fields()) {
    if (f.match != FieldMatch::Provenance) {
      EXPECT_TRUE(covered.count(f.name)) << f.name << " is not tested";
    }
  }
  fs::remove_all(dir);
}

// A file written before the newer attributes existed (no relaxation method,
// Newton settings, BFACF schedule, burn-in, stiffness flag or continuation;
// -1 for the iteration cap) reads with the documented values and is extended by a run
// with default-equivalent parameters (the direct method of earlier versions);
// the extended file records only what both runs know.
TEST(Pipeline, OldFormatFileReadsAndExtends) {
  namespace fs = std::filesystem;
  const std::string dir = fresh_dir("oldformat");
  const std::string out = dir + "/d.h5";
  ExploreOptions base = small_fixed_run(1, 1);
  base.relax = with_method(base.relax, "hybrid");  // the method of earlier versions
  ASSERT_EQ(run_one_knot(base, "3_1", out).runs, 1);
  // files of earlier versions carry no checksum either
  fixtures::write_unsealed_copy(out, out + ".old");
  fs::rename(out + ".old", out);
  const hid_t f = H5Fopen(out.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  for (const char* name : {"relax_method", "newton_hessian", "remove_rigid_motions", "contact_hessian",
                           "damp_short_steps", "coarsening", "grow_fugacity", "shrink_fugacity", "growth_factor",
                           "decorrelation_moves", "burn_in", "compute_stiffness", "contact_continuation",
                           "max_iterations"})
    ASSERT_GE(H5Adelete(f, name), 0) << name;
  const long long unknown = -1;
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t a = H5Acreate2(f, "max_iterations", H5T_STD_I64LE, space, H5P_DEFAULT, H5P_DEFAULT);
  H5Awrite(a, H5T_NATIVE_LLONG, &unknown);
  H5Aclose(a);
  H5Sclose(space);
  H5Fclose(f);
  {
    const DatasetMetadata m = DatasetReader(out).metadata();
    EXPECT_EQ(m.relax_method, "direct");
    EXPECT_FALSE(m.coarse_levels || m.coarse_continuation || m.newton_hessian || m.remove_rigid_motions);
    EXPECT_EQ(m.grow_fugacity, 0.40);
    EXPECT_EQ(m.shrink_fugacity, 0.10);
    EXPECT_EQ(m.growth_factor, 10.0);
    EXPECT_EQ(m.decorrelation_moves, 0);
    EXPECT_EQ(m.contact_continuation, std::vector<double>{});
    EXPECT_EQ(m.contact_hessian, "eigen-projected");
    EXPECT_EQ(m.damp_short_steps, false);
    EXPECT_EQ(m.coarsening, "even");
    EXPECT_FALSE(m.max_iterations || m.burn_in || m.compute_stiffness);
    EXPECT_EQ(m.difference(dataset_metadata(base)), "");
  }
  ASSERT_EQ(run_one_knot(base, "4_1", out).runs, 1);
  const DatasetReader r(out);
  EXPECT_EQ(r.knot_names(), (std::vector<std::string>{"3_1", "4_1"}));
  EXPECT_FALSE(r.metadata().max_iterations || r.metadata().burn_in || r.metadata().compute_stiffness);
  EXPECT_EQ(r.metadata().grow_fugacity, 0.40);
  // not recorded matches any value; a documented value must match
  ExploreOptions other = base;
  other.stiffness = true;
  other.relax.max_iterations = 300;
  EXPECT_EQ(r.metadata().difference(dataset_metadata(other)), "");
  other.sampling.grow_fugacity = 0.45;
  EXPECT_EQ(r.metadata().difference(dataset_metadata(other)), "grow_fugacity 0.4 vs 0.45");
  ExploreOptions multilevel = small_fixed_run(1, 1);
  multilevel.relax = with_method(multilevel.relax, "eigen-projected");
  EXPECT_EQ(r.metadata().difference(dataset_metadata(multilevel)), "relax_method direct vs multilevel");
  fs::remove_all(dir);
}

// Merge compares every pair of inputs: a parameter that the first input does
// not record must still agree between the others; the merge records only what
// every input records.
TEST(Pipeline, MergeComparesEveryPairOfInputs) {
  namespace fs = std::filesystem;
  const std::string dir = fresh_dir("mergepairs");
  DatasetMetadata meta = dataset_metadata(small_fixed_run(1, 1));
  meta.created = "2026-01-01T00:00:00Z";
  auto write = [&](const std::string& name, const std::string& knot, std::optional<bool> stiffness) {
    DatasetMetadata m = meta;
    m.compute_stiffness = stiffness;
    KnotEntry e;  // no equilibria: only the parameters matter here
    e.name = knot;
    e.alexander = {1};
    DatasetWriter w(dir + "/" + name, m);
    w.add(e);
    w.commit();
    return dir + "/" + name;
  };
  const std::string a = write("a.h5", "3_1", std::nullopt), b = write("b.h5", "4_1", false),
                    c = write("c.h5", "5_1", true);
  try {
    merge_datasets({a, b, c}, dir + "/abc.h5");
    ADD_FAILURE() << "merged inputs with different stiffness flags";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'" + c + "' has different parameters from '" + b +
                                         "' (compute_stiffness 0 vs 1)"),
              std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(fs::exists(dir + "/abc.h5"));
  merge_datasets({a, b}, dir + "/ab.h5");
  const DatasetReader r(dir + "/ab.h5");
  EXPECT_EQ(r.knot_names(), (std::vector<std::string>{"3_1", "4_1"}));
  EXPECT_FALSE(r.metadata().compute_stiffness.has_value());
  EXPECT_EQ(r.metadata().difference(meta), "");
  fs::remove_all(dir);
}
