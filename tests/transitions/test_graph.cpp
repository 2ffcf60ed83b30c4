// The transition graph: the minimax path on a hand-made graph with a known
// answer, the chain profile (each edge's whole path, in the direction
// travelled), and the transitions file round trip (an unknown status in it
// refused), its version policy (another format version refused) and a
// missing column refused naming it.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

#include "ek/core/errors.hpp"
#include "ek/dataset/h5.hpp"
#include "ek/transitions/graph.hpp"
#include "ek/transitions/run.hpp"
#include "ek/transitions/transitions_file.hpp"
#include "testing.hpp"

using namespace ek;

namespace {

Points curve(double shift) {
  Points P(4, 3);
  P << 0, 0, shift, 1, 0, shift, 1, 1, shift, 0, 1, shift;
  return P;
}

/// States 0..4 with energies; saddles (a, b, E): 0-1 at 5, 1-2 at 3, 0-2 at 9,
/// 2-3 at 4; state 4 is isolated. The lowest path 0 -> 3 is 0-1-2-3 (highest
/// saddle 5), not 0-2-3 (9).
TransitionGraph example() {
  TransitionGraph g;
  g.knot = "test";
  g.cut = 0.05;
  g.energy_scale = 0.5;
  const double state_energies[5] = {1.0, 1.1, 1.2, 1.3, 1.4};
  for (int k = 0; k < 5; ++k) g.states.push_back({k, k, state_energies[k], curve(k)});
  const int pairs[4][2] = {{0, 1}, {1, 2}, {0, 2}, {2, 3}};
  const double energies[4] = {5, 3, 9, 4};
  for (int k = 0; k < 4; ++k) {
    TransitionSaddle s;
    s.energy = energies[k];
    s.negative_eigenvalue = -1.0;
    s.second_eigenvalue = 0.5;
    s.index = 1;
    s.from = pairs[k][0];
    s.to = pairs[k][1];
    s.positions = curve(10 + k);
    s.path = {g.states[s.from].positions, s.positions, g.states[s.to].positions};
    s.path_energies = {g.states[s.from].energy, s.energy, g.states[s.to].energy};
    s.saddle_image = 1;
    s.energy_from = g.states[s.from].energy;
    s.energy_to = g.states[s.to].energy;
    s.double_ended = k == 1;
    g.saddles.push_back(s);
    g.edges.push_back({s.from, s.to, k, s.energy, s.energy - g.states[s.from].energy, s.energy - g.states[s.to].energy});
  }
  PairSearch p;
  p.a = 1;
  p.b = 2;
  p.status = SearchOutcome::Verified;
  p.seed_statuses = {SearchOutcome::OtherMinima, SearchOutcome::Verified};
  p.reached = p.verified = true;
  p.stages = 7;
  p.path_barrier = 2.5;
  p.reached_similarity = 0.995;
  p.saddle_energy = 3;
  p.saddle = 1;
  p.seconds = 1.5;
  g.pairs.push_back(p);
  g.pairs.push_back({0, 3, SearchOutcome::NotReached, {}, false, false, 40, 0.0, 0.4, 0.0, -1, 2.0});
  return g;
}

}  // namespace

TEST(TransitionGraph, MinimaxPathAvoidsTheHighSaddle) {
  const TransitionGraph g = example();
  const auto path = minimax_path(g, 0, 3);
  ASSERT_TRUE(path.has_value());
  EXPECT_EQ(*path, (std::vector<int>{0, 1, 3}));
  EXPECT_FALSE(minimax_path(g, 0, 4).has_value());  // no chain of saddles reaches state 4
  EXPECT_TRUE(minimax_path(g, 2, 2)->empty());
  const auto back = minimax_path(g, 3, 0);
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(*back, (std::vector<int>{3, 1, 0}));
}

