#pragma once
/// \file
/// The Conway polynomial of knots and links, and Milnor's triple linking
/// number of three-component links with vanishing linking numbers: the
/// invariants that tell a link from the unlink when the components and the
/// linking numbers do not (the Whitehead link, the Borromean rings).
///
/// The one-variable Alexander polynomial of a link diagram is the first
/// elementary ideal of its Fox matrix with every meridian sent to t (Fox;
/// Rolfsen, Knots and Links, 7.B): for a diagram with c crossings and a arcs,
/// each row is a crossing as in alexander(GaussDiagram); a = c + z, z the
/// components without an under-crossing. Since every row sums to zero, a
/// vanishing (a−1)-minor is forced when z >= 2 (the link is split), the
/// minor deleting one column when z = 1, and the one deleting the last row
/// and column when z = 0. This is Conway's normalisation up to ±t^k:
/// Δ_L(t) ≐ ∇_L(t^{1/2} − t^{−1/2}), the Hopf link's Δ = t − 1, ∇ = z.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "ek/geometry/link.hpp"
#include "ek/knots/codes.hpp"
#include "ek/knots/diagram.hpp"
#include "ek/knots/polynomial.hpp"

namespace ek {

/// ∇(z) = Σ_k c_k z^k, coefficients c_0, c_1, ... (lowest degree first); the
/// zero polynomial (a split link) has none. A knot's has only even powers
/// and c_0 = 1; a link of m components has only powers m−1, m+1, ...
/// (Hoste), and its overall sign, which the Alexander polynomial does not
/// fix, is chosen so that the lowest nonzero coefficient is positive.
/// Examples: 3_1 [1, 0, 1]; the Hopf link [0, 1]; the Whitehead link
/// [0, 0, 0, 1]; the Borromean rings [0, 0, 0, 0, 1]; a split link [].
struct ConwayPolynomial {
  std::vector<std::int64_t> coefficients;  ///< c_0, c_1, ... (lowest degree first); empty for the zero polynomial.

  bool zero() const { return coefficients.empty(); }  ///< Whether ∇ = 0 (a split link).
  /// "[0, 1]", "[]" for zero.
  std::string to_string() const;
  /// Equal coefficient lists.
  bool operator==(const ConwayPolynomial& o) const { return coefficients == o.coefficients; }
  bool operator!=(const ConwayPolynomial& o) const { return !(*this == o); }  ///< Different coefficient lists.
};

/// ∇ from a one-variable Alexander polynomial given up to ±t^k (Laurent
/// coefficients, lowest first; empty or all zero for 0) of a link of
/// `components` >= 1 components: t^{-D/2}·Δ(t) written in powers of
/// z² = t − 2 + t^{-1}, after dividing by (t − 1) = t^{1/2}·z when the
/// degree span D is odd. Throws std::logic_error when Δ is not of a link
/// of that many components (not (anti)symmetric, or of the wrong parity).
ConwayPolynomial conway_from_alexander(std::vector<std::int64_t> delta, int components);

/// The one-variable Alexander polynomial of a link diagram by the Fox matrix
/// (file comment): Laurent coefficients up to ±t^k, empty when it vanishes.
std::vector<std::int64_t> alexander_coefficients(const LinkDiagram& diagram);

/// ∇ of a link diagram (via alexander_coefficients(LinkDiagram)).
ConwayPolynomial conway(const LinkDiagram& diagram);

/// ∇ of a link or knot given as curves (link_diagram_from_curves()).
ConwayPolynomial conway(const Link& link, const ProjectionOptions& options = {});

/// ∇ of a braid's closure by the Burau formula (alexander_coefficients of
/// the braid), independently of the diagram route.
ConwayPolynomial conway(const BraidWord& braid);

/// |μ̄(123)|, Milnor's triple linking number up to sign, of a link of three
/// components whose linking numbers all vanish: c_4(L) = μ̄(123)² (Levine;
/// Masbaum and Vaintrob, "Milnor numbers, spanning trees, and the
/// Alexander-Conway polynomial", 2002). 1 for the Borromean rings, 0 for the
/// unlink. Nothing for other links (`linking` is the m by m matrix of
/// linking numbers). Throws std::logic_error when c_4 is not a square.
std::optional<int> milnor_triple_linking(const ConwayPolynomial& conway, const Eigen::MatrixXi& linking);

/// Hoste's formula for the lowest possible coefficient c_{m−1} of an
/// m-component link: the determinant of the m by m matrix Λ with
/// Λ_ij = −Lk(i, j) (i ≠ j) and Λ_ii = Σ_{k≠i} Lk(i, k), with one row and
/// column removed (the Hopf link: 1; the (3,3) torus link: 3). An
/// independent check of ∇ from the linking numbers alone.
std::int64_t hoste_coefficient(const Eigen::MatrixXi& linking);

}  // namespace ek
