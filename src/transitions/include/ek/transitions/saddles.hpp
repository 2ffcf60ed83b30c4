#pragma once
/// \file
/// Verified index-1 saddles of an elastic knot next to one of its stable
/// states, and the minimum energy paths through them (paper Section 8.5:
/// "we currently do not have the means to find the transition between such
/// states, nor quantify the energy barrier separating them").
///
/// From a stable equilibrium x₀ (polished by Newton's method first), one
/// search per soft mode and direction: for each of the `modes` lowest
/// eigenpairs (λ_k, v_k) of H(x₀) without its rigid modes, search_saddle()
/// (ek/optim/saddle.hpp) along +v_k and −v_k. A converged search yields a
/// saddle x_s only when it passes every check:
///   1. ||∇E(x_s)||₂ <= the solver's tolerance (relax()'s gradient tolerance);
///   2. exactly one eigenvalue of H(x_s) without its rigid modes below
///      −ε·λ_min and none within ±ε·λ_min (hessian_index(): λ₁ < 0 < λ₂);
///   3. Newton's method of relax()'s direct method (with_method(o,
///      "hybrid")) from x_s ± δ·v₁ (δ: the largest vertex displacement
///      `displacement`, cut by the collision detection) reaches two
///      converged-stable equilibria: one of them the start x₀ (similarity
///      >= `start_similarity` and energy within `start_energy_tolerance`
///      relative of E₀: a similar state of another energy is another
///      state), the other not (a saddle whose descents both return to x₀,
///      e.g. the curve slid by one edge along itself, joins no two states);
///   4. the Alexander polynomial of every stored image of both descents
///      equals x₀'s, and with a prescribed link Lk = Tw + Wr at the saddle and
///      at both minima equals it within `link_tolerance` (every step is also
///      cut by the CCD, so no step can let two edges pass through each other).
/// The two descents, reversed and joined at x_s, are the path: a monotone
/// descent from the saddle into each basin (the minimum energy path up to
/// the descent's discretisation).
#include <array>
#include <functional>
#include <string>
#include <vector>

#include "ek/geometry/types.hpp"
#include "ek/knots/polynomial.hpp"
#include "ek/optim/saddle.hpp"
#include "ek/solver/relax.hpp"
#include "ek/transitions/status.hpp"

