#pragma once
/// \file
/// Initial 3D embeddings of a knot type (paper Sections 5 and 8.3, Fig.\ 13):
/// simple closed polygons with a requested number of vertices and equal edge
/// lengths, built from a braid word or a PD code of the table.
#include <optional>
#include <string>

#include "ek/geometry/link.hpp"
#include "ek/geometry/types.hpp"
#include "ek/knots/codes.hpp"
#include "ek/knots/polynomial.hpp"
#include "ek/knots/table.hpp"

namespace ek {

/// How embed_braid() lays out a closed braid.
enum class BraidStyle {
  /// Strand positions side by side in the plane z = 0 around a core circle
  /// (a flat coil; with a small strand_spacing, a multi-covered circle).
  Coil,
  /// Strand positions stacked along the z axis on the cylinder r = R, one
  /// letter slot's arc 2πR/L apart: the multi-covered-circle start of the
  /// paper's public code (its example 12n_838-braid.obj), a tall 3D start of
  /// height (s − 1)·2πR/L.
  Cylinder,
};
std::string to_string(BraidStyle style);            ///< "coil", "cylinder"
BraidStyle parse_braid_style(const std::string& text);  ///< "coil" | "cylinder"; InputError otherwise

/// Options shared by the embeddings. Lengths are in units of the output's
/// edge length unless stated.
struct EmbeddingOptions {
  int vertices = 400;          ///< [1] vertex count n of the output polygon (>= 4)
  double edge_length = 1.0;    ///< [length] common edge length of the output polygon
  BraidStyle braid_style = BraidStyle::Coil;  ///< braid closure: coil or cylinder
  /// Braid closure: distance between neighbouring strand positions, in units
  /// of the coil radius R (radial for the coil, axial for the cylinder);
  /// unset: for L letters on s strands, min(0.5 · 2π/L, 0.6/s) for the coil
  /// (a well separated coil; small values give a multi-covered circle) and
  /// 2π/L for the cylinder (one letter slot's arc).
  std::optional<double> strand_spacing;  ///< [R] > 0
  /// Braid coil: height of the over/under offsets at a crossing, in units of
  /// the strand spacing.
  double crossing_height = 0.5;  ///< [strand spacing]
  /// Braid cylinder: radial offset of the two strands at a crossing (the over
  /// strand inwards, the under strand outwards), in output edge lengths. The
  /// default is a little more than the default wire radius r = 0.2, so the
  /// crossing strands start just outside the contact distance d̂ = 2r, as in
  /// the paper's public start (±0.207 at r = 0.2).
  double cylinder_crossing_offset = 0.21;  ///< [edge length]
  /// Braid closure: turn of every cross-section about the core circle
  /// (r, z) = (R, 0); 0 is the flat coil, π/2 stacks the strands along the
  /// axis on the cylinder r = R (a tall, 3D start). Any value is an isotopy of
  /// the coil (same knot type and chirality).
  double braid_tilt = 0.0;  ///< [rad] finite; coil only
  int samples_per_letter = 32;   ///< [1] dense samples per braid letter before resampling
  /// PD drawing: height of the over/under offsets at a crossing, in units of
  /// the shortest straight piece (crossing to edge midpoint) of the drawing.
  double pd_crossing_height = 0.3;  ///< [shortest piece]
  /// PD drawing: lower bound of the crossing height in output edge lengths.
  double pd_min_crossing_height = 1.0;  ///< [edge length]
  int samples_per_piece = 4;        ///< [1] dense samples per piece of the smoothed drawing before resampling
  /// PD drawing: rounds of Tutte re-solves with every edge reweighted by its
  /// current length (0 = plain uniform Tutte embedding). With `verify`, other
  /// round counts are tried if this one does not survive the resampling.
  int pd_reweighting_rounds = 2;    ///< [1]
  /// Check the result's Alexander polynomial against the code's (throws
  /// InputError when the resampling was too coarse for the embedding).
  bool verify = true;
};

/// How an embedding was drawn: from a braid word (embed_braid()), a PD code
/// (embed_pd()), or as a circle (the unknot).
enum class EmbeddingMethod { Braid, PD, Circle };
std::string to_string(EmbeddingMethod method);  ///< "braid", "pd", "circle"

/// An embedding and what was measured on it.
struct Embedding {
  Points points;             ///< n by 3, edge i joins vertex i to i + 1 (cyclic)
  double edge_length = 0.0;  ///< [length] common edge length
  double max_edge_deviation = 0.0;  ///< [length] max | |e_i| - edge_length |
  double clearance = 0.0;    ///< [length] smallest distance between non-adjacent edges
  EmbeddingMethod method = EmbeddingMethod::Braid;  ///< what it was drawn from
  /// The polygon's Alexander polynomial, checked against the code's (set
  /// when EmbeddingOptions::verify).
  std::optional<AlexanderPolynomial> alexander;
};

/// Closed braid as a coil around the z axis (Scharein 1998; paper Fig.\ 13):
/// strand position k (1..s) runs on the circle of radius R + (k - (s+1)/2)·δ
/// in the plane z = 0; letter j occupies the angular slot [2πj/L, 2π(j+1)/L],
/// where strands at positions i and i+1 exchange radii (smoothstep) while the
/// over strand rises to +h and the under strand dips to -h (h = crossing_height·δ).
/// σ_i (letter +i): the strand coming from position i passes over, a positive
/// crossing seen from +z. With a small strand_spacing this is the paper's
/// multi-covered circle initialisation.
/// braid_tilt = α turns every cross-section by α about the core circle: the
/// coil's offsets (radial a, height b) become (a cos α - b sin α, a sin α +
/// b cos α). This is an isotopy of the solid torus, so the knot type and its
/// chirality are kept. At α = π/2 position k lies at height (k - (s+1)/2)·δ on
/// the cylinder r = R, and the over strand of a crossing moves inwards to
/// R - h, the under strand outwards to R + h.
///
/// BraidStyle::Cylinder is that tilted layout with the paper's public
/// code's proportions: position k at height z = (k - (s+1)/2)·δ with
/// δ = 2πR/L (one letter slot's arc), the two strands of a letter exchanging
/// heights along the cosine step (1 - cos πu)/2 of the slot (u in [0, 1]),
/// and the over strand at radius R - h·sin πu, the under strand at
/// R + h·sin πu, h = cylinder_crossing_offset. Its height is (s - 1)·2πR/L
/// (12n_838: 5 strands, 12 letters, 2.09 R). The same knot type and
/// chirality as the coil (an isotopy of it).
///
/// The output has options.vertices equal edges of options.edge_length
/// (the dense curve resampled by arc length).
Embedding embed_braid(const BraidWord& word, const EmbeddingOptions& options = {});

/// A link's embedding: one closed polygon per component.
struct LinkEmbedding {
  Link components;           ///< one n_c by 3 polygon per cycle of the braid's permutation, in order of their first position
  double edge_length = 0.0;  ///< [length] the mean edge length (options.edge_length)
  double max_edge_deviation = 0.0;  ///< [length] max | |e_i| − edge_length | over all components
  Eigen::MatrixXi linking_numbers;  ///< [1] m by m, from the braid word (half the signed letters between two components)
};

/// The closure of a braid word of any number of components, laid out as
/// embed_braid() lays out a knot (coil or cylinder; the same options): one
/// component per cycle of the word's permutation, starting at its lowest
/// position; about options.vertices vertices in all, shared by the
/// components in proportion to their lengths, every component's edges
/// equal and the components scaled together so that their mean edge is
/// options.edge_length. With options.verify the linking numbers of the
/// polygons (link.hpp) are checked against the word's. Throws InputError
/// when the components touch or the check fails (use more vertices).
LinkEmbedding embed_braid_link(const BraidWord& word, const EmbeddingOptions& options = {});

/// PD code realised from a planar straight-line drawing: the 4-valent plane
/// graph of the diagram (faces traced from the PD's counterclockwise rotation
/// system) is subdivided by a node per edge midpoint and a node per face joined
/// to the face's corners, which triangulates it; its Tutte embedding (uniform
/// weights, the largest face's boundary pinned to a circle) gives straight-line
/// positions, after a few rounds of reweighting each edge by its length to
/// undo the crowding of uniform weights. The knot runs crossing -> edge midpoint -> crossing, lifted to
/// ±h at crossings (over/under) and 0 at midpoints, its corners rounded by
/// three rounds of Chaikin corner cutting. Throws InputError for a
/// code whose diagram is not planar or has a nugatory crossing.
Embedding embed_pd(const PDCode& pd, const EmbeddingOptions& options = {});

/// A link's PD code (parse_pd_link, at least 2 components) drawn as
/// embed_pd() draws a knot's: one Tutte layout of the diagram, each
/// component traced through its labels, then finished as embed_braid_link()
/// finishes a braid (vertices shared by length, equal edges, one scale).
/// With options.verify the polygons' link type (components' Alexander
/// polynomials, linking numbers, ∇) must equal the code's, and the best of a
/// few reweighting rounds by the components' clearance is kept. Throws
/// InputError for a code of one component, a non-planar or split diagram,
/// and when no drawing keeps the link type (use more vertices).
LinkEmbedding embed_pd_link(const PDLinkCode& pd, const EmbeddingOptions& options = {});

/// Which code an embedding of a table knot is built from: Braid, the table's
/// braid word (embed_braid()), or PD, its PD code (embed_pd()).
enum class EmbeddingSource { Braid, PD };
EmbeddingSource parse_embedding_source(const std::string& text);  ///< "braid" | "pd"; InputError otherwise

/// Embedding of a table knot. The unknot is a circle. Throws InputError when
/// the table has no code of the requested kind.
Embedding embed_knot(const KnotRecord& knot, EmbeddingSource source, const EmbeddingOptions& options = {});

}  // namespace ek
