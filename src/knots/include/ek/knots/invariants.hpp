#pragma once
/// \file
/// Invariants of a table knot and of a curve, as `knots info` and `knots
/// invariants` report them (and the Python module's knot() and invariants()).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "ek/geometry/link.hpp"
#include "ek/geometry/polyline.hpp"
#include "ek/geometry/types.hpp"
#include "ek/knots/conway.hpp"
#include "ek/knots/polynomial.hpp"
#include "ek/knots/table.hpp"

namespace ek {

/// The Alexander polynomial of a table knot: from its PD code, cross-checked
/// with its braid word when the table lists one (the unknot: 1). Throws
/// std::runtime_error when the two disagree (a broken table row).
AlexanderPolynomial table_alexander(const KnotRecord& knot);

/// What `knots invariants` measures on a closed polygon.
struct CurveInvariants {
  int vertices = 0;                 ///< [1] n
  double length = 0.0;              ///< [length] Σ edge lengths
  AlexanderPolynomial alexander;    ///< Δ(t), normal form (polynomial.hpp)
  double writhe = 0.0;              ///< [1] Wr, exact Gauss double sum
  double total_curvature = 0.0;     ///< [rad] Σ turning angles
  Clearance clearance;              ///< [length] smallest distance of edges sharing no vertex, and the two edges
};

/// The invariants of the closed polygon P (n by 3, a simple polygon: the
/// Alexander polynomial needs a generic projection; InputError otherwise).
CurveInvariants curve_invariants(const Points& P);

/// What `knots invariants` measures on a link of m >= 2 components.
struct LinkInvariants {
  std::vector<CurveInvariants> components;  ///< each component's, in the file's order
  Eigen::MatrixXd linking;                  ///< [1] m by m, Lk(i, j) as exact Gauss sums (link.hpp), zero diagonal
  Eigen::MatrixXi linking_numbers;          ///< [1] m by m, `linking` rounded
  double linking_error = 0.0;               ///< [1] max |linking − linking_numbers|: a sanity check, ~1e-12
  double component_clearance = 0.0;         ///< [length] smallest distance between two components
  ConwayPolynomial conway;                  ///< ∇ of the whole link (conway.hpp): zero for a split link
  std::optional<int> milnor_triple;         ///< [1] |μ̄(123)| of 3 components with vanishing linking numbers
};

/// What a link keeps: its components' knot types, its linking numbers and ∇.
struct LinkType {
  std::vector<AlexanderPolynomial> alexander;  ///< per component
  Eigen::MatrixXi linking_numbers;             ///< [1] m by m
  ConwayPolynomial conway;                     ///< ∇ of the whole link (conway.hpp): zero for a split link.

  /// Same component types, linking numbers and ∇.
  bool operator==(const LinkType& o) const {
    return alexander == o.alexander && linking_numbers == o.linking_numbers && conway == o.conway;
  }
  bool operator!=(const LinkType& o) const { return !(*this == o); }  ///< Not the same link type by these invariants.
  /// "components [..], [..]; linking numbers ..; Conway [..]"
  std::string to_string() const;
};

/// The link type of polygons (validate_link; each component's projection,
/// the Gauss sums rounded, the link's projection).
LinkType link_type(const Link& link);

/// The link type of a diagram (for example link_diagram_from_pd()): each
/// component alone (component_diagram), the half signed crossings between
/// components, ∇ of the diagram.
LinkType link_type(const LinkDiagram& diagram);

/// The invariants of a link (validate_link: disjoint components, each a
/// simple polygon). Throws InputError for a link of one component (use
/// curve_invariants) and as curve_invariants does.
LinkInvariants link_invariants(const Link& link);

}  // namespace ek