namespace ek {

/// The model, the searches and the checks of the single-ended saddle searches
/// from a knot's stable state (see the file's description).
struct KnotSaddleOptions {
  /// The model (material, contact, tolerance, link); relaxations use its
  /// direct method (with_method(relax, "hybrid")). No slab.
  RelaxOptions relax;
  int modes = 4;                 ///< [1] softest non-rigid modes searched, each in both directions
  /// The searches' options; gradient_tolerance, base_shift and
  /// max_energy_rise are replaced by the model's tolerance, ε·λ_min and
  /// max_rise_factor·E₀.
  SaddleSearchOptions search;
  /// [1] a search has left the basin when E − E₀ > this times E₀ (the
  /// start's energy) before converging.
  double max_rise_factor = 1.0;
  /// [length] largest vertex displacement of x_s ± δ·v₁, halved (up to 30
  /// times) until the energy there is below the saddle's.
  double displacement = 0.02;
  double start_similarity = 0.99;  ///< [1] a descent's minimum is the start at this similarity or more
  double start_energy_tolerance = 1e-8;  ///< [1] ... and with |E − E₀| <= this times |E₀|
  int max_images = 24;           ///< [1] images kept per descent (evenly by path length; >= 2)
  /// [1] the start is an equilibrium when ||∇E|| <= this times the tolerance
  /// before the polish (Newton from it must then converge stable).
  double start_gradient_factor = 1e4;
  /// [1] |Lk − prescribed| allowed at the saddle and the minima (a strand
  /// passage changes Lk by ±2).
  double link_tolerance = 1e-6;
  void validate() const;         ///< InputError for impossible values
};

/// One descent from the saddle (item 3 of the file comment).
struct SaddleMinimum {
  /// Newton's status of the descent (relax()'s), TopologyChanged, or
  /// NotBelowSaddle (no displacement lowered the energy: no descent).
  DescentStatus status = DescentStatus::NotBelowSaddle;
  Points positions;              ///< n by 3, the equilibrium reached
  double energy = 0.0;           ///< [energy]
  double gradient_norm = 0.0;    ///< [energy/length]
  double start_similarity = 0.0; ///< [1] to the start x₀
  int iterations = 0;            ///< [1] Newton iterations of the descent
  std::vector<Points> images;    ///< from the saddle (first) down to the minimum (last)
  std::vector<double> energies;  ///< [energy] of the images
  bool alexander_preserved = true;  ///< on every image
  double link = 0.0;             ///< [1] Lk = Tw + Wr at the minimum (0 without a prescribed link)
  bool link_preserved = true;    ///< |Lk − prescribed| <= link_tolerance (true without a prescribed link)
};

/// One search and, when it converged, its checks.
struct SaddleRecord {
  int mode = 0;                  ///< [1] rank of the followed mode at the start (0: softest)
  int direction = 1;             ///< +1 or −1
  /// Verified, or why not: the search's outcome (MaxIterations, Stalled,
  /// LeftBasin, Degenerate), Index (K ≠ 1 negative eigenvalues),
  /// DegenerateHessian (an eigenvalue within ±ε·λ_min), DescentFailed (a
  /// descent did not converge stable), TopologyChanged (Alexander
  /// polynomial or link), StartNotReached (neither descent reached x₀),
  /// ReturnsToStart (both did); a double-ended search's seed
  /// (double_ended.hpp) has OtherMinima instead of the last two.
  SearchStatus status;
  bool verified = false;         ///< status is Verified
  double energy = 0.0;           ///< [energy] at the saddle (the search's last iterate otherwise)
  double gradient_norm = 0.0;    ///< [energy/length]
  double negative_eigenvalue = 0.0;  ///< [energy/length²] λ₁ (0 when not computed)
  double second_eigenvalue = 0.0;    ///< [energy/length²] λ₂
  int index = -1;                ///< [1] negative eigenvalues (-1: not computed)
  int iterations = 0;            ///< of the search
  int rejected = 0;              ///< steps the trust region rejected
  double seconds = 0.0;          ///< [s] search and checks
  Points saddle;                 ///< n by 3 (the last iterate when not converged)
  /// minima[0]: the descent that reached the start (when verified), minima[1]: the other.
  std::array<SaddleMinimum, 2> minima;
  int duplicate_of = -1;         ///< an earlier verified record with the same saddle (energy and similarity)
  double link = 0.0;             ///< [1] Lk at the saddle (0 without a prescribed link)
};

/// The stable start after the polish.
struct SaddleStart {
  Points positions;              ///< n by 3
  VecX dofs;                     ///< the model's dofs (positions, and θ, Θ when the model has them)
  double energy = 0.0;           ///< [energy]
  double gradient_norm = 0.0;    ///< [energy/length] after the polish
  double input_gradient_norm = 0.0;  ///< [energy/length] of the input
  double tolerance = 0.0;        ///< [energy/length] the model's gradient tolerance
  double lambda_min = 0.0;       ///< [energy/length²] straight rod's, for the shift ε·λ_min
  VecX mode_eigenvalues;         ///< [energy/length²] of the `modes` softest non-rigid modes (ascending, > 0)
  Eigen::MatrixXd modes;         ///< dofs by `modes`: those modes (unit columns)
  AlexanderPolynomial alexander;  ///< of the start
  double energy_scale = 0.0;     ///< [energy] EI / L, L the total rest length
};

/// Gradient norm and lowest eigenvalues of H without rigid modes at a curve,
/// for the model of `model` (direct method; θ relaxed for the given
/// positions when the model has θ): re-verifies a stored saddle or minimum.
struct PointCheck {
  double gradient_norm = 0.0;    ///< [energy/length] ||∇E||₂
  double tolerance = 0.0;        ///< [energy/length] the model's gradient tolerance
  double threshold = 0.0;        ///< [energy/length²] ε·λ_min: |λ| below it is "zero"
  double energy = 0.0;           ///< [energy]
  HessianIndex index;            ///< hessian_index(objective, count, threshold)
};
/// The check of the curve `x` (n by 3, rest lengths `rest`) in the model
/// `model`, with the `count` lowest eigenvalues (see PointCheck).
PointCheck check_point(const Points& x, const VecX& rest, const RelaxOptions& model, int count = 2);

/// Similarity of two curves (for the start check): the caller provides it
/// (ek/analysis similarity with orientation reversal, and mirror images for
/// amphicheiral knots).
using CurveSimilarity = std::function<double(const Points&, const Points&)>;

/// Polishes and checks the start: InputError (one line) when `state` is not
/// a stable equilibrium of the model with rest lengths `rest`.
SaddleStart prepare_start(const Points& state, const VecX& rest, const KnotSaddleOptions& options);

/// Called after each search with (searches done, searches total).
using SaddleProgress = std::function<void(int, int)>;

/// Every search from `start` (prepare_start()) and its checks, in the order
/// mode 0 +, mode 0 −, mode 1 +, ... . Verified records with the same saddle
/// as an earlier one (energy within 1e-9 relative and similarity >= 0.99)
/// get duplicate_of.
std::vector<SaddleRecord> find_knot_saddles(const SaddleStart& start, const VecX& rest, const KnotSaddleOptions& options,
                                            const CurveSimilarity& similarity, const SaddleProgress& progress = {});

/// The path of a verified record from the start over the saddle to the other
/// minimum: minima[0]'s images reversed, then minima[1]'s without the saddle.
/// `saddle_image` receives the saddle's position in it.
std::vector<Points> saddle_path(const SaddleRecord& record, std::vector<double>& energies, int& saddle_image);

/// A path as one OBJ file, atomically: one object per image ("o image_<k>
/// E=<energy>"), each a closed polyline (`l` over its vertices and back).
void write_path_obj(const std::string& path, const std::vector<Points>& images, const std::vector<double>& energies);
/// Reads write_path_obj()'s file: the images and their energies (InputError
/// naming the file when it is not such a file).
std::vector<Points> read_path_obj(const std::string& path, std::vector<double>& energies);

}  // namespace ek