TEST(TransitionGraph, ChainProfileJoinsThePathsInTheDirectionTravelled) {
  const TransitionGraph g = example();
  std::vector<Points> images;
  std::vector<double> energies;
  std::vector<int> saddles;
  chain_profile(g, 3, {3, 1, 0}, images, energies, saddles);  // 3 -> 2 -> 1 -> 0, each edge reversed
  EXPECT_EQ(energies, (std::vector<double>{1.3, 4, 1.2, 1.2, 3, 1.1, 1.1, 5, 1.0}));
  EXPECT_EQ(saddles, (std::vector<int>{1, 4, 7}));
  EXPECT_EQ(images.size(), energies.size());
  EXPECT_THROW(chain_profile(g, 4, {0}, images, energies, saddles), std::invalid_argument);
}

// A double-ended search adds its summary, and its other saddles as edges
// between the states their minima match (a minimum matching none: a new
// state); a saddle already in the graph is not added twice.
TEST(TransitionGraph, PairAddsItsOtherSaddlesBetweenMatchedStates) {
  TransitionGraph g = example();
  const CurveSimilarity same = [](const Points& x, const Points& y) { return x.isApprox(y) ? 1.0 : 0.0; };
  TransitionSearch t;
  t.status = SearchOutcome::OtherMinima;
  t.reached = true;
  t.seed_statuses = {SearchOutcome::OtherMinima};
  SaddleRecord r;
  r.status = SearchOutcome::OtherMinima;
  r.energy = 7.0;
  r.index = 1;
  r.saddle = curve(20);
  r.minima[0].positions = curve(1);  // state 1
  r.minima[0].energy = 1.1;
  r.minima[0].images = {curve(20), curve(1)};
  r.minima[0].energies = {7.0, 1.1};
  r.minima[1].positions = curve(30);  // no state: a new one
  r.minima[1].energy = 2.0;
  r.minima[1].images = {curve(20), curve(30)};
  r.minima[1].energies = {7.0, 2.0};
  t.other_saddles = {r};
  const size_t states = g.states.size(), edges = g.edges.size();
  add_pair(g, 0, 3, t, same, 0.95);
  ASSERT_EQ(g.pairs.size(), 3u);
  EXPECT_EQ(g.pairs.back().seed_statuses, std::vector<SearchStatus>{SearchOutcome::OtherMinima});
  EXPECT_EQ(g.pairs.back().saddle, -1);
  ASSERT_EQ(g.states.size(), states + 1);
  ASSERT_EQ(g.edges.size(), edges + 1);
  const TransitionEdge& e = g.edges.back();
  EXPECT_EQ(e.from, 1);
  EXPECT_EQ(e.to, static_cast<int>(states));
  EXPECT_EQ(e.barrier_forward, 7.0 - 1.1);
  EXPECT_EQ(e.barrier_backward, 7.0 - 2.0);
  EXPECT_TRUE(g.saddles.back().double_ended);
  EXPECT_EQ(g.saddles.back().path.size(), 3u);
  EXPECT_EQ(g.saddles.back().saddle_image, 1);
  add_pair(g, 0, 3, t, same, 0.95);  // the same saddle again
  EXPECT_EQ(g.edges.size(), edges + 1);
}

// Double-ended pairs: the nearest states in energy rank, bounded.
TEST(TransitionGraph, PairsAreNeighboursInEnergyRank) {
  TransitionRunOptions o;
  o.pair_gap = 1;
  EXPECT_EQ(transition_pairs(4, o), (std::vector<std::pair<int, int>>{{0, 1}, {1, 2}, {2, 3}}));
  o.pair_gap = 2;
  o.max_pairs = 3;
  EXPECT_EQ(transition_pairs(4, o), (std::vector<std::pair<int, int>>{{0, 1}, {0, 2}, {1, 2}}));
  o.pair_gap = 0;
  EXPECT_TRUE(transition_pairs(4, o).empty());
}

