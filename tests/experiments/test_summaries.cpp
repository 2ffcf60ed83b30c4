// The summaries of the paper experiments (experiments/schema): every struct
// survives a round trip through the JSON that the experiments write, keys are
// the field names in declaration order, a missing required key is an error
// naming it, and optional keys (values that may be absent) may be null or missing.
#include <gtest/gtest.h>

#include "adaptive_summary.hpp"
#include "cross_topology_summary.hpp"
#include "dataset_summary.hpp"
#include "filters_summary.hpp"
#include "generalization_summary.hpp"
#include "hausdorff_summary.hpp"
#include "jumping_dynamics_summary.hpp"
#include "jumping_knots_summary.hpp"
#include "loads_summary.hpp"
#include "milnor_summary.hpp"
#include "multistability_summary.hpp"
#include "periodic_braids_summary.hpp"
#include "planarity_summary.hpp"
#include "puzzles_summary.hpp"
#include "saddles_summary.hpp"
#include "thresholds.hpp"
#include "time_vs_error_summary.hpp"

using namespace ek::results;
using nlohmann::json;
using nlohmann::ordered_json;

namespace {
/// Written as the experiments write it (ordered, dumped) and read back as the checks read it.
template <class S>
S round_trip(const S& s) {
  return parse_summary<S>(json::parse(ordered_json(s).dump(2)), "test");
}
}  // namespace

TEST(Summaries, AdaptiveRoundTrip) {
  AdaptiveSummary s;
  s.scale = "ci";
  s.knots = 7;
  s.score_threshold = 0.1;
  s.low_energy_factor = 1.2;
  s.low_energy_clusters = 30;
  s.low_energy_clusters_found = 28;
  s.missed_samples = 3;
  s.missed_sample_share = 3.0 / 420;
  s.missed = {{"5_2", 1.5, 1.4, 2}, {"6_1", 2.5, 2.2, 1}};
  s.paper_rule.saved_share_lower_bound = 0.377;
  s.shuffled.orders_per_knot = 20;
  AdaptiveRuleReplay unseen;
  unseen.rule = "unseen";
  unseen.median_samples = 80.0;
  unseen.low_energy_states_found_mean = 591.0;
  unseen.chain_low_energy_states_found = 520;
  s.rules = {AdaptiveRuleReplay{}, unseen};
  const AdaptiveSummary r = round_trip(s);
  EXPECT_EQ(r.knots, 7);
  EXPECT_EQ(r.missed_samples, std::optional<long>(3));
  ASSERT_EQ(r.missed.size(), 2u);
  EXPECT_EQ(r.missed[1].knot, "6_1");
  EXPECT_EQ(r.missed[0].samples, std::optional<long>(2));
  EXPECT_DOUBLE_EQ(r.paper_rule.saved_share_lower_bound, 0.377);
  EXPECT_EQ(r.shuffled.orders_per_knot, 20);
  ASSERT_EQ(r.rules.size(), 2u);
  EXPECT_EQ(r.rules[1].rule, "unseen");
  EXPECT_DOUBLE_EQ(r.rules[1].median_samples, 80.0);
  EXPECT_DOUBLE_EQ(r.rules[1].low_energy_states_found_mean, 591.0);
  EXPECT_EQ(r.rules[1].chain_low_energy_states_found, 520);
  // keys in declaration order, as the experiment writes them: the rules' replays last
  const ordered_json j = s;
  EXPECT_EQ(j.begin().key(), "scale");
  EXPECT_EQ(j.back().size(), 2u);
  EXPECT_EQ(j.back()[1].size(), ordered_json(unseen).size());
}

// An optional field (a value that may be absent) reads as empty when its
// key is null or missing; every other key is required.
TEST(Summaries, OptionalKeysMayBeAbsentRequiredOnesMayNot) {
  json j = ordered_json(DatasetSummary{});
  j.erase("full_table_estimate");
  EXPECT_FALSE(parse_summary<DatasetSummary>(j, "x").full_table_estimate.has_value());
  j = ordered_json(AdaptiveSummary{});
  j.erase("missed_sample_share");
  EXPECT_THROW(parse_summary<AdaptiveSummary>(j, "x"), std::runtime_error);
}

TEST(Summaries, MissingRequiredKeyNamesIt) {
  json j = ordered_json(MilnorSummary{});
  j.erase("top_decile_size");
  try {
    parse_summary<MilnorSummary>(j, "results/ci/milnor/summary.json");
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("top_decile_size"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("results/ci/milnor/summary.json"), std::string::npos) << e.what();
  }
  j = ordered_json(MilnorSummary{});
  j["knots"] = "many";  // a wrong type is an error too
  EXPECT_THROW(parse_summary<MilnorSummary>(j, "x"), std::runtime_error);
}

