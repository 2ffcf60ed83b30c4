// BFACF on several polygons (a link) and the lattice samples of table links:
// a lattice Hopf link of two 8-site rings walks 2·10⁵ moves keeping both
// polygons self-avoiding, disjoint and linked once; moves drawn on one
// component leave the others as they were; no component shrinks below the
// square; one polygon given as a list walks exactly as given alone;
// touching components are bad input; the Borromean rings and the Whitehead
// link rounded onto the lattice keep their link type (components, linking
// numbers, Conway polynomial) and their samples have the target lengths and
// the link type.
#include <gtest/gtest.h>

#include <cmath>

#include "ek/core/errors.hpp"
#include "ek/geometry/link.hpp"
#include "ek/knots/link_table.hpp"
#include "ek/lattice/bfacf.hpp"
#include "ek/lattice/link_sampling.hpp"
#include "testing.hpp"

using namespace ek;

namespace {

LatticePoints sites(std::initializer_list<std::array<int, 3>> list) { return fixtures::rows3<LatticePoints>(list); }

/// A ring around (1, 1, 0) in the plane z = 0, and one in the plane y = 1
/// through that hole and around the ring's side x = 2.
std::vector<LatticePoints> lattice_hopf() {
  return {sites({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {2, 2, 0}, {1, 2, 0}, {0, 2, 0}, {0, 1, 0}}),
          sites({{1, 1, 1}, {1, 1, 0}, {1, 1, -1}, {2, 1, -1}, {3, 1, -1}, {3, 1, 0}, {3, 1, 1}, {2, 1, 1}})};
}

int lk(const std::vector<LatticePoints>& link) {
  return static_cast<int>(std::lround(linking_number(to_points(link[0]), to_points(link[1]))));
}

}  // namespace

TEST(LinkBfacf, HopfLinkStaysLinkedSelfAvoidingAndDisjoint) {
  const auto start = lattice_hopf();
  ASSERT_EQ(std::abs(lk(start)), 1);
  const int sign = lk(start);
  BfacfWalk walk(start, 7);
  ASSERT_EQ(walk.components(), 2);
  int longest = 0;
  for (int round = 0; round < 200; ++round) {
    walk.run(1000, round < 100 ? 0.3 : 0.15);
    const auto link = walk.polygons();
    for (const LatticePoints& L : link) EXPECT_TRUE(check_lattice_polygon(L).ok);
    EXPECT_GT(component_distance(to_points(link[0]), to_points(link[1])), 0.5);  // distinct sites: >= 1 apart
    ASSERT_EQ(lk(link), sign) << "round " << round;
    longest = std::max(longest, walk.length());
    EXPECT_EQ(walk.length(), walk.component_length(0) + walk.component_length(1));
  }
  EXPECT_GT(longest, 40);  // the walk did move
}

TEST(LinkBfacf, MovesOnOneComponentLeaveTheOthers) {
  BfacfWalk walk(lattice_hopf(), 3);
  const LatticePoints other = walk.polygon_of(1);
  const BfacfRunReport r = walk.run_to_length(60, 0.4, 1000000, 0);
  EXPECT_TRUE(r.reached);
  EXPECT_EQ(walk.component_length(0), 60);
  EXPECT_EQ(walk.polygon_of(1), other);
  EXPECT_TRUE(walk.run_to_length(8, 0.1, 1000000, 0).reached);
  EXPECT_EQ(walk.polygon_of(1), other);
  EXPECT_EQ(std::abs(lk(walk.polygons())), 1);
}

TEST(LinkBfacf, NoComponentShrinksBelowTheSquare) {
  // two squares far apart: at a small fugacity only corner flips remain
  const LatticePoints a = sites({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
  LatticePoints b = a;
  b.col(0).array() += 10;
  BfacfWalk walk(std::vector<LatticePoints>{a, b}, 5);
  walk.run(20000, 0.05);
  EXPECT_GE(walk.component_length(0), 4);
  EXPECT_GE(walk.component_length(1), 4);
}

TEST(LinkBfacf, OnePolygonAsAListWalksAsAlone) {
  const LatticePoints ring = lattice_hopf()[0];
  BfacfWalk alone(ring, 11), listed(std::vector<LatticePoints>{ring}, 11);
  alone.run(50000, 0.25);
  listed.run(50000, 0.25);
  EXPECT_EQ(alone.polygon(), listed.polygon());
}

TEST(LinkBfacf, TouchingComponentsAreBadInput) {
  auto link = lattice_hopf();
  link[1].row(0) << 0, 0, 0;  // a site of the other ring (and no longer a lattice polygon either)
  EXPECT_THROW(BfacfWalk(link, 1), InputError);
  link = lattice_hopf();
  link.push_back(link[0]);
  EXPECT_THROW(BfacfWalk(link, 1), InputError);
}

TEST(LinkSampling, TableLinksKeepTheirTypeOnTheLattice) {
  for (const char* name : {"borromean", "whitehead"}) {
    const LinkRecord& record = *find_link(name);
    const LatticeLinkStart start = lattice_link_start(record);
    ASSERT_EQ(static_cast<int>(start.components.size()), record.components()) << name;
    EXPECT_EQ(start.type.conway, record.conway) << name;
    EXPECT_GT(start.scale, 0.0) << name;
    SampleOptions o;
    o.vertices = 100 * record.components();
    o.count = 3;
    o.growth_factor = 4.0;
    const LinkSampleBatch batch = sample_lattice_link(start.components, o, start.type, name);
    ASSERT_EQ(batch.samples.size(), 3u) << name;
    for (const auto& sample : batch.samples) {
      for (size_t c = 0; c < sample.size(); ++c) {
        EXPECT_EQ(sample[c].rows(), batch.component_vertices[c]) << name;
        EXPECT_TRUE(check_lattice_polygon(sample[c]).ok) << name;
      }
      EXPECT_EQ(link_type(to_link(sample)), start.type) << name;  // also checked inside, independently here
    }
    EXPECT_NE(batch.samples[0], batch.samples[1]) << name;
  }
}