TEST(TransitionsFile, RoundTripAndBadInput) {
  TransitionGraph g = example();
  StateSearches refused;  // a start that was not stable: one "start-refused" row
  refused.state = 2;
  refused.error = "not a stable equilibrium";
  refused.seconds = 0.25;
  StateSearches searched;
  searched.state = 0;
  for (int k = 0; k < 2; ++k) {
    SaddleRecord r;
    r.mode = k;
    r.direction = k == 0 ? 1 : -1;
    r.status = k == 0 ? SearchOutcome::Verified : SearchOutcome::LeftBasin;
    r.verified = k == 0;
    r.index = k == 0 ? 1 : -1;
    r.iterations = 10 + k;
    r.energy = 2.5 + k;
    r.gradient_norm = 1e-9;
    r.seconds = 0.5;
    searched.records.push_back(r);
  }
  g.searches = {searched, refused};
  const std::string path = std::filesystem::temp_directory_path() / "ek_test_transitions.h5";
  write_transitions(path, g, "dataset.h5", "options", false, 3);
  TransitionsFileInfo info;
  const TransitionGraph r = read_transitions(path, info);
  EXPECT_EQ(info.options, "options");
  EXPECT_EQ(info.dataset, "dataset.h5");
  EXPECT_FALSE(info.complete);
  EXPECT_EQ(info.states_searched, 3);
  ASSERT_EQ(r.searches.size(), 2u);
  EXPECT_EQ(r.searches[0].state, 0);
  ASSERT_EQ(r.searches[0].records.size(), 2u);
  for (int k = 0; k < 2; ++k) {
    const SaddleRecord &a = r.searches[0].records[k], &b = searched.records[k];
    EXPECT_EQ(a.mode, b.mode);
    EXPECT_EQ(a.direction, b.direction);
    EXPECT_EQ(a.status, b.status);
    EXPECT_EQ(a.verified, b.verified);
    EXPECT_EQ(a.index, b.index);
    EXPECT_EQ(a.iterations, b.iterations);
    EXPECT_EQ(a.energy, b.energy);
    EXPECT_EQ(a.gradient_norm, b.gradient_norm);
  }
  EXPECT_EQ(r.searches[0].energy, g.states[0].energy);
  EXPECT_EQ(r.searches[1].state, 2);
  EXPECT_EQ(r.searches[1].error, "not a stable equilibrium");
  EXPECT_TRUE(r.searches[1].records.empty());
  write_transitions(path, g, "dataset.h5", "options", true);
  std::string options;
  EXPECT_EQ(read_transitions(path, info).searches.size(), 2u);
  EXPECT_TRUE(info.complete);
  EXPECT_EQ(info.states_searched, -1);  // not recorded
  read_transitions(path, &options);
  EXPECT_EQ(options, "options");
  EXPECT_EQ(r.knot, "test");
  ASSERT_EQ(r.states.size(), g.states.size());
  ASSERT_EQ(r.saddles.size(), g.saddles.size());
  ASSERT_EQ(r.edges.size(), g.edges.size());
  for (size_t k = 0; k < g.saddles.size(); ++k) {
    EXPECT_EQ(r.saddles[k].energy, g.saddles[k].energy);
    EXPECT_EQ(r.saddles[k].path_energies, g.saddles[k].path_energies);
    EXPECT_EQ(r.saddles[k].path.size(), 3u);
    EXPECT_TRUE(r.saddles[k].positions.isApprox(g.saddles[k].positions));
  }
  for (size_t k = 0; k < g.saddles.size(); ++k) {
    EXPECT_EQ(r.saddles[k].energy_from, g.saddles[k].energy_from);
    EXPECT_EQ(r.saddles[k].energy_to, g.saddles[k].energy_to);
    EXPECT_EQ(r.saddles[k].double_ended, g.saddles[k].double_ended);
  }
  ASSERT_EQ(r.pairs.size(), 2u);
  EXPECT_EQ(r.pairs[0].status, g.pairs[0].status);
  EXPECT_EQ(r.pairs[0].saddle, 1);
  EXPECT_EQ(r.pairs[0].stages, 7);
  EXPECT_EQ(r.pairs[0].seed_statuses, g.pairs[0].seed_statuses);
  EXPECT_EQ(r.pairs[1].status.outcome, SearchOutcome::NotReached);
  EXPECT_TRUE(r.pairs[1].seed_statuses.empty());
  EXPECT_EQ(r.pairs[1].saddle, -1);
  EXPECT_FALSE(r.pairs[1].reached);
  EXPECT_EQ(*minimax_path(r, 0, 3), (std::vector<int>{0, 1, 3}));
  for (const char* column : {"searches", "pairs"}) {  // a status the reader does not know
    write_transitions(path, g, "dataset.h5", "options", true);
    {
      const h5::Handle f = h5::open_file(path, true);
      const h5::Handle table = h5::open_group(f.id(), column);
      const size_t rows = h5::read_strings(table.id(), "status").size();
      H5Ldelete(table.id(), "status", H5P_DEFAULT);
      h5::write_strings(table.id(), "status", std::vector<std::string>(rows, "half-verified"));
    }
    fixtures::expect_input_error([&] { read_transitions(path); }, path + ": unknown search status 'half-verified'");
  }
  std::remove(path.c_str());
  const std::string bad = std::filesystem::temp_directory_path() / "ek_test_transitions_bad.h5";
  { std::FILE* f = std::fopen(bad.c_str(), "w"); std::fputs("not hdf5", f); std::fclose(f); }
  EXPECT_THROW(read_transitions(bad), InputError);
  std::remove(bad.c_str());
}

