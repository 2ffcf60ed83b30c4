#pragma once
/// \file
/// The outcomes of the searches of this module as types. Their texts
/// (to_string(), from_string()) appear only in files, JSON and CSV: the
/// transitions file's searches/ and pairs/ columns (transitions_file.hpp),
/// the JSON of `knots saddles`, `knots transition`, `knots transitions` and
/// `knots connect` (docs/cli.md), and the experiments' tables.
#include <string>
#include <vector>

#include "ek/optim/newton.hpp"
#include "ek/optim/saddle.hpp"

namespace ek {

/// How a saddle search (saddles.hpp) or a transition search
/// (double_ended.hpp) ended; the text of each value follows its name.
enum class SearchOutcome {
  Verified,           ///< "verified": a saddle that passed every check
  // the saddle search stopped (search_saddle(), ek/optim/saddle.hpp)
  MaxIterations,      ///< "max-iterations": its iteration budget ran out
  Stalled,            ///< "stalled": its trust radius fell below the minimum
  LeftBasin,          ///< "left-basin": the energy rose too far above the start
  Degenerate,         ///< "degenerate": no usable eigenpair or factorisation
  // the checks of a converged search (saddles.hpp, items 2-4)
  DegenerateHessian,  ///< "degenerate-hessian": an eigenvalue of H within ±ε·λ_min
  Index,              ///< "index-K": K ≠ 1 negative eigenvalues (SearchStatus::index)
  DescentFailed,      ///< "descent-failed": a descent did not end converged-stable
  TopologyChanged,    ///< "topology-changed": an Alexander polynomial or Lk changed
  // the single-ended search's minima (saddles.hpp)
  StartNotReached,    ///< "start-not-reached": neither descent reached the start
  ReturnsToStart,     ///< "returns-to-start": both did
  // the double-ended search (double_ended.hpp)
  OtherMinima,        ///< "other-minima": the descents do not end in A's and B's states
  SameState,          ///< "same-state": A and B are one curve
  DifferentKnot,      ///< "different-knot": their Alexander polynomials differ
  NotReached,         ///< "not-reached": the steering stages ran out before B
  NoSeed,             ///< "no-seed": no saddle search ran
  // a search that did not run (graph.hpp, connect.hpp)
  Refused,            ///< "refused: <reason>": its input was refused (SearchStatus::reason)
};

/// A SearchOutcome with its parameter: K of "index-K", the reason of
/// "refused: <reason>".
struct SearchStatus {
  SearchOutcome outcome = SearchOutcome::NoSeed;  ///< default: no search ran
  int index = 0;        ///< [1] K, the negative eigenvalues (outcome Index; else 0)
  std::string reason;   ///< why the input was refused (outcome Refused; else empty)

  SearchStatus() = default;  ///< NoSeed: no search ran.
  /// An outcome without a parameter (std::invalid_argument for Index and Refused).
  SearchStatus(SearchOutcome outcome);  // NOLINT(google-explicit-constructor): statuses read as their outcome
  static SearchStatus with_index(int negative);   ///< "index-K", K >= 0 (K ≠ 1 for a search)
  static SearchStatus refused(std::string reason);  ///< "refused: <reason>"
  bool verified() const { return outcome == SearchOutcome::Verified; }  ///< Whether the outcome is Verified.
};
/// Same outcome, index and reason.
bool operator==(const SearchStatus& a, const SearchStatus& b);
/// Not the same status.
inline bool operator!=(const SearchStatus& a, const SearchStatus& b) { return !(a == b); }

/// How one descent from a saddle ended (SaddleMinimum::status): Newton's
/// status (relax()'s), or the checks' and the displacement's verdicts.
enum class DescentStatus {
  ConvergedStable,    ///< "converged-stable"
  ConvergedUnstable,  ///< "converged-unstable"
  MaxIterations,      ///< "max-iterations"
  Stalled,            ///< "stalled"
  TopologyChanged,    ///< "topology-changed": an image's Alexander polynomial or Lk changed
  NotBelowSaddle,     ///< "not-below-saddle": no displacement lowered the energy (no descent)
};

/// How connect_states() (connect.hpp) ended.
enum class ConnectStatus {
  Connected,  ///< "connected": a chain of verified saddles joins a and b
  Budget,     ///< "budget": max_searches spent
  Exhausted,  ///< "exhausted": no untried pair on a path from a to b
};

/// The outcome's text ("verified", "index-K", "refused: <reason>", ...).
std::string to_string(const SearchStatus& status);
std::string to_string(DescentStatus status);  ///< The status's text ("converged-stable", ...).
std::string to_string(ConnectStatus status);  ///< "connected", "budget" or "exhausted".
/// A list of statuses as one text, ";" between them ("" for none): the
/// pairs' seed_statuses column (a seed's status is never "refused").
std::string to_string(const std::vector<SearchStatus>& list);

/// The value whose to_string() is `text` exactly: InputError (one line)
/// for any other text.
template <class T>
T from_string(const std::string& text);
/// The SearchStatus of a text of to_string(const SearchStatus&).
template <>
SearchStatus from_string<SearchStatus>(const std::string& text);
/// The DescentStatus of a text of to_string(DescentStatus).
template <>
DescentStatus from_string<DescentStatus>(const std::string& text);
/// The ConnectStatus of a text of to_string(ConnectStatus).
template <>
ConnectStatus from_string<ConnectStatus>(const std::string& text);
/// The list of statuses of a text of to_string(const std::vector<SearchStatus>&)
/// ("" for none).
template <>
std::vector<SearchStatus> from_string<std::vector<SearchStatus>>(const std::string& text);

/// The outcome of a saddle search that stopped without converging
/// (std::invalid_argument for SaddleStatus::Converged: a converged search's
/// outcome comes from its checks).
SearchOutcome search_outcome(SaddleStatus status);
/// A descent's status from Newton's.
DescentStatus descent_status(SolverStatus status);

}  // namespace ek
