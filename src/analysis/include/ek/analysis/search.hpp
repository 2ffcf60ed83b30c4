#pragma once
/// \file
/// Rigid alignment of closed curves (ICP with a search over cyclic shifts and
/// symmetries) and cross-topology search (paper Section 8.2, Fig.\ 10): filter
/// candidates by attribute ranges, then rank them by alignment distance.
///
/// Alignment of a candidate C to a query Q:
///  1. both are resampled at equal arc length to m points (ek::resample_arclength,
///     from vertex 0), so that index shifts correspond to arc-length shifts;
///  2. for every allowed symmetry of C (identity; reversed vertex order;
///     mirror image x -> -x; both) and every cyclic shift s, the optimal rigid
///     motion for the correspondence Q_i <-> C_{(i+s) mod m} is found in closed
///     form (Kabsch/Umeyama: SVD of the 3x3 cross-covariance, with det = +1);
///  3. the `refine_starts` best (symmetry, shift) pairs that are local minima
///     over s are refined by symmetric point-to-point ICP on the resampled
///     points (Besl & McKay 1992; Rusinkiewicz & Levoy 2001): each iteration
///     pairs every point of either curve with the nearest point of the other
///     and solves for the rigid motion of C that minimises the sum of squared
///     pair distances (Kabsch); it stops when the mean squared distance
///     decreases by less than relative_tolerance of itself, or after
///     max_iterations; the start whose result has the smallest symmetric RMS
///     distance between the resampled polygons wins;
///  4. the winner is polished by up to polish_iterations point-to-line
///     Gauss–Newton steps (Chen & Medioni 1992, for curves): each resampled
///     point is paired with the closest point on the other curve's original
///     polygon, the residual is its component normal to that segment, the
///     rotation is linearised about the query's centroid (ω × r) and the
///     damped 6x6 normal equations are solved; resampled points lie on the
///     originals, so an exact rigid copy is aligned to rounding;
///  5. the distance is the symmetric RMS closest-point distance between the
///     original polygons (each one's vertices to the other's segments):
///       d = sqrt( (Σ_i dist(q_i, C)² + Σ_j dist(c_j, Q)²) / (n_Q + n_C) )   [length].
/// Cost, brute-force nearest points: O(m²) per ICP iteration, O(m·n) per
/// polishing step, O(n_Q·n_C) for the distance (m = 100, n = 400: ~10 ms).
/// No scaling: curves of the data set have equal length (n unit edges).
#include <limits>
#include <string>
#include <vector>

#include "ek/analysis/attributes.hpp"
#include "ek/geometry/types.hpp"

namespace ek {

/// Options of align_curves().
struct AlignmentOptions {
  int samples = 100;                ///< [1] points m of the resampled curves (>= 4)
  bool reversal = true;             ///< also try the candidate with reversed orientation
  bool mirror = false;              ///< also try the candidate's mirror image
  int refine_starts = 3;            ///< [1] initial alignments refined by ICP (>= 1)
  int max_iterations = 50;          ///< [1] ICP iterations per start (>= 0)
  int polish_iterations = 10;       ///< [1] point-to-line Gauss-Newton steps on the original polygons (>= 0)
  double relative_tolerance = 1e-8;  ///< [1] ICP stops when the MSE decreases by less than this fraction

  /// Throws std::invalid_argument for values outside the ranges above.
  void validate() const;
};

/// How the ICP of the best start ended: its mean squared distance decreased by
/// less than relative_tolerance (Converged), or max_iterations were reached.
enum class AlignmentStatus { Converged, MaxIterations };

/// Result of align_curves().
struct Alignment {
  double distance = 0.0;  ///< [length] symmetric RMS closest-point distance (step 5)
  /// Rigid motion x -> rotation·x + translation mapping the candidate (after
  /// its symmetry) onto the query.
  Mat3 rotation = Mat3::Identity();
  Vec3 translation = Vec3::Zero();  ///< [length]
  int shift = 0;          ///< [1] initial correspondence of the best start: Q_i <-> C_{(i+shift) mod m}
  bool reversed = false;  ///< the best alignment uses the candidate's reversed orientation
  bool mirrored = false;  ///< the best alignment uses the candidate's mirror image (x -> -x, applied first)
  int iterations = 0;     ///< [1] ICP iterations (step 3) of the best start
  AlignmentStatus status = AlignmentStatus::Converged;  ///< of the best start's ICP
};

/// Aligns `candidate` to `query` (closed polygons, >= 3 vertices each).
Alignment align_curves(const Points& query, const Points& candidate, const AlignmentOptions& options = {});

/// The candidate moved by an alignment: its symmetry (reversed vertex order,
/// mirror image x -> -x; they commute), then x -> rotation·x + translation. Row i is vertex i of the moved (possibly reversed) polygon;
/// alignment.distance is the distance between the query and this curve.
Points aligned_candidate(const Points& candidate, const Alignment& alignment);

/// Closed range of one attribute (attribute names as in attributes.hpp).
struct AttributeRange {
  std::string name;                                      ///< attribute name, e.g. "threedim"
  double min = -std::numeric_limits<double>::infinity();  ///< inclusive lower bound
  double max = std::numeric_limits<double>::infinity();   ///< inclusive upper bound
};

/// Whether every filter's attribute is set and inside its range. Unknown
/// names throw InputError.
bool passes_filters(const Attributes& attributes, const std::vector<AttributeRange>& filters);

/// Ranges around the query's values: [v - w, v + w] with
/// w = max(relative_width·|v|, absolute_width), for each name (the query's
/// attribute must be set).
std::vector<AttributeRange> ranges_around(const Attributes& query, const std::vector<std::string>& names,
                                          double relative_width, double absolute_width = 0.0);

/// Options of search_similar().
struct SearchOptions {
  std::vector<AttributeRange> filters;  ///< pre-filter; empty: every candidate is aligned
  AlignmentOptions alignment;           ///< alignment of each remaining candidate
  int max_results = 10;                 ///< [1] hits returned (0: all that pass the filters)
};

/// One ranked candidate.
struct SearchHit {
  int index = 0;          ///< index into the candidate list
  double distance = 0.0;  ///< [length] alignment distance
  Alignment alignment;    ///< the rigid motion and symmetry that align the candidate to the query
};

/// Cross-topology search: keeps the candidates whose attributes pass
/// options.filters, aligns each to the query, and returns them sorted by
/// increasing distance (ties by index). `candidate_attributes` holds one entry
/// per candidate (e.g. from a data set); when it is empty and there are
/// filters, compute_attributes() is evaluated for each candidate.
std::vector<SearchHit> search_similar(const Points& query, const std::vector<Points>& candidates,
                                      const std::vector<Attributes>& candidate_attributes,
                                      const SearchOptions& options = {});

}  // namespace ek
