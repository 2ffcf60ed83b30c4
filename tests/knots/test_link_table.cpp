// The link table against the code's own invariants, by routes independent of
// the published values it lists: the Burau formula on each braid word and the
// Fox matrix of its closure's diagram give the listed Conway polynomial; the
// closure's diagram has the listed linking numbers (half its signed crossings
// between two components) and each component alone the listed knot type (its
// Alexander polynomial equals the knot table's); names and aliases resolve.
// (The embedded polygons: tests/embedding/test_link_embedding.cpp.)
#include <gtest/gtest.h>

#include <set>

#include "ek/core/errors.hpp"
#include "ek/knots/alexander.hpp"
#include "ek/knots/invariants.hpp"
#include "ek/knots/link_table.hpp"
#include "ek/knots/table.hpp"

using namespace ek;

TEST(LinkTable, EveryEntryHasTheInvariantsItLists) {
  const KnotTable& knots = KnotTable::global();
  std::set<std::string> names;
  for (const LinkRecord& r : link_table()) {
    const int m = r.components();
    ASSERT_GE(m, 2) << r.name;
    EXPECT_TRUE(names.insert(r.name).second) << r.name;
    EXPECT_EQ(closure_components(r.braid), m) << r.name;
    EXPECT_GE(r.braid.length(), r.crossing_number) << r.name;
    EXPECT_EQ(conway(r.braid), r.conway) << r.name << ": Burau";
    const LinkDiagram d = link_diagram_from_braid(r.braid);
    EXPECT_EQ(conway(d), r.conway) << r.name << ": the closure's diagram";
    ASSERT_EQ(r.linking_numbers.size(), static_cast<size_t>(m * m)) << r.name;
    EXPECT_EQ(linking_numbers(d), r.linking_matrix()) << r.name;
    for (int k = 0; k < m; ++k)
      EXPECT_EQ(alexander(component_diagram(d, k)), table_alexander(knots.at(r.component_types[static_cast<size_t>(k)])))
          << r.name << " component " << k + 1;
  }
  EXPECT_GE(link_table().size(), 7u);
}

TEST(LinkTable, NamesAliasesAndTheBorromeanRingsMilnorNumber) {
  ASSERT_NE(find_link("borromean"), nullptr);
  EXPECT_EQ(find_link("L6a4"), find_link("borromean"));
  EXPECT_EQ(find_link("L2a1"), find_link("hopf"));
  EXPECT_EQ(find_link("3_1"), nullptr);  // a knot, not a link
  EXPECT_EQ(find_link("nonsense"), nullptr);
  EXPECT_EQ(find_link("borromean")->milnor_triple(), 1);
  EXPECT_FALSE(find_link("t3_3")->milnor_triple());  // linking numbers 1: not defined
  EXPECT_EQ(find_link("trefoil_hopf")->component_types, (std::vector<std::string>{"3_1", "0_1"}));
}

TEST(LinkTable, ComponentDiagramOfAKnotIsTheKnot) {
  // One component: the link diagram of a knot's braid is the knot's diagram.
  const BraidWord trefoil{2, {1, 1, 1}};
  const LinkDiagram d = link_diagram_from_braid(trefoil);
  ASSERT_EQ(d.components.size(), 1u);
  EXPECT_EQ(alexander(component_diagram(d, 0)).to_string(), "[1, -1, 1]");
  EXPECT_EQ(linking_numbers(d), Eigen::MatrixXi::Zero(1, 1));
}

// The PD codes of the table's links (of their braids' closures) read back
// with the same components and orientations, and their diagrams have the
// listed link type: components' knot types, linking numbers and ∇.
TEST(LinkTable, PDCodesHaveTheListedInvariants) {
  const KnotTable& knots = KnotTable::global();
  for (const LinkRecord& r : link_table()) {
    const PDLinkCode pd = r.pd();
    const PDLinkCode back = parse_pd_link(to_string(pd.code));
    EXPECT_EQ(back.components, pd.components) << r.name;
    EXPECT_EQ(back.over_in, pd.over_in) << r.name;
    ASSERT_EQ(static_cast<int>(back.components.size()), r.components()) << r.name;
    EXPECT_EQ(back.code.size(), r.braid.length()) << r.name;
    const LinkType t = link_type(link_diagram_from_pd(back));
    EXPECT_EQ(t.conway, r.conway) << r.name;
    EXPECT_EQ(t.linking_numbers, r.linking_matrix()) << r.name;
    for (int k = 0; k < r.components(); ++k)
      EXPECT_EQ(t.alexander[static_cast<size_t>(k)], table_alexander(knots.at(r.component_types[static_cast<size_t>(k)])))
          << r.name << " component " << k + 1;
  }
}

// A knot's braid gives a PD code of one component whose Alexander polynomial
// is the knot's; a braid with an untouched strand has none.
TEST(LinkTable, PDCodeOfABraidClosure) {
  const PDLinkCode t = pd_from_braid(BraidWord{2, {1, 1, 1}});
  ASSERT_EQ(t.components.size(), 1u);
  EXPECT_EQ(alexander(parse_pd(to_string(t.code))).to_string(), "[1, -1, 1]");
  EXPECT_THROW(pd_from_braid(BraidWord{3, {1, 1}}), InputError);
}