// Typed flags and null for "not tabulated"; a missing required field (here
// the symmetric critical point) is an error naming it; the optional 3D
// search is null when absent.
TEST(Summaries, PeriodicBraidsFlagsAndRequiredFields) {
  PeriodicBraidsSummary s;
  s.scale = "ci";
  PeriodicMember m;
  m.family = "s1s2i";
  m.p = 2;
  m.knot = "4_1";
  m.alexander_matches_table = true;
  m.symmetric_critical_point.index = 0;
  m.symmetric_critical_point.modes.push_back({-1.5e-6, 1, {0.0, 1.0}});
  s.members.push_back(m);
  m.p = 7;
  m.knot.reset();
  m.alexander_matches_table.reset();
  m.three_d_search = PeriodicThreeDSearch{};
  m.three_d_search->gradient_norm = 3e-3;
  s.members.push_back(m);
  const ordered_json j = s;
  EXPECT_TRUE(j["members"][0]["alexander_matches_table"].is_boolean());
  EXPECT_TRUE(j["members"][1]["alexander_matches_table"].is_null());
  EXPECT_TRUE(j["members"][1]["knot"].is_null());
  EXPECT_TRUE(j["members"][0]["three_d_search"].is_null());
  const auto r = round_trip(s);
  EXPECT_EQ(r.members[0].tabulated(), "4_1");
  EXPECT_EQ(r.members[0].symmetric_critical_point.modes.at(0).dominant_class, 1);
  EXPECT_EQ(r.members[1].tabulated(), "");
  EXPECT_EQ(r.members[1].three_d_search->gradient_norm, 3e-3);
  json bad = j;
  bad["members"][0].erase("symmetric_critical_point");
  EXPECT_THROW(parse_summary<PeriodicBraidsSummary>(bad, "bad"), std::runtime_error);
  bad = j;
  bad["members"][0]["alexander_matches_table"] = "yes";
  EXPECT_THROW(parse_summary<PeriodicBraidsSummary>(bad, "bad"), std::runtime_error);
}

// The per-knot objects sit under the knot names at the top level.
TEST(Summaries, MultistabilityKnotsByName) {
  MultistabilitySummary s;
  s.scale = "default";
  s.cut = kClusterCut;
  s.planar_threshold = kPlanarThreedim;
  s.knots["8_1"] = {150, 150, 9, 5, 5.0 / 9};
  s.knots["4_1"] = {150, 149, 8, 7, 7.0 / 8};
  const ordered_json j = s;
  EXPECT_EQ(j["8_1"]["distinct"], 9);
  const auto r = round_trip(s);
  ASSERT_EQ(r.knots.size(), 2u);
  EXPECT_EQ(r.knots.at("4_1").equilibria, 149);
  EXPECT_DOUBLE_EQ(r.knots.at("8_1").distinctly_3d_share, 5.0 / 9);
  EXPECT_DOUBLE_EQ(r.cut, kClusterCut);
}

TEST(Summaries, OtherSummariesRoundTrip) {
  DatasetSummary d;
  d.knots = 14;
  d.sampling = "fixed:12";
  EXPECT_EQ(round_trip(d).sampling, "fixed:12");
  MilnorSummary m;
  m.bb_knots = {{"3_1", 1.00003, 0.006, std::nullopt, 0, 0}};
  EXPECT_EQ(round_trip(m).bb_knots.at(0).knot, "3_1");
  PlanaritySummary p;
  p.planar_share = 0.756;
  EXPECT_DOUBLE_EQ(round_trip(p).planar_share, 0.756);
  JumpingKnotsSummary k;
  k.jumping = {"4_1", "12a_1019"};
  k.planar_threshold = kPlanarThreedim;
  k.radius = 0.2;
  EXPECT_EQ(round_trip(k).jumping.at(1), "12a_1019");
  EXPECT_EQ(round_trip(k).radius, 0.2);
  JumpingDynamicsSummary jd;
  jd.mu_grid = {0.0, 4.0};
  jd.brackets = {{"12a_1019", 0.0, 4.0}, {"4_1", std::nullopt, 0.5}};
  EXPECT_EQ(round_trip(jd).brackets.at(1).mu_jumps, std::nullopt);
  EXPECT_DOUBLE_EQ(*round_trip(jd).brackets.at(1).mu_flat, 0.5);
  EXPECT_FALSE(round_trip(jd).step_check.has_value());
  jd.step_check = StepCheck{"12a_1019", 0.5, 0.99, 2600.0, 2625.0};
  EXPECT_DOUBLE_EQ(round_trip(jd).step_check->similarity, 0.99);
  PuzzlesSummary z;
  z.links = {{"7_7", -3.0}};
  z.radius = 0.2;
  z.dhat = 0.4;
  EXPECT_DOUBLE_EQ(round_trip(z).links.at(0).link, -3.0);
  EXPECT_EQ(round_trip(z).dhat, 0.4);
  SaddlesSummary sd;
  sd.knot = "4_1";
  sd.verified_saddles = {{1, 3, 0.8, 2e-6, 0.79, 3e-4, -4e-6, 1.0, 0.9998, 0.05, "state1_search3"}};
  const SaddlesSummary sr = round_trip(sd);
  EXPECT_EQ(sr.verified_saddles.at(0).folder, "state1_search3");
  EXPECT_DOUBLE_EQ(sr.verified_saddles.at(0).other_similarity, 0.9998);
  EXPECT_EQ(ordered_json(sd).begin().key(), "scale");
  LoadsSummary ld;
  ld.plates_to = 4.0;
  ld.flips = 2;
  EXPECT_EQ(round_trip(ld).plates_to, 4.0);
  EXPECT_EQ(round_trip(ld).flips, 2);
  EXPECT_EQ(ordered_json(ld).begin().key(), "scale");
  TimeVsErrorSummary t;
  t.michell = {{400, 2.6, 1e-4}};
  EXPECT_EQ(round_trip(t).michell.at(0).n, 400);
}

