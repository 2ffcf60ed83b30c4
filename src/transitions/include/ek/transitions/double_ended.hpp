#pragma once
/// \file
/// Double-ended search for a transition between two known, distinct stable
/// states A and B of an elastic knot (paper Section 8.5: "we currently do not
/// have the means to find the transition between such states, nor quantify
/// the energy barrier separating them"). The single-ended searches of
/// saddles.hpp start from one state and find what lies next to it; this one
/// is steered towards a given second state.
///
///  1. Alignment. Over both orientations of B and every cyclic shift s, the
///     rigid motion (R, t) minimising Σ_i |A_i − R B_{(i+s) mod n} − t|²
///     (Kabsch: closed form, SVD of the 3×3 cross-covariance, det R = +1;
///     O(n²) in all); the least residual wins. This is exact on the vertex
///     correspondence the path needs (align_curves() of ek/analysis works on
///     resampled curves and ICP: a different, approximate correspondence). No
///     mirror image: it is not a motion. x_B is the aligned B: the same
///     curve, so the same energy (the model is invariant under rigid
///     motions, re-indexing and reversal with equal rest lengths).
///  2. Steered path. From x₀ = A, for stages j = 0, 1, ...: Newton's method
///     of the model (its direct method) on
///        F_j(x) = E(x) + (k_j/2) |P(x) − x_B|²,   k_j = k₀·growth^j,
///        k₀ = initial_stiffness · λ₁(A)   [energy/length²],
///     λ₁(A) the softest non-rigid eigenvalue of the Hessian at A (so the
///     first stages barely move A: x*(k) − x_A ≈ k (H + kI)⁻¹ (x_B − x_A)),
///     P(x) the positions (n by 3) of the dofs x, from the previous stage's
///     result. The stage minimisers x*(k_j) follow the minimum of F from A
///     until it disappears (a fold: the pull has carried it over the
///     barrier) and Newton's method falls into B's side; the highest images
///     lie near that fold. Every Newton step is cut by the CCD
///     (Objective::max_step), so no step lets two edges pass through each
///     other and the knot type is kept: a B that can only be reached by a
///     strand passage (a crossing change) is never reached. Once an image
///     has similarity >= `reach` to B, Newton's method on E alone from it
///     (the release) must end converged-stable in B's state (below); else
///     steering goes on. The chain is every accepted iterate from A to B
///     (the stages, then the release), thinned evenly by length to
///     `max_images`; the Alexander polynomial of every stored image must be
///     A's.
///  3. Saddle. Seeds, in order: (a) a point on the boundary of A's basin
///     along the chain: a binary search over the chain's iterates (every
///     accepted iterate, before thinning) for consecutive ones x_j, x_{j+1}
///     of which Newton's method on E takes the first into A's state and the
///     second not, then `bisections` halvings of the straight step between
///     them (a step the CCD cleared), then edge tracking (`tracking_rounds`
///     rounds: both points move by `tracking_steps` Newton iterations, each
///     staying in its basin, and the pair, checked again and its straight
///     step cleared by the CCD, is bisected `tracking_bisections` times):
///     the pair slides along the boundary towards the saddle on it, which
///     has one descent into A's state and one out of it; the search starts
///     from the inside point along the step to the outside one; (b) the
///     chain's highest interior local maxima of E, along its tangent
///     x_{i+1} − x_{i−1}; `seeds` in all. From each, search_saddle()
///     (ek/optim/saddle.hpp) follows the mode closest to the given
///     direction; a converged search gets saddles.hpp's checks 1-3 and 5
///     (gradient, exactly one negative and no near-zero eigenvalue, two
///     converged-stable descents from x_s ± δ·v₁, the topology kept), and
///     counts only when one descent ends in A's state and the other in B's:
///     then the barriers are E_s minus the energies of the two minima
///     reached. The first verified seed ends the search.
/// States. A minimum is in A's state when its similarity to A is >= `reach`
/// and its similarity to B is not (and vice versa): the landscape around a
/// state holds many nearby minima of slightly different energy (the
/// single-ended searches join them), which the data set's clustering
/// merges. When it is similar to both (A and B in one similarity class,
/// e.g. a chiral curve and its mirror image, which the similarity cannot
/// tell apart), only A or B itself counts: energy within
/// `energy_tolerance` relative and aligned RMS vertex distance (step 1) at
/// most `same_distance`.
/// Statuses (SearchStatus, status.hpp; never a false saddle): Verified;
/// SameState (A and B are one curve: energies within `energy_tolerance`
/// relative and the aligned RMS vertex distance at most `same_distance`; a
/// mirror image, which the similarity cannot tell apart, is not the same
/// curve); DifferentKnot (Alexander polynomials differ: no path without a
/// strand passage); NotReached (the stages ran out before the release
/// reached B); TopologyChanged (an image's Alexander polynomial differs:
/// the CCD makes this a defect, never expected); else the last seed's status
/// (the search's: MaxIterations, Stalled, LeftBasin, Degenerate; the
/// checks': DegenerateHessian, Index, DescentFailed, TopologyChanged; and
/// OtherMinima when the descents do not end in A's and B's states:
/// TransitionSearch::other_saddles keeps those); NoSeed when no seed was
/// searched (no boundary seed and no interior local maximum of E).
/// The chain's highest energy, E_max − E_A, bounds the barrier of the best
/// path between A and B from above even when no saddle verifies.
#include <array>
#include <string>
#include <vector>

