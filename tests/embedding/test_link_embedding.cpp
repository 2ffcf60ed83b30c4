// Braid closures of several components (embed_braid_link): one component
// per cycle of the permutation, every linking number of the polygons equal
// to the word's (half its signed letters between two components) on the
// Hopf link σ1², the (2, 4) torus link σ1⁴, the (3, 3) torus link (σ1σ2)³
// and the Borromean rings (σ1σ2⁻¹)³; every component of these an unknot; a
// knot's word gives one component of the knot's type; equal edges within
// each component, the mean edge as asked; both layouts.
#include <gtest/gtest.h>

#include "ek/core/errors.hpp"
#include "ek/embedding/embedding.hpp"
#include "ek/geometry/link.hpp"
#include "ek/geometry/polyline.hpp"
#include "ek/knots/alexander.hpp"
#include "ek/knots/invariants.hpp"
#include "ek/knots/link_table.hpp"
#include "ek/knots/table.hpp"

using namespace ek;

namespace {

BraidWord word(int strands, std::vector<int> letters) { return BraidWord{strands, std::move(letters)}; }

Eigen::MatrixXi rounded_linking(const Link& link) { return linking_matrix(link).array().round().cast<int>(); }

}  // namespace

TEST(LinkEmbedding, LinkingNumbersAreTheWords) {
  struct Case {
    const char* name;
    BraidWord word;
    int components;
    int lk01;  ///< the word's Lk(0, 1)
  };
  for (const Case& c : {Case{"Hopf", word(2, {1, 1}), 2, 1}, Case{"T(2,4)", word(2, {1, 1, 1, 1}), 2, 2},
                        Case{"T(2,4) mirror", word(2, {-1, -1, -1, -1}), 2, -2},
                        Case{"T(3,3)", word(3, {1, 2, 1, 2, 1, 2}), 3, 1},
                        Case{"Borromean", word(3, {1, -2, 1, -2, 1, -2}), 3, 0}})
    for (const BraidStyle style : {BraidStyle::Coil, BraidStyle::Cylinder}) {
      EmbeddingOptions o;
      o.vertices = 300;
      o.braid_style = style;
      const LinkEmbedding e = embed_braid_link(c.word, o);
      ASSERT_EQ(static_cast<int>(e.components.size()), c.components) << c.name;
      EXPECT_EQ(e.linking_numbers(0, 1), c.lk01) << c.name;
      EXPECT_EQ(rounded_linking(e.components), e.linking_numbers) << c.name << " " << to_string(style);
      int vertices = 0;
      double mean = 0.0;
      for (const Points& P : e.components) {
        EXPECT_EQ(alexander(P).to_string(), "[1]") << c.name;
        const VecX edges = edge_lengths(P);
        EXPECT_LT(edges.maxCoeff() - edges.minCoeff(), 1e-9) << c.name;  // equal within a component
        vertices += static_cast<int>(P.rows());
        mean += edges.sum();
      }
      EXPECT_NEAR(mean / vertices, 1.0, 0.02) << c.name;
      EXPECT_NEAR(vertices, 300, c.components) << c.name;
    }
  // the Borromean rings: every pair unlinked, yet 3 components
  const LinkEmbedding b = embed_braid_link(word(3, {1, -2, 1, -2, 1, -2}));
  EXPECT_EQ(b.linking_numbers, Eigen::MatrixXi::Zero(3, 3));
}

TEST(LinkEmbedding, AKnotsWordGivesOneComponentOfItsType) {
  const BraidWord trefoil = word(2, {1, 1, 1});
  const LinkEmbedding e = embed_braid_link(trefoil);
  ASSERT_EQ(e.components.size(), 1u);
  EXPECT_EQ(alexander(e.components[0]), alexander(trefoil));
}

// Every link of the link table embedded from its braid word, as the coil and
// on the cylinder: the polygons' components have the listed knot types, their
// Gauss sums the listed linking numbers, the projected link the listed Conway
// polynomial and |μ̄(123)| (tests/knots/test_link_table.cpp checks the same
// values on the word and its diagram).
TEST(LinkEmbedding, TableLinksHaveTheirListedInvariants) {
  const KnotTable& knots = KnotTable::global();
  for (const LinkRecord& r : link_table())
    for (const BraidStyle style : {BraidStyle::Coil, BraidStyle::Cylinder}) {
      EmbeddingOptions o;
      o.vertices = 100 * r.components();
      o.braid_style = style;
      const LinkEmbedding e = embed_braid_link(r.braid, o);
      const LinkInvariants inv = link_invariants(e.components);
      const std::string at = r.name + " " + to_string(style);
      ASSERT_EQ(static_cast<int>(inv.components.size()), r.components()) << at;
      for (int k = 0; k < r.components(); ++k)
        EXPECT_EQ(inv.components[static_cast<size_t>(k)].alexander,
                  table_alexander(knots.at(r.component_types[static_cast<size_t>(k)])))
            << at << " component " << k + 1;
      EXPECT_EQ(inv.linking_numbers, r.linking_matrix()) << at;
      EXPECT_EQ(inv.conway, r.conway) << at;
      EXPECT_EQ(inv.milnor_triple, r.milnor_triple()) << at;
    }
}

// Every link of the link table drawn from its PD code (the planar drawing):
// the polygons have the listed link type (embed_pd_link checks it with
// verify; checked again here from the invariants of the polygons).
TEST(LinkEmbedding, TableLinksFromTheirPDCodes) {
  for (const LinkRecord& r : link_table()) {
    EmbeddingOptions o;
    o.vertices = 120 * r.components();
    const LinkEmbedding e = embed_pd_link(r.pd(), o);
    const LinkInvariants inv = link_invariants(e.components);
    ASSERT_EQ(static_cast<int>(inv.components.size()), r.components()) << r.name;
    EXPECT_EQ(inv.linking_numbers, r.linking_matrix()) << r.name;
    EXPECT_EQ(inv.conway, r.conway) << r.name;
    EXPECT_EQ(inv.milnor_triple, r.milnor_triple()) << r.name;
  }
  // LinkInfo's code of the Hopf link
  const LinkEmbedding h = embed_pd_link(parse_pd_link("[[4;1;3;2];[2;3;1;4]]"));
  EXPECT_EQ(link_invariants(h.components).conway.coefficients, (std::vector<std::int64_t>{0, 1}));
  EXPECT_THROW(embed_pd_link(parse_pd_link("[[1;5;2;4];[3;1;4;6];[5;3;6;2]]")), InputError);  // a knot
}
