#include "ek/transitions/status.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <utility>

#include "ek/core/errors.hpp"

namespace ek {
namespace {

constexpr const char* kIndexPrefix = "index-";
constexpr const char* kRefusedPrefix = "refused: ";

/// The texts of the outcomes without a parameter.
constexpr std::array<std::pair<SearchOutcome, const char*>, 15> kOutcomeTexts{{
    {SearchOutcome::Verified, "verified"},
    {SearchOutcome::MaxIterations, "max-iterations"},
    {SearchOutcome::Stalled, "stalled"},
    {SearchOutcome::LeftBasin, "left-basin"},
    {SearchOutcome::Degenerate, "degenerate"},
    {SearchOutcome::DegenerateHessian, "degenerate-hessian"},
    {SearchOutcome::DescentFailed, "descent-failed"},
    {SearchOutcome::TopologyChanged, "topology-changed"},
    {SearchOutcome::StartNotReached, "start-not-reached"},
    {SearchOutcome::ReturnsToStart, "returns-to-start"},
    {SearchOutcome::OtherMinima, "other-minima"},
    {SearchOutcome::SameState, "same-state"},
    {SearchOutcome::DifferentKnot, "different-knot"},
    {SearchOutcome::NotReached, "not-reached"},
    {SearchOutcome::NoSeed, "no-seed"},
}};

constexpr std::array<DescentStatus, 6> kDescentStatuses{
    DescentStatus::ConvergedStable, DescentStatus::ConvergedUnstable, DescentStatus::MaxIterations,
    DescentStatus::Stalled,         DescentStatus::TopologyChanged,   DescentStatus::NotBelowSaddle};

constexpr std::array<ConnectStatus, 3> kConnectStatuses{ConnectStatus::Connected, ConnectStatus::Budget,
                                                        ConnectStatus::Exhausted};

bool starts_with(const std::string& text, const char* prefix) { return text.rfind(prefix, 0) == 0; }

/// The value of `all` whose text is `text`, else InputError naming `what`.
template <class T, size_t N>
T find_text(const std::array<T, N>& all, const std::string& text, const std::string& what) {
  for (const T& x : all)
    if (to_string(x) == text) return x;
  throw InputError("unknown " + what + " '" + text + "'");
}

/// "index-K" back to K (the exact text to_string() writes: no sign, no leading zero).
SearchStatus parse_index(const std::string& text) {
  const std::string digits = text.substr(std::string(kIndexPrefix).size());
  const bool ok = !digits.empty() && digits.size() <= 9 &&
                  std::all_of(digits.begin(), digits.end(), [](unsigned char c) { return std::isdigit(c); });
  const SearchStatus s = SearchStatus::with_index(ok ? std::stoi(digits) : 0);
  if (!ok || to_string(s) != text) throw InputError("unknown search status '" + text + "'");
  return s;
}

}  // namespace

SearchStatus::SearchStatus(SearchOutcome o) : outcome(o) {
  require(o != SearchOutcome::Index && o != SearchOutcome::Refused,
          "SearchStatus: index-K and refused need their parameter (with_index(), refused())");
}

SearchStatus SearchStatus::with_index(int negative) {
  require(negative >= 0, "SearchStatus::with_index: the number of negative eigenvalues must be >= 0");
  SearchStatus s;
  s.outcome = SearchOutcome::Index;
  s.index = negative;
  return s;
}

SearchStatus SearchStatus::refused(std::string reason) {
  SearchStatus s;
  s.outcome = SearchOutcome::Refused;
  s.reason = std::move(reason);
  return s;
}

bool operator==(const SearchStatus& a, const SearchStatus& b) {
  return a.outcome == b.outcome && a.index == b.index && a.reason == b.reason;
}

std::string to_string(const SearchStatus& s) {
  if (s.outcome == SearchOutcome::Index) return kIndexPrefix + std::to_string(s.index);
  if (s.outcome == SearchOutcome::Refused) return kRefusedPrefix + s.reason;
  for (const auto& [outcome, text] : kOutcomeTexts)
    if (outcome == s.outcome) return text;
  return "?";
}

std::string to_string(DescentStatus s) {
  switch (s) {
    case DescentStatus::ConvergedStable: return to_string(SolverStatus::ConvergedStable);
    case DescentStatus::ConvergedUnstable: return to_string(SolverStatus::ConvergedUnstable);
    case DescentStatus::MaxIterations: return to_string(SolverStatus::MaxIterations);
    case DescentStatus::Stalled: return to_string(SolverStatus::Stalled);
    case DescentStatus::TopologyChanged: return "topology-changed";
    case DescentStatus::NotBelowSaddle: return "not-below-saddle";
  }
  return "?";
}

std::string to_string(ConnectStatus s) {
  switch (s) {
    case ConnectStatus::Connected: return "connected";
    case ConnectStatus::Budget: return "budget";
    case ConnectStatus::Exhausted: return "exhausted";
  }
  return "?";
}

std::string to_string(const std::vector<SearchStatus>& list) {
  std::string out;
  for (const SearchStatus& s : list) out += (out.empty() ? "" : ";") + to_string(s);
  return out;
}

template <>
SearchStatus from_string<SearchStatus>(const std::string& text) {
  if (starts_with(text, kIndexPrefix)) return parse_index(text);
  if (starts_with(text, kRefusedPrefix)) return SearchStatus::refused(text.substr(std::string(kRefusedPrefix).size()));
  for (const auto& [outcome, name] : kOutcomeTexts)
    if (text == name) return outcome;
  throw InputError("unknown search status '" + text + "'");
}

template <>
DescentStatus from_string<DescentStatus>(const std::string& text) {
  return find_text(kDescentStatuses, text, "descent status");
}

template <>
ConnectStatus from_string<ConnectStatus>(const std::string& text) {
  return find_text(kConnectStatuses, text, "connect status");
}

template <>
std::vector<SearchStatus> from_string<std::vector<SearchStatus>>(const std::string& text) {
  std::vector<SearchStatus> out;
  for (size_t begin = 0; !text.empty() && begin <= text.size();) {
    const size_t end = std::min(text.find(';', begin), text.size());
    out.push_back(from_string<SearchStatus>(text.substr(begin, end - begin)));
    begin = end + 1;
  }
  return out;
}

SearchOutcome search_outcome(SaddleStatus s) {
  switch (s) {
    case SaddleStatus::MaxIterations: return SearchOutcome::MaxIterations;
    case SaddleStatus::Stalled: return SearchOutcome::Stalled;
    case SaddleStatus::LeftBasin: return SearchOutcome::LeftBasin;
    case SaddleStatus::Degenerate: return SearchOutcome::Degenerate;
    case SaddleStatus::Converged: break;
  }
  throw std::invalid_argument("search_outcome: a converged search's outcome comes from its checks");
}

DescentStatus descent_status(SolverStatus s) {
  switch (s) {
    case SolverStatus::ConvergedStable: return DescentStatus::ConvergedStable;
    case SolverStatus::ConvergedUnstable: return DescentStatus::ConvergedUnstable;
    case SolverStatus::MaxIterations: return DescentStatus::MaxIterations;
    case SolverStatus::Stalled: return DescentStatus::Stalled;
  }
  throw std::invalid_argument("descent_status: not a solver status");
}

}  // namespace ek