#include "ek/transitions/saddles.hpp"

namespace ek {

/// The model, the steering stages, the chain and the seeds of
/// transition_search() (see the file's description).
struct TransitionSearchOptions {
  /// The model and the checks of the saddle (relax, search, displacement,
  /// max_images, link_tolerance, start_gradient_factor, max_rise_factor:
  /// a seed's search has left the basin when E rises by more than
  /// max_rise_factor·E_A above the seed); `modes` is not used.
  KnotSaddleOptions saddle;
  double initial_stiffness = 0.1;   ///< [1] k₀ / λ₁(A)
  double growth = 1.5;              ///< [1] k_{j+1} / k_j (> 1)
  int max_stages = 60;              ///< [1] steering stages before NotReached (k up to 0.1·1.5⁵⁹ ≈ 2·10⁹ λ₁)
  int stage_iterations = 200;       ///< [1] Newton iterations per stage (and for the release)
  double reach = 0.99;              ///< [1] similarity to B (and A) that counts as reaching it
  double energy_tolerance = 1e-8;   ///< [1] relative energy difference that counts as the same minimum
  /// [length] aligned RMS vertex distance (align_vertices()) within which two
  /// minima of equal energy are one curve (see "States")
  double same_distance = 1e-2;
  int max_images = 48;              ///< [1] images kept in the chain (>= 3)
  int seeds = 3;                    ///< [1] saddle searches at most (the boundary point, then local maxima of E; >= 1)
  /// [1] iterations of each seed's saddle search (replaces saddle.search.max_iterations:
  /// a seed is no equilibrium, and the searches from it take longer than from a state)
  int search_iterations = 1500;
  /// [1] halvings of the chain step that crosses A's basin boundary (0: no boundary seed)
  int bisections = 30;
  int tracking_rounds = 6;          ///< [1] edge-tracking rounds along the boundary (0: none)
  int tracking_steps = 2;           ///< [1] Newton iterations of both points per round
  int tracking_bisections = 12;     ///< [1] halvings per round
  void validate() const;            ///< InputError for impossible values
};

/// The outcome of transition_search(). Energies in [energy], EI/L in
/// energy_scale (L the total rest length).
struct TransitionSearch {
  SearchStatus status;               ///< see the file comment
  bool reached = false;              ///< the release from the chain reached B
  bool verified = false;             ///< status is Verified
  double energy_a = 0.0;             ///< [energy] A after the polish
  double energy_b = 0.0;             ///< [energy] B after the polish
  double energy_scale = 0.0;         ///< [energy] EI / L
  double similarity_ab = 0.0;        ///< [1] of A and B
  double alignment_distance = 0.0;   ///< [length] RMS vertex distance of the aligned B to A
  int stages = 0;                    ///< [1] steering stages run
  double final_stiffness = 0.0;      ///< [energy/length²] k of the last stage
  double reached_similarity = 0.0;   ///< [1] of the chain's last image to B
  ///@{
  /// n by 3: A, and B aligned to A (both polished).
  Points a, b;
  ///@}
  std::vector<Points> chain;         ///< images from A (first) to the chain's end (B when reached)
  std::vector<double> chain_energies;  ///< [energy] E of the images
  bool alexander_preserved = true;   ///< on every chain image
  double path_barrier = 0.0;         ///< [energy] highest chain iterate's E − E_A (when reached; else 0)
  int seeds_tried = 0;               ///< [1] saddle searches run
  std::vector<SearchStatus> seed_statuses;  ///< each seed's search status, in order
  /// The seeds' saddles that passed checks 1-3 and 5 of saddles.hpp (index
  /// one, gradient, two converged-stable descents, topology kept) but whose
  /// descents do not end in A's and B's states (OtherMinima): saddles
  /// between the minima they reached, with their descents.
  std::vector<SaddleRecord> other_saddles;
  /// The last seed's search: minima[0] the descent that ended nearer A (by
  /// similarity; in A's state when verified), minima[1] the other; their
  /// start_similarity is to A. Barriers: energy − minima[k].energy.
  SaddleRecord saddle;
  std::array<double, 2> minima_to_b{0.0, 0.0};  ///< [1] similarity of saddle.minima to B
  double seconds = 0.0;              ///< [s]
};

/// B aligned to A vertex by vertex (step 1 of the file comment): the same
/// curve as B, reversed and cyclically re-indexed and rigidly moved; n by 3
/// each (equal vertex counts, else InputError). `distance` receives the RMS
/// vertex distance [length].
Points align_vertices(const Points& a, const Points& b, double& distance);

/// The double-ended search between stable states `a` and `b` (n by 3 each,
/// rest lengths `rest`): InputError when either is not a stable equilibrium
/// of the model (prepare_start()) or the vertex counts differ.
TransitionSearch transition_search(const Points& a, const Points& b, const VecX& rest,
                                   const TransitionSearchOptions& options, const CurveSimilarity& similarity);

}  // namespace ek