// The summaries of Figs. 5, 7, 10 and 15: nested records and lists survive
// the round trip; the Hausdorff median is null when no state has two members.
TEST(Summaries, AnalysisFiguresRoundTrip) {
  HausdorffSummary h;
  h.knot = "6_1";
  h.shown = {{1, 4, 0, 2, 0.8, 0.2, 0.3, 1.0, 1.2, "curves/a.obj", "curves/b.obj"}};
  EXPECT_FALSE(round_trip(h).median_same_cluster_hausdorff.has_value());
  h.median_same_cluster_hausdorff = 1.5;
  h.below_median_pairs = 3;
  const HausdorffSummary hr = round_trip(h);
  EXPECT_EQ(hr.median_same_cluster_hausdorff, std::optional<double>(1.5));
  EXPECT_EQ(hr.below_median_pairs, 3);
  EXPECT_FALSE(hr.median_unique_same_cluster_hausdorff.has_value());
  h.median_unique_same_cluster_hausdorff = 2.5;
  h.below_unique_median_pairs = 7;
  EXPECT_EQ(round_trip(h).median_unique_same_cluster_hausdorff, std::optional<double>(2.5));
  EXPECT_EQ(round_trip(h).below_unique_median_pairs, 7);
  ASSERT_EQ(hr.shown.size(), 1u);
  EXPECT_EQ(hr.shown[0].b, 4);
  EXPECT_EQ(hr.shown[0].curve_b, "curves/b.obj");
  FiltersSummary f;
  f.attributes = {"energy", "diameter"};
  f.extremes = {{"energy", "min", "3_1", 2, 0.5, "curves/energy_min.obj"}};
  const FiltersSummary fr = round_trip(f);
  EXPECT_EQ(fr.attributes, f.attributes);
  EXPECT_EQ(fr.extremes.at(0).knot, "3_1");
  CrossTopologySummary c;
  c.queries.push_back({"8_1", 3, 1.0, 0.6, "curves/q.obj", 100, 40, {{1, "7_4", 5, 2.5, 1.1, 0.5, "curves/h.obj"}}});
  const CrossTopologySummary cr = round_trip(c);
  ASSERT_EQ(cr.queries.at(0).hits.size(), 1u);
  EXPECT_EQ(cr.queries[0].hits[0].knot, "7_4");
  EXPECT_DOUBLE_EQ(cr.queries[0].hits[0].distance, 2.5);
  GeneralizationSummary g;
  g.pattern.knot = "9_35";
  g.pattern.circles.three_circles = true;
  GeneralizationMember m;
  m.name = "P(3,3,5)";
  m.twists = {3, 3, 5};
  m.alexander = {7, -13, 7};
  m.table_knots = {"11a_1"};
  g.members = {m};
  EXPECT_FALSE(round_trip(g).dataset_min_relative_rms.has_value());  // null: no non-coplanar state
  g.dataset_min_relative_rms = 0.09;
  const GeneralizationSummary gr = round_trip(g);
  EXPECT_EQ(gr.dataset_min_relative_rms, std::optional<double>(0.09));
  EXPECT_TRUE(gr.pattern.circles.three_circles);
  EXPECT_EQ(gr.members.at(0).twists, m.twists);
  EXPECT_EQ(gr.members.at(0).alexander, m.alexander);
  EXPECT_EQ(gr.members.at(0).table_knots, m.table_knots);
}
