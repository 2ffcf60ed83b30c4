#pragma once
// summary.json of exp_periodic_braids (docs/results.md, "periodic_braids").
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "json_fields.hpp"

namespace ek::results {

/// A member relaxed from its cylinder start (the paper's multi-covered
/// circle, EmbeddingOptions::braid_style = Cylinder), twist-free.
struct PeriodicEquilibrium {
  std::string method;           ///< relax method: "default" or "paper"
  std::string status;           ///< RelaxResult::status()
  int iterations = 0;           ///< [1] Newton iterations, all phases
  double energy = 0.0;          ///< [energy]
  double threedim = 0.0;        ///< [1]
  bool stable = false;          ///< converged-stable
  double symmetry_error = 0.0;  ///< [1] p-fold about its own best axis (ek::find_symmetry_axis)
  std::string curve;            ///< OBJ, relative to the folder
};
EK_JSON_FIELDS(PeriodicEquilibrium, method, status, iterations, energy, threedim, stable, symmetry_error, curve)

/// The paper's solver (relax --method paper) from the cylinder start, stopped
/// after `iterations` Newton iterations: not converged unless `status` says so.
struct PeriodicTransient {
  int iterations = 0;           ///< [1] the iteration cap
  std::string status;           ///< "max-iterations" unless it converged within the cap
  double energy = 0.0;          ///< [energy]
  double gradient_norm = 0.0;   ///< [energy/length]
  double threedim = 0.0;        ///< [1]
  double symmetry_error = 0.0;  ///< [1] p-fold about its own best axis
  std::string curve;            ///< OBJ, relative to the folder
};
EK_JSON_FIELDS(PeriodicTransient, iterations, status, energy, gradient_norm, threedim, symmetry_error, curve)

/// One eigenpair of the full Hessian at a symmetric critical point.
struct PeriodicMode {
  double eigenvalue = 0.0;        ///< [energy/length²]
  int dominant_class = 0;         ///< [1] wavenumber of the largest Fourier class (0: symmetric)
  std::vector<double> classes;    ///< [1] weight per wavenumber 0..⌊p/2⌋ (ek::symmetry_classes)
};
EK_JSON_FIELDS(PeriodicMode, eigenvalue, dominant_class, classes)

/// Where a saddle falls: relax() from the critical point displaced along its
/// most negative mode (sign ±1).
struct PeriodicSaddleDescent {
  int sign = 1;
  std::string status;
  double energy = 0.0;    ///< [energy]
  double threedim = 0.0;  ///< [1]
};
EK_JSON_FIELDS(PeriodicSaddleDescent, sign, status, energy, threedim)

/// A p-fold symmetric critical point (ek::find_symmetric_critical_point):
/// Newton within the p-fold symmetric subspace, verified in the full space.
struct PeriodicCriticalPoint {
  std::string solve;             ///< "minimize" (a minimum within the subspace) or "root" (Newton–Raphson)
  std::string status;            ///< of the restricted solve
  int iterations = 0;            ///< [1]
  bool converged = false;        ///< full gradient norm <= tolerance
  double energy = 0.0;           ///< [energy]
  double gradient_norm = 0.0;    ///< [energy/length] ||∇E|| in the full space
  double tolerance = 0.0;        ///< [energy/length]
  double threedim = 0.0;         ///< [1]
  double residual = 0.0;         ///< [length] distance from exact p-fold symmetry (rms)
  bool alexander_preserved = false;
  int index = 0;                 ///< [1] Morse index: negative eigenvalues of the full Hessian
  bool index_complete = false;   ///< false: `index` is a lower bound
  int near_zero = 0;             ///< [1] eigenvalues within ±threshold
  int subspace_index = 0;        ///< [1] negative eigenvalues within the symmetric subspace
  double threshold = 0.0;        ///< [energy/length²]
  std::vector<PeriodicMode> modes;  ///< the lowest eigenpairs (every negative one first)
  std::array<double, 3> axis{0.0, 0.0, 1.0};    ///< unit: the symmetry axis
  std::array<double, 3> center{0.0, 0.0, 0.0};  ///< a point of the axis
  int crossings = 0;             ///< [1] braid crossings along the axis (within kCrossingGap)
  std::string polygon_split;     ///< "height" or "radius"
  double polygon_error_deg = 0.0;  ///< [deg]
  double rotation_deg = 0.0;       ///< [deg] between the two p-gons
  std::string curve;             ///< OBJ, relative to the folder
  std::vector<PeriodicSaddleDescent> descents;  ///< where it falls (index >= 1), both signs
};
EK_JSON_FIELDS(PeriodicCriticalPoint, solve, status, iterations, converged, energy, gradient_norm, tolerance, threedim,
               residual, alexander_preserved, index, index_complete, near_zero, subspace_index, threshold, modes, axis,
               center, crossings, polygon_split, polygon_error_deg, rotation_deg, curve, descents)

/// The search for a 3D symmetric critical point where the subspace's minimum
/// is flat: the restricted descent from the cylinder (ek::descend_symmetric),
/// its 3D image of least gradient norm (the bottleneck of the flow), and
/// Newton–Raphson within the subspace from there.
struct PeriodicThreeDSearch {
  int images = 0;                ///< [1] images of the restricted descent
  int image = 0;                 ///< [1] the image of least gradient norm with 3D-ness >= search_threedim
  double search_threedim = 0.0;  ///< [1]
  double energy = 0.0;           ///< [energy] of that image
  double gradient_norm = 0.0;    ///< [energy/length] of that image (full space)
  double threedim = 0.0;         ///< [1] of that image
  int crossings = 0;             ///< [1] braid crossings of that image along the axis
  double polygon_error_deg = 0.0;  ///< [deg]
  double rotation_deg = 0.0;       ///< [deg]
  std::string curve;             ///< OBJ of that image, relative to the folder
  std::string root_status;       ///< Newton–Raphson from it
  double root_energy = 0.0;      ///< [energy]
  double root_gradient_norm = 0.0;  ///< [energy/length]
  double root_threedim = 0.0;    ///< [1]
  bool found = false;            ///< it converged to a 3D critical point (then symmetric_critical_point)
};
EK_JSON_FIELDS(PeriodicThreeDSearch, images, image, search_threedim, energy, gradient_norm, threedim, crossings,
               polygon_error_deg, rotation_deg, curve, root_status, root_energy, root_gradient_norm, root_threedim,
               found)

struct PeriodicMember {
  std::string family;              ///< "s1s2i" (σ1σ2⁻¹)^p or "s1s2is3" (σ1σ2⁻¹σ3)^p
  int p = 0;                       ///< [1] periods
  std::optional<std::string> knot;  ///< the tabulated knot type, null when not tabulated
  // ---- relaxed twist-free from our flat coil (multicovered_circle())
  std::string status;              ///< solver status
  double energy = 0.0;             ///< [energy]
  bool alexander_preserved = false;
  std::optional<bool> alexander_matches_table;  ///< null when not tabulated
  double threedim = 0.0;           ///< [1]
  double symmetry_error = 0.0;     ///< [1] p-fold about `axis` (ek::rotational_symmetry_error)
  double control_error = 0.0;      ///< [1] (p+1)-fold about the same axis
  std::array<double, 3> axis{0.0, 0.0, 1.0};    ///< unit: ek::find_symmetry_axis of the relaxed state
  std::array<double, 3> center{0.0, 0.0, 0.0};  ///< its point, the centroid
  int crossings = 0;               ///< [1] braid crossings along the axis (within kCrossingGap)
  int projection_crossings = 0;    ///< [1] every crossing of the projection along the axis
  std::string polygon_split;       ///< "height" or "radius"
  double polygon_error_deg = 0.0;  ///< [deg]
  double relative_rotation_deg = 0.0;   ///< [deg]
  /// [deg] the rotation between the two p-gons by the family: 180/p for
  /// (σ1σ2⁻¹)^p, 0 for (σ1σ2⁻¹σ3)^p
  double expected_rotation_deg = 0.0;
  std::string curve;               ///< OBJ of the relaxed state, relative to the folder
  // ---- from the cylinder start (the paper's multi-covered circle)
  double start_threedim = 0.0;     ///< [1] of the cylinder start
  PeriodicEquilibrium equilibrium;        ///< relax(), the default method
  PeriodicEquilibrium equilibrium_paper;  ///< relax --method paper
  std::vector<PeriodicTransient> transient;  ///< the paper's solver at 100 and 200 iterations
  PeriodicCriticalPoint symmetric_critical_point;  ///< 3D when one was found, else the subspace's minimum
  /// Present when the subspace's minimum is flat (3D-ness < kPlanarThreedim).
  std::optional<PeriodicThreeDSearch> three_d_search;

