#pragma once
/// \file
/// A knot under load: the path of its equilibria as a device pulls two of
/// its points apart, presses it between two plates, or applies a pair of
/// forces (loads.hpp), followed by pseudo-arclength continuation
/// (continuation.hpp); where the path turns back at a limit point and loses
/// stability, the knot snaps: the state it falls into under the load, and
/// that state relaxed without it.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "ek/geometry/types.hpp"
#include "ek/mechanics/continuation.hpp"
#include "ek/solver/relax.hpp"

namespace ek {

/// What the device does.
enum class LoadKind {
  Pull,    ///< displacement control: two vertices pulled to a distance
  Plates,  ///< displacement control: two parallel plates closed to a gap
  Force,   ///< load control: opposite forces on two vertices
};
std::string to_string(LoadKind kind);           ///< "pull", "plates", "force"
LoadKind parse_load_kind(const std::string& text);  ///< InputError for another text

/// The model, the device and the path of load_knot().
struct KnotLoadOptions {
  /// The model (twist-free: no link, no full model, no slab): material, d̂,
  /// ω, the tolerance (the correctors' gradient tolerance) as for relax().
  RelaxOptions relax;
  LoadKind kind = LoadKind::Pull;  ///< the device: pull, plates or force
  /// pull, force: the two vertices (0-based, distinct); unset: the pair
  /// farthest apart in the relaxed start (its diameter)
  std::optional<std::array<int, 2>> vertices;
  /// [parameter] start of the parameter: the distance, gap or force; unset:
  /// the start's distance of i and j (pull), its extent along the normal
  /// plus the reach of the plates' barrier on each side (plates), 0 (force)
  std::optional<double> from;
  double to = 0.0;                     ///< [parameter] where the path ends
  /// plates: their unit normal; unset: the start's axis of least extent
  /// (the smallest principal axis of its vertices)
  std::optional<Vec3> normal;
  /// [EI/ℓ³] the pull's spring stiffness k (ℓ the mean rest edge length):
  /// far stiffer than a knot along a pull, so the distance follows the control
  double pull_stiffness = 100.0;
  /// [1] the plates' barrier: its reach in wire radii and its stiffness in
  /// units of the contact stiffness ω
  double plates_reach = 1.0;
  double plates_stiffness = 1.0;       ///< [ω] the plates' barrier stiffness κ in units of ω
  int steps = 40;                      ///< [1] the first arclength step is |to − from| / steps
  int max_points = 400;                ///< [1] points of the path at most
  bool stop_at_snap = true;            ///< end the path at its first snap (else go on from the state it snapped into)
  /// relax the start without the load first (false: the start is taken as
  /// it is, e.g.\ a point of an earlier path, already an equilibrium under the
  /// load at `from`; the path's first point brings it to the tolerance there)
  bool relax_start = true;
  int eigen_count = 4;                 ///< [1] lowest eigenpairs at each point (the index)
  /// [ℓ] a landing farther than this RMS vertex distance (after the best
  /// rigid motion) from the predictor and from the branch's last state, at
  /// the smallest step and with energy released at the same control, is a
  /// snap (continuation.hpp, ContinuationOptions::minimizer)
  double snap_jump = 0.1;
  void validate() const;               ///< InputError for impossible values
};

/// Where the knot snapped: the stable branch it followed ended (at a fold
/// of the load path or where the branch lost its stability) and the
/// minimiser, at the smallest step, fell into another stable state.
struct Snap {
  int point = 0;                  ///< [1] the path point of the state it fell into (PathEvent::Snap)
  double parameter = 0.0;         ///< [parameter] the last parameter of the branch that ended
  double reaction = 0.0;          ///< [force] the device's force there: the push that flips the state
  double jump = 0.0;              ///< [length] RMS vertex distance from the branch's last state to the new one
  /// [energy] E_knot + E_load released by the jump at the same control:
  /// E(x_before; μ) − E(x_loaded; μ) at the snap's point μ (> 0; dissipated)
  double energy_drop = 0.0;
  Points loaded;                  ///< n by 3: the stable state it falls into under the load
  double loaded_energy = 0.0;     ///< [energy] E_knot + E_load there
  Points released;                ///< n by 3: that state relaxed without the load
  RelaxStatus released_status = RelaxStatus::Stalled;  ///< RelaxResult::status()
  double released_energy = 0.0;   ///< [energy]
  /// the state it falls into and its released state have the start's Alexander polynomial
  bool alexander_preserved = true;
};

/// What load_knot() returns: the stable load path, its work and the snaps
/// along it.
struct KnotLoadResult {
  /// The stable path; no points (status stalled) when no equilibrium under
  /// the load was found at its start `from`.
  LoadPath path;
  std::string parameter_name;     ///< "distance", "gap" or "force"
  double from = 0.0;              ///< [length or energy/length] the control at the path's start
  double start_energy = 0.0;      ///< [energy] the start relaxed without load (as given without relax_start)
  /// [energy] ∫ ∂E/∂μ dμ along the path (trapezoids; a snap is a jump at
  /// nearly fixed μ and does no work): for a displacement control, the
  /// change of E_knot + E_load plus the energy the snaps dissipated
  double work = 0.0;
  double dissipated = 0.0;        ///< [energy] Σ of the snaps' energy drops
  /// [1] points where the path left its branch without a snap
  /// (PathEvent::BranchJump: no energy released at the same control)
  int branch_jumps = 0;
  bool alexander_preserved = true;  ///< at every path point
  std::vector<Snap> snaps;        ///< every snap of the path, in order
  Vec3 normal = Vec3::UnitZ();    ///< plates: the normal used
  std::array<int, 2> vertices{-1, -1};  ///< pull, force: the vertices used
  double pull_stiffness = 0.0;    ///< [energy/length²] the pull's k
};

/// The two vertices of X (n by 3) farthest apart (the default pull's pair).
std::array<int, 2> diameter_pair(const Points& X);

/// The secant stiffness dF/dδ at path point k from point k − 1 (reaction
/// over displacement) [energy/length²]; none at the first point, across a
/// snap, or where the displacement did not change.
std::optional<double> secant_stiffness(const LoadPath& path, size_t k);

/// ∫ ∂E/∂μ dμ over the path's points [0, end) by trapezoids, a snap or a
/// branch jump (a jump at nearly fixed μ) doing no work: KnotLoadResult::work for end = all.
double path_work(const LoadPath& path, size_t end);

/// Loads `start` (n by 3, simple; rest lengths `rest`, n) as `options` say:
/// relaxes it without load first (unless relax_start is off), then follows its stable equilibria from
/// `from` to `to` (continuation.hpp with the model's Newton solver as the
/// corrector); where the branch ends the knot snaps into another stable
/// state and, unless stop_at_snap, the path goes on from there. InputError
/// for bad options or a start the model refuses (touching itself, outside the
/// plates at `from`).
KnotLoadResult load_knot(const Points& start, const VecX& rest, const KnotLoadOptions& options);

}  // namespace ek
