#pragma once
/// \file
/// A small table of links (several components), the counterpart of the
/// knot table for links: each entry a braid word whose closure is the link
/// (one component per cycle of its permutation, closure_cycles() order) and
/// the invariants published for it, which the tests recompute by the code's
/// own routes (tests/knots/test_link_table.cpp: the Burau formula, the
/// closure's diagram, and the embedded polygons).
///
/// Names are lower-case words ("hopf", "whitehead", "borromean") or torus
/// links "t2_4" (T(2, 4)); the Thistlethwaite names of LinkInfo ("L2a1",
/// "L4a1", "L5a1", "L6a4") are accepted as aliases where given.
#include <optional>
#include <string>
#include <vector>

#include "ek/knots/codes.hpp"
#include "ek/knots/conway.hpp"

namespace ek {

/// One link type.
struct LinkRecord {
  std::string name;                          ///< "borromean"
  std::vector<std::string> aliases;          ///< other accepted names: "L6a4"
  std::string description;                   ///< "the Borromean rings"
  int crossing_number = 0;                   ///< [1] of the link type
  BraidWord braid;                           ///< its closure is the link
  std::vector<std::string> component_types;  ///< each component's knot type (knot table names), closure_cycles() order
  std::vector<int> linking_numbers;          ///< [1] m by m, row by row, zero diagonal (with the braid's orientation)
  ConwayPolynomial conway;                   ///< published ∇, sign as ConwayPolynomial fixes it

  int components() const { return static_cast<int>(component_types.size()); }  ///< m, the number of components.
  /// `linking_numbers` as the m by m matrix.
  Eigen::MatrixXi linking_matrix() const;
  /// |μ̄(123)| when defined (three components, vanishing linking numbers).
  std::optional<int> milnor_triple() const;
  /// The PD code of the braid's closure (pd_from_braid(), LinkInfo's
  /// labelling convention); the tests check its link type against the
  /// entry's.
  PDLinkCode pd() const;
};

/// Every entry, in order of crossing number.
const std::vector<LinkRecord>& link_table();

/// The entry named `name` or carrying it as an alias (case-sensitive);
/// nullptr when there is none.
const LinkRecord* find_link(const std::string& name);

}  // namespace ek