  /// The tabulated knot's name, or "".
  std::string tabulated() const { return knot.value_or(""); }
};
EK_JSON_FIELDS(PeriodicMember, family, p, knot, status, energy, alexander_preserved, alexander_matches_table, threedim,
               symmetry_error, control_error, axis, center, crossings, projection_crossings, polygon_split,
               polygon_error_deg, relative_rotation_deg, expected_rotation_deg, curve, start_threedim, equilibrium,
               equilibrium_paper, transient, symmetric_critical_point, three_d_search)

/// A member whose closure is a link (paper §8.5: links), relaxed as a link
/// from the coil (one component per cycle of the braid's permutation).
struct PeriodicLinkMember {
  std::string family;
  int p = 0;
  int components = 0;               ///< [1]
  int vertices = 0;                 ///< [1] in all
  std::string status;               ///< RelaxResult::status()
  double energy = 0.0;              ///< [energy]
  bool alexander_preserved = false;  ///< every component's polynomial kept
  bool linking_preserved = false;    ///< every linking number kept
  bool conway_preserved = false;     ///< the link's Conway polynomial kept
  std::vector<std::int64_t> conway;  ///< [1] the link's ∇, c_0, c_1, ... (ek/knots/conway.hpp)
  std::vector<int> linking_numbers;  ///< [1] components × components, row by row (from the braid word)
  double min_distance = 0.0;        ///< [length] closest edge pair within reach of the contact (NaN: none)
  double threedim = 0.0;            ///< [1] 3D-ness of all vertices together
  double symmetry_error = 0.0;      ///< [1] p-fold, about the axis of least extent through the centroid
  double control_error = 0.0;       ///< [1] (p+1)-fold about the same axis
  std::string curve;                ///< link file, relative to the experiment's folder
};
EK_JSON_FIELDS(PeriodicLinkMember, family, p, components, vertices, status, energy, alexander_preserved,
               linking_preserved, conway_preserved, conway, linking_numbers, min_distance, threedim, symmetry_error, control_error, curve)

struct PeriodicBraidsSummary {
  std::string scale;
  double crossing_gap = 0.0;        ///< [length] kCrossingGap
  double radius = 0.0;              ///< [length] wire radius r of the curves
  double threedim_threshold = 0.0;  ///< [1] kPlanarThreedim: a state at least this 3D counts as 3D
  std::vector<PeriodicMember> members;
  /// Braids of the families whose closure is not a knot (skipped), e.g. "s1s2i p=3: 3 components".
  std::vector<std::string> skipped;
  /// The skipped members relaxed as links, in the order of `skipped`.
  std::vector<PeriodicLinkMember> links;
};
EK_JSON_FIELDS(PeriodicBraidsSummary, scale, crossing_gap, radius, threedim_threshold, members, skipped, links)

}  // namespace ek::results
