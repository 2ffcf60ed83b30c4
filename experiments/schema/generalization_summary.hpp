#pragma once
// summary.json of exp_generalization (docs/results.md, "generalization"):
// 9_35's three-circle state, the data set's states closest to it, and the
// pretzel family P(p,q,r) built beyond the table (paper Section 8.4, Fig. 15).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "json_fields.hpp"

namespace ek::results {

/// The circle fit of a state (ek::fit_circles, three circles) and the criterion.
struct CircleMeasure {
  double relative_rms = 0.0;     ///< [1] RMS distance of the vertices to their circle / mean radius
  double min_plane_angle = 0.0;  ///< [rad] smallest angle between two circles' planes
  double min_share = 0.0;        ///< [1] smallest fraction of the vertices on one circle
  double mean_radius = 0.0;      ///< [length]
  bool three_circles = false;    ///< meets the criterion (summary's circle_criterion)
};
EK_JSON_FIELDS(CircleMeasure, relative_rms, min_plane_angle, min_share, mean_radius, three_circles)

/// 9_35's three-circle state.
struct GeneralizationPattern {
  std::string knot;          ///< "9_35"
  std::string route;         ///< how it was reached ("pd": the PD drawing relaxed)
  std::string status;        ///< solver status
  double energy = 0.0;       ///< [energy]
  double threedim = 0.0;     ///< [1]
  double total_curvature = 0.0;  ///< [rad]
  CircleMeasure circles;
  std::string curve;         ///< OBJ path relative to the folder
};
EK_JSON_FIELDS(GeneralizationPattern, knot, route, status, energy, threedim, total_curvature, circles, curve)

/// One equilibrium of the data set close to the pattern.
struct GeneralizationHit {
  int rank = 0;           ///< [1] 1-based
  std::string knot;
  int index = -1;         ///< equilibrium index in the data set
  double distance = 0.0;  ///< [length] alignment distance to the pattern
  double threedim = 0.0;  ///< [1]
  CircleMeasure circles;
  std::string curve;      ///< OBJ path relative to the folder, aligned onto the pattern
};
EK_JSON_FIELDS(GeneralizationHit, rank, knot, index, distance, threedim, circles, curve)

/// One constructed member P(p,q,r).
struct GeneralizationMember {
  std::string name;                   ///< "P(3,3,5)" (signs as constructed)
  std::vector<int> twists;            ///< crossings per touching region, signed (ek::pretzel_pd)
  int crossings = 0;                  ///< [1] of the construction's diagram, Σ|p_i|
  std::vector<std::int64_t> alexander;  ///< the construction's Alexander polynomial
  std::vector<std::string> table_knots;  ///< table knots with the same polynomial (none: not in the table)
  std::string status;                 ///< solver status
  bool alexander_preserved = false;   ///< the equilibrium's polynomial is the construction's
  double energy = 0.0;                ///< [energy]
  double threedim = 0.0;              ///< [1]
  double total_curvature = 0.0;       ///< [rad]
  double similarity = 0.0;            ///< [1] curvature-torsion similarity to the pattern (with reversal)
  double alignment_distance = 0.0;    ///< [length] ICP distance to the pattern (same length, no scaling)
  CircleMeasure circles;
  std::string curve;                  ///< OBJ path relative to the folder (the equilibrium)
};
EK_JSON_FIELDS(GeneralizationMember, name, twists, crossings, alexander, table_knots, status, alexander_preserved,
               energy, threedim, total_curvature, similarity, alignment_distance, circles, curve)

struct GeneralizationSummary {
  std::string scale;
  /// the criterion of CircleMeasure::three_circles (ek::CircleCriterion)
  double max_relative_rms = 0.0;        ///< [1]
  double min_share = 0.0;               ///< [1]
  double min_plane_angle = 0.0;         ///< [rad]
  GeneralizationPattern pattern;
  std::string dataset;                  ///< searched data set, relative to the results root
  long dataset_equilibria = 0;          ///< [1]
  long dataset_three_circle_states = 0; ///< [1] equilibria of the data set meeting the criterion
  /// [1] smallest relative RMS of a data-set equilibrium whose fit meets the
  /// share and plane-angle parts of the criterion (how close the data set's
  /// non-coplanar states come to three circles; null: none)
  std::optional<double> dataset_min_relative_rms;
  std::string dataset_min_relative_rms_knot;  ///< its knot type ("" when null)
  double dataset_max_similarity = 0.0;  ///< [1] largest similarity of a data-set equilibrium to the pattern
  std::string dataset_max_similarity_knot;
  std::vector<GeneralizationHit> search;       ///< the closest equilibria of the data set
  std::vector<std::string> search_knot_types;  ///< their knot types, in rank order, once each
  std::vector<GeneralizationMember> members;
};
EK_JSON_FIELDS(GeneralizationSummary, scale, max_relative_rms, min_share, min_plane_angle, pattern, dataset,
               dataset_equilibria, dataset_three_circle_states, dataset_min_relative_rms,
               dataset_min_relative_rms_knot, dataset_max_similarity, dataset_max_similarity_knot,
               search, search_knot_types, members)

}  // namespace ek::results
