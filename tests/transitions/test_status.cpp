// The statuses of the transitions module (status.hpp): every value has the
// text the files, JSON and CSV hold, and reads back from it exactly; any
// other text is refused with a one-line InputError.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "ek/core/errors.hpp"
#include "ek/transitions/status.hpp"
#include "testing.hpp"

using namespace ek;

namespace {

/// Every search status with its text (one index-K and one refused reason
/// besides K = 0, 2, 3 and an empty reason).
std::vector<std::pair<SearchStatus, std::string>> search_statuses() {
  return {
      {SearchOutcome::Verified, "verified"},
      {SearchOutcome::MaxIterations, "max-iterations"},
      {SearchOutcome::Stalled, "stalled"},
      {SearchOutcome::LeftBasin, "left-basin"},
      {SearchOutcome::Degenerate, "degenerate"},
      {SearchOutcome::DegenerateHessian, "degenerate-hessian"},
      {SearchStatus::with_index(0), "index-0"},
      {SearchStatus::with_index(2), "index-2"},
      {SearchStatus::with_index(3), "index-3"},
      {SearchOutcome::DescentFailed, "descent-failed"},
      {SearchOutcome::TopologyChanged, "topology-changed"},
      {SearchOutcome::StartNotReached, "start-not-reached"},
      {SearchOutcome::ReturnsToStart, "returns-to-start"},
      {SearchOutcome::OtherMinima, "other-minima"},
      {SearchOutcome::SameState, "same-state"},
      {SearchOutcome::DifferentKnot, "different-knot"},
      {SearchOutcome::NotReached, "not-reached"},
      {SearchOutcome::NoSeed, "no-seed"},
      {SearchStatus::refused("the start is not a stable equilibrium: 1 negative eigenvalue(s)"),
       "refused: the start is not a stable equilibrium: 1 negative eigenvalue(s)"},
      {SearchStatus::refused(""), "refused: "},
  };
}

}  // namespace

TEST(TransitionStatus, SearchStatusesRoundTrip) {
  for (const auto& [status, text] : search_statuses()) {
    EXPECT_EQ(to_string(status), text);
    const SearchStatus back = from_string<SearchStatus>(text);
    EXPECT_TRUE(back == status) << text;
    EXPECT_EQ(back.outcome, status.outcome) << text;
    EXPECT_EQ(back.index, status.index) << text;
    EXPECT_EQ(back.reason, status.reason) << text;
  }
  const SearchStatus k3 = from_string<SearchStatus>("index-3");
  EXPECT_EQ(k3.outcome, SearchOutcome::Index);
  EXPECT_EQ(k3.index, 3);
  const SearchStatus refused = from_string<SearchStatus>("refused: vertex counts differ; 100 and 120");
  EXPECT_EQ(refused.outcome, SearchOutcome::Refused);
  EXPECT_EQ(refused.reason, "vertex counts differ; 100 and 120");
  EXPECT_TRUE(from_string<SearchStatus>("verified").verified());
  EXPECT_FALSE(SearchStatus::with_index(1).verified());
}

TEST(TransitionStatus, SeedListsRoundTrip) {
  const std::vector<SearchStatus> seeds{SearchOutcome::OtherMinima, SearchStatus::with_index(2),
                                        SearchOutcome::Verified};
  EXPECT_EQ(to_string(seeds), "other-minima;index-2;verified");
  EXPECT_EQ(from_string<std::vector<SearchStatus>>("other-minima;index-2;verified"), seeds);
  EXPECT_EQ(to_string(std::vector<SearchStatus>{}), "");
  EXPECT_TRUE(from_string<std::vector<SearchStatus>>("").empty());
  EXPECT_EQ(from_string<std::vector<SearchStatus>>("left-basin"), std::vector<SearchStatus>{SearchOutcome::LeftBasin});
}

TEST(TransitionStatus, DescentAndConnectStatusesRoundTrip) {
  const std::vector<std::pair<DescentStatus, std::string>> descents{
      {DescentStatus::ConvergedStable, "converged-stable"}, {DescentStatus::ConvergedUnstable, "converged-unstable"},
      {DescentStatus::MaxIterations, "max-iterations"},     {DescentStatus::Stalled, "stalled"},
      {DescentStatus::TopologyChanged, "topology-changed"}, {DescentStatus::NotBelowSaddle, "not-below-saddle"}};
  for (const auto& [status, text] : descents) {
    EXPECT_EQ(to_string(status), text);
    EXPECT_EQ(from_string<DescentStatus>(text), status) << text;
  }
  for (const SolverStatus s : {SolverStatus::ConvergedStable, SolverStatus::ConvergedUnstable,
                               SolverStatus::MaxIterations, SolverStatus::Stalled})
    EXPECT_EQ(to_string(descent_status(s)), to_string(s));  // relax()'s texts
  const std::vector<std::pair<ConnectStatus, std::string>> connects{
      {ConnectStatus::Connected, "connected"},
      {ConnectStatus::Budget, "budget"},
      {ConnectStatus::Exhausted, "exhausted"}};
  for (const auto& [status, text] : connects) {
    EXPECT_EQ(to_string(status), text);
    EXPECT_EQ(from_string<ConnectStatus>(text), status) << text;
  }
}

TEST(TransitionStatus, UnknownTextsAreRefused) {
  for (const std::string text : {"", "converged", "Verified", "verified ", " verified", "index-", "index-01",
                                 "index--1", "index-+2", "index-x", "index-1234567890", "refused:", "refused:x",
                                 "start-refused: not stable", "other-minima;verified"})
    fixtures::expect_input_error([&] { from_string<SearchStatus>(text); }, "unknown search status '" + text + "'");
  for (const std::string text : {"other-minima;", ";verified", "verified;;other-minima", "verified;nope"})
    EXPECT_THROW(from_string<std::vector<SearchStatus>>(text), InputError) << text;
  fixtures::expect_input_error([] { from_string<DescentStatus>("converged"); }, "unknown descent status 'converged'");
  fixtures::expect_input_error([] { from_string<ConnectStatus>("refused: x"); },
                               "unknown connect status 'refused: x'");
  try {
    from_string<SearchStatus>("two\nlines");
    ADD_FAILURE() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
  }
}

// Misuse: index-K and refused carry their parameter; a converged saddle
// search has no outcome of its own (its checks give it).
TEST(TransitionStatus, MisuseThrows) {
  EXPECT_THROW(SearchStatus{SearchOutcome::Index}, std::invalid_argument);
  EXPECT_THROW(SearchStatus{SearchOutcome::Refused}, std::invalid_argument);
  EXPECT_THROW(SearchStatus::with_index(-1), std::invalid_argument);
  EXPECT_THROW(search_outcome(SaddleStatus::Converged), std::invalid_argument);
  EXPECT_EQ(search_outcome(SaddleStatus::MaxIterations), SearchOutcome::MaxIterations);
  EXPECT_EQ(search_outcome(SaddleStatus::Stalled), SearchOutcome::Stalled);
  EXPECT_EQ(search_outcome(SaddleStatus::LeftBasin), SearchOutcome::LeftBasin);
  EXPECT_EQ(search_outcome(SaddleStatus::Degenerate), SearchOutcome::Degenerate);
  for (const SaddleStatus s : {SaddleStatus::MaxIterations, SaddleStatus::Stalled, SaddleStatus::LeftBasin,
                               SaddleStatus::Degenerate})
    EXPECT_EQ(to_string(SearchStatus(search_outcome(s))), to_string(s));  // search_saddle()'s texts
}
