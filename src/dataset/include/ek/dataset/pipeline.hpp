#pragma once
/// \file
/// The data-set pipeline (paper Section 7.4, Fig.\ 3): for a knot type, random
/// cubic-lattice samples (lattice module) are relaxed to stable equilibria
/// (solver), compared with the curvature-torsion similarity, clustered
/// (analysis), and stored with their attributes and the report of every run.
///
/// Adaptive sampling (Section 7.4; the paper's supplement, which defines the
/// score, is not available, so the definition is ours): 50 initial samples,
/// then batches of 10; after each batch the importance score
///
/// ~~~{.unparsed}
///   S = max_{j in batch, stable} ν_j · w_j  ∈ [0, 1],
///   ν_j = min(1, (1 - max_{i earlier or earlier in the batch} sim(j, i)) / δ)   (geometric novelty)
///   w_j = E_min / E_j                                                         (energy weight)
/// ~~~
///
/// where sim is the similarity of Section 7.1 (with orientation reversal),
/// δ = novelty_distance, the distance at which two states count as different,
/// and E_min the lowest energy found so far (this batch included). S is 1
/// when the batch found a state unlike all earlier ones at the lowest energy
/// seen, and 0 when every new state repeats a known one (or none converged).
/// Sampling continues while S > score_threshold (0.1) and stops at
/// max_samples (500). A batch without any stable equilibrium scores 0.
///
/// The unseen rule (ours, not the paper's; StoppingRule::Unseen): after each
/// batch the stable equilibria so far are clustered at δ (complete linkage on
/// 1 - similarity, as the data set's states); a state is low in energy when
/// its lowest energy is at most low_energy_factor times the lowest found so
/// far. With n the stable samples and f1 the low-energy states seen once,
/// p = f1 / n estimates the chance that the next sample finds a low-energy
/// state not seen yet (Good–Turing for one kind of state,
/// ek/analysis/unseen.hpp), and P = 1 - (1 - p)^b that the next batch of b
/// samples does. Sampling continues while P > new_state_threshold and stops
/// at max_samples; the score history holds P after each batch (0 for a batch
/// after which no state is seen once).
///
/// Determinism: the samples of a knot come from one walk: sample k continues
/// from sample k - 1 with a seed derived from the run's seed, the knot's name
/// and k, so an adaptive run uses exactly the first samples of a fixed-budget
/// run with the same seed; each relaxation is sequential and
/// deterministic, so the stored equilibria do not depend on the number of
/// jobs or on thread scheduling (only the order in which runs finish and the
/// measured seconds do).
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "ek/analysis/similarity.hpp"
#include "ek/dataset/dataset_file.hpp"
#include "ek/knots/link_table.hpp"
#include "ek/knots/table.hpp"
#include "ek/lattice/sampling.hpp"
#include "ek/solver/relax.hpp"

