#pragma once
// summary.json of exp_saddles (docs/results.md, "saddles"): transitions
// between 4_1's stable states (paper Section 8.5, an open direction).
#include <string>
#include <vector>

#include "json_fields.hpp"

namespace ek::results {

/// One distinct verified saddle (saddles.csv has every search).
struct VerifiedSaddle {
  int state = -1;                 ///< [1] cluster rank of the start (states.csv)
  int search = -1;                ///< [1] the search that found it (mode 2k: +, 2k+1: −)
  double energy = 0.0;            ///< [energy] E_saddle
  double barrier = 0.0;           ///< [energy] E_saddle − E_start
  double other_energy = 0.0;      ///< [energy] the other minimum's energy
  double barrier_scaled = 0.0;    ///< [1] barrier / (EI/L)
  double negative_eigenvalue = 0.0;  ///< [energy/length²] λ₁ of H without rigid modes
  double start_similarity = 0.0;  ///< [1] of the descent's minimum to the start
  /// [1] of the other minimum to the start (below 1 − cut: another state at the cut)
  double other_similarity = 0.0;
  double seconds = 0.0;           ///< [s] the search and its checks
  std::string folder;             ///< files: start.obj, saddle.obj, end.obj, path.obj (relative to the run)
};
EK_JSON_FIELDS(VerifiedSaddle, state, search, energy, barrier, other_energy, barrier_scaled, negative_eigenvalue,
               start_similarity, other_similarity, seconds, folder)

struct SaddlesSummary {
  std::string scale;
  std::string knot;               ///< "4_1"
  double cut = 0.0;               ///< [1] kClusterCut (the states: clusters of the multistability data set)
  int modes = 0;                  ///< [1] K softest non-rigid modes per state (both directions)
  double edge_length = 1.0;       ///< [length] rest edge length of the data set
  double energy_scale = 0.0;      ///< [energy] EI/L
  int states = 0;                 ///< [1] states searched from
  int states_refused = 0;         ///< [1] of them, not stable equilibria of the model (no search)
  int searches = 0;               ///< [1]
  int verified = 0;               ///< [1] searches ending in a verified saddle (duplicates included)
  int saddles = 0;                ///< [1] distinct verified saddles (per state)
  int saddles_to_other_states = 0;   ///< [1] of them, whose other minimum is another state at the cut
  double seconds_per_search = 0.0;   ///< [s] mean wall time of a search and its checks
  double seconds_per_saddle = 0.0;   ///< [s] all searches' time over the distinct verified saddles
  std::vector<VerifiedSaddle> verified_saddles;
  double seconds = 0.0;           ///< [s] the whole run
};
EK_JSON_FIELDS(SaddlesSummary, scale, knot, cut, modes, edge_length, energy_scale, states, states_refused, searches,
               verified, saddles, saddles_to_other_states, seconds_per_search, seconds_per_saddle, verified_saddles, seconds)

}  // namespace ek::results
