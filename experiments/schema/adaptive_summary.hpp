#pragma once
// summary.json of exp_adaptive (docs/results.md, "adaptive").
#include <optional>
#include <string>
#include <vector>

#include "json_fields.hpp"

namespace ek::results {

/// A low-energy cluster of the full budget that the scaled rule did not find.
struct AdaptiveMissedCluster {
  std::string knot;
  double cluster_energy = 0.0;   ///< [energy] its lowest energy
  double knot_min_energy = 0.0;  ///< [energy] the knot's lowest
  long samples = 0;   ///< [1] full-budget samples that ended in it
};
EK_JSON_FIELDS(AdaptiveMissedCluster, knot, cluster_energy, knot_min_energy, samples)

/// The scaled rule replayed on random orders of each knot's stored runs.
struct AdaptiveShuffled {
  int orders_per_knot = 0;                       ///< [1]
  double low_energy_clusters_found_mean = 0.0;   ///< [1] summed over knots, mean over orders
  double saved_share_mean = 0.0;                 ///< [1]
};
EK_JSON_FIELDS(AdaptiveShuffled, orders_per_knot, low_energy_clusters_found_mean, saved_share_mean)

/// The paper's rule (50 + 10, at most 500) replayed on the stored runs.
struct AdaptivePaperRule {
  std::string adaptive;                  ///< sampling description
  int budget = 0;                        ///< [samples] 500
  int stored_samples = 0;                ///< [samples] per knot in fixed.h5
  int knots_stopped_within_stored = 0;   ///< [1] knots where the replay is exact
  long simulations_upper_bound = 0;      ///< [1] truncated knots counted as the budget
  double saved_share_lower_bound = 0.0;  ///< [1]
  double saved_share_upper_bound = 0.0;  ///< [1] truncated knots counted as stored + 1
  int low_energy_clusters = 0;           ///< [1]
  int low_energy_clusters_found = 0;     ///< [1] a truncated knot used every stored sample
  int median_samples_of_stopped = 0;     ///< [samples] over the exact knots
};
EK_JSON_FIELDS(AdaptivePaperRule, adaptive, budget, stored_samples, knots_stopped_within_stored,
               simulations_upper_bound, saved_share_lower_bound, saved_share_upper_bound, low_energy_clusters,
               low_energy_clusters_found, median_samples_of_stopped)

/// A stopping rule replayed on the random orders of `shuffled` (the same
/// orders for every rule), against the states of the stored samples at the
/// cut: the ground truth of the stopping rules when the budget is 500.
struct AdaptiveRuleReplay {
  std::string rule;                         ///< "score" (the paper's, as reconstructed) or "unseen"
  std::string adaptive;                     ///< its sampling description
  double median_samples = 0.0;              ///< [samples] over knots and orders
  double mean_samples = 0.0;                ///< [samples]
  double capped_share = 0.0;                ///< [1] knot-orders that used every stored sample
  double saved_share = 0.0;                 ///< [1] 1 - samples used / samples stored
  int states = 0;                           ///< [1] the stored samples' states, summed over knots
  double states_found_mean = 0.0;           ///< [1] of them found, summed over knots, mean over orders
  int low_energy_states = 0;                ///< [1] states within low_energy_factor of a knot's lowest
  double low_energy_states_found_mean = 0.0;  ///< [1] summed over knots, mean over orders
  /// [1] knot-orders whose 95% Chao1 interval at the stop (the prefix
  /// clustered alone) holds the stored samples' state count
  double interval_coverage = 0.0;
  double low_energy_interval_coverage = 0.0;  ///< [1] the same for the low-energy states
  /// The chain's own order (sample k continues the walk from sample k − 1:
  /// correlated samples, as a run meets them)
  double chain_mean_samples = 0.0;            ///< [samples] per knot
  int chain_low_energy_states_found = 0;      ///< [1] summed over knots
};
EK_JSON_FIELDS(AdaptiveRuleReplay, rule, adaptive, median_samples, mean_samples, capped_share, saved_share, states,
               states_found_mean, low_energy_states, low_energy_states_found_mean, interval_coverage,
               low_energy_interval_coverage, chain_mean_samples, chain_low_energy_states_found)

struct AdaptiveSummary {
  std::string scale;
  int knots = 0;                            ///< [1]
  int budget = 0;                           ///< [samples] fixed budget per knot
  std::string adaptive;                     ///< the scaled rule's sampling description
  double score_threshold = 0.0;    ///< [1] sampling continues while S > this
  long fixed_simulations = 0;               ///< [1]
  long adaptive_simulations = 0;            ///< [1] of the scaled rule
  double saved_share = 0.0;                 ///< [1] 1 - adaptive / fixed
  int median_samples = 0;                   ///< [samples] per knot, scaled rule
  double stopped_by_score_share = 0.0;      ///< [1] knots whose sampling the score ended
  // Coverage of the scaled rule (measured, not a claim of the paper): the
  // clusters of the full budget within low_energy_factor of the knot's
  // lowest energy, how many the rule found, and the share of the full
  // budget's samples that ended in the clusters it missed.
  double low_energy_factor = 0.0;  ///< [1] kLowEnergyFactor
  int low_energy_clusters = 0;              ///< [1]
  int low_energy_clusters_found = 0;        ///< [1]
  long missed_samples = 0;       ///< [1] full-budget samples in missed clusters
  double missed_sample_share = 0.0;  ///< [1] missed_samples / fixed_simulations
  std::vector<AdaptiveMissedCluster> missed;  ///< one per missed low-energy cluster
  AdaptiveShuffled shuffled;
  AdaptivePaperRule paper_rule;
  std::string fixed_source;                  ///< the stored samples: "" (run here) or the --fixed data set
  std::vector<AdaptiveRuleReplay> rules;     ///< both stopping rules on the same random orders
};
EK_JSON_FIELDS(AdaptiveSummary, scale, knots, budget, adaptive, score_threshold, fixed_simulations,
               adaptive_simulations, saved_share, median_samples, stopped_by_score_share, low_energy_factor,
               low_energy_clusters, low_energy_clusters_found, missed_samples, missed_sample_share, missed, shuffled,
               paper_rule, fixed_source, rules)

}  // namespace ek::results