namespace ek {

/// How adaptive sampling decides that a knot has enough samples (see the file comment).
enum class StoppingRule {
  Score,   ///< the importance score S of the last batch; continue while S > score_threshold (the paper's rule)
  Unseen,  ///< the chance P of a new low-energy state in the next batch; continue while P > new_state_threshold
};
std::string to_string(StoppingRule rule);  ///< "score", "unseen"
/// "score" or "unseen"; InputError otherwise.
StoppingRule parse_stopping_rule(const std::string& name);

/// How a knot type's entry is computed: the relaxation, the lattice samples,
/// the sample count or adaptive rule, the similarity, the seed and the jobs.
struct ExploreOptions {
  RelaxOptions relax;              ///< material, tolerance, iterations (stiffness: see `stiffness`)
  SampleOptions sampling;          ///< n, fugacities, decorrelation (count and seed are set per batch)
  LatticeStartOptions start;       ///< how the first lattice polygon is made
  int samples = 50;                ///< [1] samples per knot without adaptive sampling
  /// [samples] Burn-in: the knot's walk makes and discards this many samples
  /// before sample 0, so sample k is the walk's sample burn_in + k (the same
  /// curve and seed as sample burn_in + k of a run without burn-in). The walk
  /// starts next to the rounded table drawing and drifts away over many
  /// samples (docs/models.md, "Lattice sampling"); 0 keeps every sample.
  int burn_in = 0;
  bool adaptive = false;           ///< adaptive sampling (see the file comment)
  int initial_samples = 50;        ///< [1] adaptive: samples before the first score
  int batch_samples = 10;          ///< [1] adaptive: samples per batch after the initial ones
  int max_samples = 500;           ///< [1] adaptive: the most samples per knot
  StoppingRule stopping = StoppingRule::Score;  ///< adaptive sampling's rule
  double score_threshold = 0.1;    ///< [1] Score: continue while S > this
  double new_state_threshold = 0.1;  ///< [1] Unseen: continue while P > this
  double low_energy_factor = 1.1;  ///< [1] Unseen: a state is low in energy below this times the lowest
  double novelty_distance = 0.1;   ///< [1] δ in 1 - similarity
  SimilarityOptions similarity;    ///< comparisons (orientation reversal on by default)
  /// Compare with mirror images too (similarity.mirror) for the knots whose
  /// unoriented type equals its mirror image: KnotInfo symmetry type
  /// positive, negative or fully amphicheiral (paper Section 7.1,
  /// "Symmetries": mirror images are states of equal energy, the same state
  /// when the knot type allows it). Off: similarity.mirror as given.
  bool mirror_amphicheiral = true;
  bool stiffness = true;           ///< compute the stiffness attribute (smallest non-rigid Hessian eigenvalue)
  std::uint64_t seed = 1;          ///< run seed; each knot's walk seed is derived from it and the name
  int jobs = 1;                    ///< [1] relaxations in parallel
  ExploreOptions();                ///< The defaults; the similarity with orientation reversal on.
  void validate() const;           ///< InputError for impossible values
  /// "fixed:50", "adaptive:50+10,max=500,S>0.1,delta=0.1" (Score) or
  /// "adaptive:50+10,max=500,unseen<0.1,low=1.1,delta=0.1" (Unseen): recorded in the file.
  std::string sampling_description() const;
};

/// The file-level metadata of a data set computed with these options: every
/// field of metadata_fields() set, d̂, ω and the tolerance as resolve_model()
/// resolves them for the lattice samples' unit edges. Not recorded (library
/// settings that `knots explore` and `knots dataset` do not expose, kept at
/// their defaults there): start, similarity, mirror_amphicheiral, and the
/// solver's inner settings (relax.newton apart from the Hessian mode and the
/// rigid-motion removal, the contact Hessian and the damping of short steps, which the named methods of
/// with_method() set; max_tangent_rotation, contact_hessian_margin, slab, the
/// value of a prescribed link); jobs does not change the results.
DatasetMetadata dataset_metadata(const ExploreOptions& options);

/// The run status of a relaxation that ended with `status` (the same name).
RunStatus run_status(RelaxStatus status);

/// Seed of a knot's walk: splitmix64 of the run seed and a hash of the name.
std::uint64_t knot_seed(std::uint64_t run_seed, const std::string& name);
/// Seed of sample k of a knot: the walk continues from sample k - 1 with
/// this seed, so sample k depends only on (knot seed, k), not on batching.
std::uint64_t sample_seed(std::uint64_t knot_seed, int sample);

/// Names of the attribute columns stored per equilibrium.
const std::vector<std::string>& dataset_attribute_names();

/// The options used for one knot: `options` with similarity.mirror set when
/// mirror_amphicheiral and the knot is amphicheiral (see ExploreOptions).
ExploreOptions options_for_knot(const ExploreOptions& options, const KnotRecord& knot);

/// Importance score S of a batch (see the file comment): `batch_similarity`
/// is the batch's stable equilibria (rows) against every stable equilibrium
/// known before the batch and the earlier members of the batch (columns in the
/// order [earlier..., batch...]; entries of later batch members are ignored).
double importance_score(const Eigen::MatrixXd& batch_similarity, int earlier, const std::vector<double>& batch_energies,
                        double minimum_energy, double novelty_distance);

/// Samples that fell into each state, and each state's lowest energy, when
/// equilibria with these similarities ([m, m]) and energies ([m]) are
/// clustered at `cut` (complete linkage on 1 - similarity, as the data set's
/// states); states numbered by their first member. m = 0: no state.
struct StateCounts {
  std::vector<int> counts;     ///< [samples] per state
  std::vector<double> lowest;  ///< [energy] per state
};
/// The states of equilibria with `similarity` [m, m] and `energies` [m] at
/// `cut` (see StateCounts).
StateCounts state_counts(const Eigen::MatrixXd& similarity, const std::vector<double>& energies, double cut);

/// The stopping rule's score of successive batches (see the file comment),
/// fed with similarities: S (Score) or P (Unseen). Keeps the similarities
/// among every stable equilibrium seen so far (Unseen) and their energies.
class StoppingScore {
 public:
  explicit StoppingScore(const ExploreOptions& options);  ///< The rule, δ, the low-energy factor and b of `options`.
  /// Adds a batch: `similarity` of its stable equilibria (rows) against
  /// [earlier..., batch...] (columns; entries of later batch members are
  /// ignored), `energies` theirs. Returns the batch's score.
  double add_batch(const Eigen::MatrixXd& similarity, const std::vector<double>& energies);