namespace {

/// The example with searches whose state energies and seconds are what the
/// reader rebuilds (the state's energy, the records' seconds summed), every
/// column holding a value of its own.
TransitionGraph example_with_searches() {
  TransitionGraph g = example();
  g.states[3].cluster = -1;
  g.states[4].equilibrium = -1;
  for (size_t k = 0; k < g.saddles.size(); ++k) {
    g.saddles[k].gradient_norm = 1e-9 * static_cast<double>(k + 1);
    g.saddles[k].index = static_cast<int>(k) + 1;
    g.saddles[k].saddle_image = k == 2 ? 2 : 1;
  }
  StateSearches searched;
  searched.state = 0;
  searched.energy = g.states[0].energy;
  for (int k = 0; k < 2; ++k) {
    SaddleRecord r;
    r.mode = k;
    r.direction = k == 0 ? 1 : -1;
    r.status = k == 0 ? SearchStatus(SearchOutcome::Verified) : SearchStatus(SearchOutcome::LeftBasin);
    r.verified = k == 0;
    r.index = k == 0 ? 1 : -1;
    r.iterations = 10 + k;
    r.energy = 2.5 + k;
    r.gradient_norm = 1e-9 * (k + 1);
    r.seconds = 0.5 + k;
    searched.records.push_back(r);
    searched.seconds += r.seconds;
  }
  StateSearches refused;
  refused.state = 2;
  refused.energy = g.states[2].energy;
  refused.error = "not a stable equilibrium";
  refused.seconds = 0.25;
  g.searches = {searched, refused};
  return g;
}

/// Every member the file keeps, compared exactly.
void expect_same_graph(const TransitionGraph& a, const TransitionGraph& b) {
  EXPECT_EQ(a.knot, b.knot);
  EXPECT_EQ(a.cut, b.cut);
  EXPECT_EQ(a.energy_scale, b.energy_scale);
  ASSERT_EQ(a.states.size(), b.states.size());
  for (size_t k = 0; k < a.states.size(); ++k) {
    const TransitionState &x = a.states[k], &y = b.states[k];
    EXPECT_EQ(x.energy, y.energy) << k;
    EXPECT_EQ(x.cluster, y.cluster) << k;
    EXPECT_EQ(x.equilibrium, y.equilibrium) << k;
    EXPECT_EQ(x.positions, y.positions) << k;
  }
  ASSERT_EQ(a.saddles.size(), b.saddles.size());
  for (size_t k = 0; k < a.saddles.size(); ++k) {
    const TransitionSaddle &x = a.saddles[k], &y = b.saddles[k];
    EXPECT_EQ(x.energy, y.energy) << k;
    EXPECT_EQ(x.negative_eigenvalue, y.negative_eigenvalue) << k;
    EXPECT_EQ(x.second_eigenvalue, y.second_eigenvalue) << k;
    EXPECT_EQ(x.gradient_norm, y.gradient_norm) << k;
    EXPECT_EQ(x.index, y.index) << k;
    EXPECT_EQ(x.from, y.from) << k;
    EXPECT_EQ(x.to, y.to) << k;
    EXPECT_EQ(x.saddle_image, y.saddle_image) << k;
    EXPECT_EQ(x.energy_from, y.energy_from) << k;
    EXPECT_EQ(x.energy_to, y.energy_to) << k;
    EXPECT_EQ(x.double_ended, y.double_ended) << k;
    EXPECT_EQ(x.positions, y.positions) << k;
    EXPECT_EQ(x.path, y.path) << k;
    EXPECT_EQ(x.path_energies, y.path_energies) << k;
  }
  ASSERT_EQ(a.edges.size(), b.edges.size());
  for (size_t k = 0; k < a.edges.size(); ++k) {
    const TransitionEdge &x = a.edges[k], &y = b.edges[k];
    EXPECT_EQ(x.from, y.from) << k;
    EXPECT_EQ(x.to, y.to) << k;
    EXPECT_EQ(x.saddle, y.saddle) << k;
    EXPECT_EQ(x.energy, y.energy) << k;
    EXPECT_EQ(x.barrier_forward, y.barrier_forward) << k;
    EXPECT_EQ(x.barrier_backward, y.barrier_backward) << k;
  }
  ASSERT_EQ(a.searches.size(), b.searches.size());
  for (size_t k = 0; k < a.searches.size(); ++k) {
    const StateSearches &x = a.searches[k], &y = b.searches[k];
    EXPECT_EQ(x.state, y.state) << k;
    EXPECT_EQ(x.energy, y.energy) << k;
    EXPECT_EQ(x.seconds, y.seconds) << k;
    EXPECT_EQ(x.error, y.error) << k;
    ASSERT_EQ(x.records.size(), y.records.size()) << k;
    for (size_t j = 0; j < x.records.size(); ++j) {
      const SaddleRecord &r = x.records[j], &s = y.records[j];
      EXPECT_EQ(r.mode, s.mode);
      EXPECT_EQ(r.direction, s.direction);
      EXPECT_EQ(r.verified, s.verified);
      EXPECT_EQ(r.index, s.index);
      EXPECT_EQ(r.iterations, s.iterations);
      EXPECT_EQ(r.status, s.status);
      EXPECT_EQ(r.energy, s.energy);
      EXPECT_EQ(r.gradient_norm, s.gradient_norm);
      EXPECT_EQ(r.seconds, s.seconds);
    }
  }
  ASSERT_EQ(a.pairs.size(), b.pairs.size());
  for (size_t k = 0; k < a.pairs.size(); ++k) {
    const PairSearch &x = a.pairs[k], &y = b.pairs[k];
    EXPECT_EQ(x.a, y.a) << k;
    EXPECT_EQ(x.b, y.b) << k;
    EXPECT_EQ(x.status, y.status) << k;
    EXPECT_EQ(x.seed_statuses, y.seed_statuses) << k;
    EXPECT_EQ(x.reached, y.reached) << k;
    EXPECT_EQ(x.verified, y.verified) << k;
    EXPECT_EQ(x.stages, y.stages) << k;
    EXPECT_EQ(x.saddle, y.saddle) << k;
    EXPECT_EQ(x.path_barrier, y.path_barrier) << k;
    EXPECT_EQ(x.reached_similarity, y.reached_similarity) << k;
    EXPECT_EQ(x.saddle_energy, y.saddle_energy) << k;
    EXPECT_EQ(x.seconds, y.seconds) << k;
  }
}

/// The InputError message of f() (empty when it does not throw one).
template <class F>
std::string input_error(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string temp_file(const std::string& name) { return std::filesystem::temp_directory_path() / name; }

}  // namespace

// Written and read back, the graph is the one in memory (every column), and
// so is every attribute; an empty graph too.
TEST(TransitionsFile, RoundTripEqualsTheGraph) {
  const std::string path = temp_file("ek_test_transitions_round_trip.h5");
  const TransitionGraph g = example_with_searches();
  write_transitions(path, g, "data.h5", "modes 2", false, 1);
  TransitionsFileInfo info;
  expect_same_graph(read_transitions(path, info), g);
  EXPECT_EQ(info.dataset, "data.h5");
  EXPECT_EQ(info.options, "modes 2");
  EXPECT_FALSE(info.complete);
  EXPECT_EQ(info.states_searched, 1);
  TransitionGraph empty;
  empty.knot = "0_1";
  write_transitions(path, empty, "", "", true);
  expect_same_graph(read_transitions(path, info), empty);
  EXPECT_TRUE(info.complete);
  EXPECT_EQ(info.states_searched, -1);
  std::remove(path.c_str());
}

// The reader accepts its own format version only: another (older or newer)
// is one line naming the file and both versions.
TEST(TransitionsFile, AnotherFormatVersionIsRefused) {
  const std::string path = temp_file("ek_test_transitions_version.h5");
  for (const std::int64_t version : {std::int64_t{0}, std::int64_t{2}}) {
    write_transitions(path, example_with_searches(), "data.h5", "options", true);
    {
      const h5::Handle f = h5::open_file(path, true);
      h5::set_attr(f.id(), "format_version", version);
    }
    const std::string message = input_error([&] { read_transitions(path); });
    EXPECT_EQ(message, path + ": transitions format version " + std::to_string(version) + ", expected 1");
    EXPECT_EQ(message.find('\n'), std::string::npos);
  }
  std::remove(path.c_str());
}

// A file without one of its columns (a derived one included) or required
// attributes is refused naming it; one whose columns differ in length names
// both.
TEST(TransitionsFile, AMissingColumnIsRefusedNamingIt) {
  const std::string path = temp_file("ek_test_transitions_missing.h5");
  const std::pair<const char*, const char*> columns[] = {
      {"states", "energy"},         {"states", "positions"},     {"saddles", "energy_from"},
      {"saddles", "double_ended"},  {"saddles/path_1", "energies"}, {"edges", "barrier_backward"},
      {"edges", "barrier_forward_scaled"}, {"searches", "status"}, {"pairs", "seed_statuses"},
  };
  for (const auto& [group, column] : columns) {
    write_transitions(path, example_with_searches(), "data.h5", "options", true, 2);
    {
      const h5::Handle f = h5::open_file(path, true);
      const h5::Handle g = h5::open_group(f.id(), group);
      ASSERT_GE(H5Ldelete(g.id(), column, H5P_DEFAULT), 0) << group << "/" << column;
    }
    EXPECT_EQ(input_error([&] { read_transitions(path); }),
              path + ": the column '" + group + "/" + column + "' is missing");
  }
  for (const char* attribute : {"knot", "cut", "complete"}) {
    write_transitions(path, example_with_searches(), "data.h5", "options", true, 2);
    {
      const h5::Handle f = h5::open_file(path, true);
      ASSERT_GE(H5Adelete(f.id(), attribute), 0) << attribute;
    }
    EXPECT_EQ(input_error([&] { read_transitions(path); }),
              path + ": the attribute '" + std::string(attribute) + "' is missing");
  }
  write_transitions(path, example_with_searches(), "data.h5", "options", true, 2);
  {
    const h5::Handle f = h5::open_file(path, true);
    const h5::Handle g = h5::open_group(f.id(), "edges");
    H5Ldelete(g.id(), "energy", H5P_DEFAULT);
    const std::vector<double> one{1.0};
    h5::write_doubles(g.id(), "energy", {1}, one.data());
  }
  EXPECT_EQ(input_error([&] { read_transitions(path); }), path + ": edges: column 'energy' has 1 rows, 'from' 4");
  std::remove(path.c_str());
}
