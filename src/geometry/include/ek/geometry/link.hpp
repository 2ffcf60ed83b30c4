#pragma once
/// \file
/// Links: several closed polygons (components) at once (paper Section 8.5:
/// "intertwined combinations of several knots").
///
/// A link is a `Link`, one `Points` array (n_c by 3, a closed polygon) per
/// component; a knot is a link of one component.
///
/// Files (chosen by the extension, as curve_io.hpp):
///  - .obj: "v x y z" lines and "l i j ..." polyline lines (1-based); the
///    l-elements form one cycle per component (an open chain is closed by
///    joining its ends). Components are ordered by their lowest-numbered
///    vertex; each starts there and runs along its first listed l-element
///    edge. Without l lines the vertices form one component.
///  - .txt: one "x y z" per line; a blank line ends a component. Lines
///    starting with '#' are ignored, as are blank lines before the first and
///    after the last vertex, and repeated blank lines.
/// A file of one component reads exactly as read_curve() reads it.
#include <string>
#include <vector>

#include "ek/geometry/types.hpp"

namespace ek {

using Link = std::vector<Points>;  ///< One closed polygon (n_c by 3) per component.

/// Parses link text ("obj" or "txt"); `source` names the input in messages.
/// Every component is validated (validate_closed_curve) and the link too
/// (validate_link). Throws InputError naming the source and the problem.
Link parse_link(const std::string& text, const std::string& format, const std::string& source);

/// Reads a link (.obj or .txt). Throws InputError on any problem.
Link read_link(const std::string& path);

/// Writes a link atomically: .obj with one closed "l" loop per component,
/// .txt with a blank line between components; 17 significant digits (an
/// exact round trip). A one-component link is written as write_curve().
void write_link(const std::string& path, const Link& link);

/// Checks a link: at least one component, each a usable closed polygon
/// (validate_closed_curve), and no two components touching (their smallest
/// segment distance above 1e-9 times the link's bounding-box diagonal).
/// Throws InputError naming `source`, the components and their distance.
/// Returns the smallest distance between two components [length]
/// (+infinity for one component).
double validate_link(const Link& link, const std::string& source);

/// Every component's vertices, one component after another (N by 3, N the
/// vertices in all).
Points all_vertices(const Link& link);

/// [length] The components' mean length (1/m) Σ_c curve_length(x_c); 0 for
/// no component.
double mean_component_length(const Link& link);

/// Smallest distance between a segment of polygon A and one of polygon B
/// (n_A by 3, n_B by 3, both closed). O(n_A·n_B).
double component_distance(const Points& A, const Points& B);

/// The linking number of two disjoint closed polygons A and B as the exact
/// Gauss double integral
///   Lk(A, B) = (1/4π) ∮_A ∮_B (r_A − r_B)·(dr_A × dr_B) / |r_A − r_B|³
///            = Σ_{i ∈ A} Σ_{j ∈ B} Ω_ij / (4π),
/// Ω_ij the signed solid angle of segment pair (i, j) (segment_pair_writhe,
/// writhe.hpp). An integer up to rounding for disjoint polygons; symmetric;
/// the sign flips with the orientation of either component. Its sign: +1
/// for B passing once through a disc bounded by A in the direction of A's
/// right-hand normal.
double linking_number(const Points& A, const Points& B);

/// The m by m matrix of linking numbers (exact sums, not rounded) of the
/// link's m components; zero diagonal.
Eigen::MatrixXd linking_matrix(const Link& link);

}  // namespace ek