 private:
  double unseen_score() const;
  StoppingRule rule_;
  double novelty_distance_, low_energy_factor_;  ///< [1] δ, and the low-energy factor
  int batch_samples_;                            ///< [1] b
  Eigen::MatrixXd similarity_;   ///< Unseen: [m, m] among the stable equilibria so far
  std::vector<double> energies_;  ///< [energy] theirs
  double min_energy_ = std::numeric_limits<double>::infinity();
};

/// The stopping rule on curves: the signature spectra of every stable
/// equilibrium seen so far give the similarities of a new batch.
class AdaptiveScorer {
 public:
  /// An engine for the options' similarity; no equilibrium seen yet.
  explicit AdaptiveScorer(const ExploreOptions& options);
  /// Adds a batch of stable equilibria (curve, energy) and returns its score.
  double add_batch(const std::vector<std::pair<const Points*, double>>& stable);

 private:
  SimilarityEngine engine_;
  std::vector<SignatureSpectrum> spectra_;
  StoppingScore score_;
};

/// Where adaptive sampling would stop on the runs of a fixed-budget entry
/// (its samples are the adaptive run's first samples, see sample_seed()), and
/// the score after each batch; `truncated` when the fixed run has too few
/// samples to decide. The similarities are the entry's stored ones (those
/// explore_knot computes from the same curves and options), so a replay
/// costs no signature.
struct AdaptiveReplay {
  int samples_used = 0;               ///< [1] samples at which the rule stops
  std::vector<double> score_history;  ///< [1] the score after each batch
  bool truncated = false;             ///< the entry's runs ended before the rule stopped
};
/// The replay of the adaptive rule of `options` on the runs of `fixed`
/// (runs in sample order, similarities stored); see AdaptiveReplay.
AdaptiveReplay replay_adaptive(const KnotEntry& fixed, const ExploreOptions& options);

/// Called after every finished run (under a lock, from a worker thread).
using RunCallback = std::function<void(const RunRecord&)>;

/// Samples, relaxes, stores and clusters one knot type. Completed runs are
/// appended to the journal file at `journal_path` (if not empty) as they
/// finish; a journal left by an interrupted run with the same options is read
/// first and its runs are not repeated. Throws InputError for impossible
/// options and for a journal written with different options.
KnotEntry explore_knot(const KnotRecord& knot, const ExploreOptions& options, const std::string& journal_path = "",
                       const RunCallback& on_run = {});

/// The attribute columns of a link's equilibria: energy (the total E_rod +
/// ω E_contact, as a knot's), energy_stretch, energy_bend, energy_contact;
/// max_stress (the largest of the components'); total_curvature and writhe
/// (summed over the components, each component's own writhe without the
/// linking terms); threedim, sphericity and diameter (of all vertices
/// together); min_distance [length] (closest approach of two edges sharing
/// no vertex, across components too); sample.
const std::vector<std::string>& link_attribute_names();

/// A link's entry (paper Section 8.5 extends the simulation to links; this
/// applies the data set of Section 7.4 to them): sample k continues the
/// link's BFACF walk (sample_lattice_link, from lattice_link_start) with the
/// seed sample_seed(knot_seed(seed, name), burn_in + k), as for knots; each
/// sample is relaxed by relax() of the link (the twist-free model by the direct
/// method) and checked against the link type (a change is a run with status
/// "topology-changed", never an equilibrium); the entry is clustered on the
/// link state distance (ek/analysis/link_states.hpp). Journal and resume as
/// explore_knot. Throws InputError for adaptive sampling (its score is
/// defined with the curvature-torsion similarity of knots), for the
/// multilevel method and for the stiffness attribute, which links do not have.
KnotEntry explore_link(const LinkRecord& link, const ExploreOptions& options, const std::string& journal_path = "",
                       const RunCallback& on_run = {});

/// One distinct equilibrium: a cluster of a knot's stored equilibria at a
/// cut, represented by its lowest-energy member.
struct StateCluster {
  std::vector<int> members;   ///< equilibrium indices (rows of KnotEntry::equilibria)
  int representative = -1;    ///< the member of lowest energy
  double energy_min = 0.0;    ///< [energy]
  double energy_max = 0.0;    ///< [energy]
};

/// The clusters of the entry's equilibria at `cut` (complete linkage on
/// 1 - similarity, from the stored linkage), sorted by increasing energy.
/// `rank` (optional) receives each equilibrium's cluster position in that order.
std::vector<StateCluster> clusters_at_cut(const KnotEntry& entry, double cut, std::vector<int>* rank = nullptr);

/// Recomputes the similarity matrix and the complete-linkage dendrogram of
/// the stored equilibria (used after merging and by explore_knot): the
/// curvature-torsion similarity for a knot, 1 − the link state distance for
/// a link (`options` unused).
void cluster_entry(KnotEntry& entry, const SimilarityOptions& options);

}  // namespace ek
