// Links (several closed polygons): linking numbers on links with known
// answers (the Hopf link with its sign convention, the (2, 2k) torus links,
// split rings), and the files: exact round trips, a one-component file read
// as read_curve() reads it, components ordered and oriented as documented,
// bad input named in one InputError.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include "ek/core/errors.hpp"
#include "ek/geometry/curve_io.hpp"
#include "ek/geometry/link.hpp"
#include "testing.hpp"

using namespace ek;
using ek::fixtures::expect_input_error;

namespace {

using fixtures::circle;

/// Component c (0 or 1) of the (2, 2k) torus link: the (1, k) curve
/// φ = t, θ = k·t + c·π on the torus of radii R = 2, r = 1.
Points torus_component(int k, int c, int n) {
  Points P(n, 3);
  for (int i = 0; i < n; ++i) {
    const double t = 2.0 * M_PI * i / n, theta = k * t + c * M_PI;
    P.row(i) << (2.0 + std::cos(theta)) * std::cos(t), (2.0 + std::cos(theta)) * std::sin(t), std::sin(theta);
  }
  return P;
}

std::string write_text(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

}  // namespace

// The Hopf link: A the unit circle of the xy-plane run counterclockwise
// (right-hand normal +z); B the circle of the xz-plane through A's centre.
// Run as (1 + cos t, 0, sin t), B crosses A's disc downwards (−z): Lk = −1;
// reversed, +1. Symmetric, and exact to 1e-9 with 64 vertices per circle.
TEST(Link, HopfLinkHasLinkingNumberOneWithTheRightHandSign) {
  const Points A = circle(64, Vec3::Zero(), 1.0, Vec3::UnitX(), Vec3::UnitY());
  const Points B = circle(64, Vec3::UnitX(), 1.0, Vec3::UnitX(), Vec3::UnitZ());
  EXPECT_NEAR(linking_number(A, B), -1.0, 1e-9);
  EXPECT_NEAR(linking_number(B, A), -1.0, 1e-9);
  const Points B_reversed = B.colwise().reverse();
  EXPECT_NEAR(linking_number(A, B_reversed), 1.0, 1e-9);
}

// The (2, 2k) torus link's components link k times; the mirror image
// (z → −z) links −k times; the matrix is symmetric with a zero diagonal.
TEST(Link, TorusLinksTwoTwoKLinkKTimes) {
  for (int k = 1; k <= 4; ++k) {
    const Link link{torus_component(k, 0, 60 * k), torus_component(k, 1, 60 * k)};
    const double lk = linking_number(link[0], link[1]);
    EXPECT_NEAR(std::abs(lk), k, 1e-9) << "k = " << k;
    Link mirror = link;
    for (Points& P : mirror) P.col(2) = -P.col(2);
    EXPECT_NEAR(linking_number(mirror[0], mirror[1]), -lk, 1e-9) << "k = " << k;
    const Eigen::MatrixXd L = linking_matrix(link);
    EXPECT_EQ(L(0, 0), 0.0);
    EXPECT_EQ(L(0, 1), L(1, 0));
    EXPECT_NEAR(L(0, 1), lk, 1e-12);
  }
}

// Two rings side by side, and a ring through which another passes twice
// in opposite directions (a clasp that unhooks), do not link.
TEST(Link, SplitRingsHaveLinkingNumberZero) {
  const Points A = circle(48, Vec3::Zero(), 1.0, Vec3::UnitX(), Vec3::UnitY());
  const Points far = circle(48, Vec3(3.0, 0.0, 0.0), 1.0, Vec3::UnitX(), Vec3::UnitZ());
  EXPECT_NEAR(linking_number(A, far), 0.0, 1e-12);
  // a long thin loop in the xz-plane that goes down through A's disc at
  // x = −0.5 and back up at x = +0.5: two crossings of opposite sign
  Points U(4, 3);
  U << -0.5, 0.0, 1.0, -0.5, 0.0, -1.0, 0.5, 0.0, -1.0, 0.5, 0.0, 1.0;
  EXPECT_NEAR(linking_number(A, U), 0.0, 1e-12);
  EXPECT_GT(component_distance(A, U), 0.49);
}

// Written and read back exactly in both formats; the one-component link is
// the curve file of write_curve() byte for byte, and read_link() of any
// curve file equals read_curve(). read_curve() refuses a link's .obj (its
// l-elements form several curves) and reads a link's .txt as one curve (it
// ignores blank lines, as it always has).
TEST(Link, RoundTripIsExactAndOneComponentIsACurve) {
  const Link link{torus_component(2, 0, 50), torus_component(2, 1, 37)};
  for (const char* ext : {".obj", ".txt"}) {
    const std::string path = ::testing::TempDir() + "link_roundtrip" + ext;
    write_link(path, link);
    const Link back = read_link(path);
    ASSERT_EQ(back.size(), 2u) << ext;
    EXPECT_EQ(back[0], link[0]) << ext;
    EXPECT_EQ(back[1], link[1]) << ext;
    if (std::string(ext) == ".obj") {
      EXPECT_THROW(read_curve(path), InputError) << "a link is not one curve";
    }
    const std::string one = ::testing::TempDir() + "link_one" + ext, curve = ::testing::TempDir() + "curve_one" + ext;
    write_link(one, Link{link[0]});
    write_curve(curve, link[0]);
    EXPECT_EQ(fixtures::read_bytes(one), fixtures::read_bytes(curve));
    EXPECT_EQ(read_link(curve).at(0), read_curve(curve));
    for (const std::string& p : {path, one, curve}) std::remove(p.c_str());
  }
}

// OBJ: components ordered by their lowest vertex, each starting there and
// running along its first listed edge; TXT: blank lines end components,
// leading, trailing and repeated blank lines and comments are ignored.
TEST(Link, ComponentsAreOrderedAndOrientedAsDocumented) {
  const std::string obj =
      "v 0 0 5\nv 10 0 0\nv 1 0 5\nv 11 0 0\nv 1 1 5\nv 11 1 0\nv 0 1 5\nv 10 1 0\n"
      "l 2 8 6 4 2\nl 1 3 5 7 1\n";
  const Link a = parse_link(obj, "obj", "obj-text");
  ASSERT_EQ(a.size(), 2u);
  EXPECT_EQ(a[0].row(0), Vec3(0, 0, 5).transpose());  // vertex 1 first
  EXPECT_EQ(a[0].row(1), Vec3(1, 0, 5).transpose());  // then along l 1 3
  EXPECT_EQ(a[1].row(0), Vec3(10, 0, 0).transpose());
  EXPECT_EQ(a[1].row(1), Vec3(10, 1, 0).transpose());  // along l 2 8
  const std::string txt = "\n# two squares\n0 0 5\n1 0 5\n1 1 5\n0 1 5\n\n\n10 0 0\n11 0 0\n11 1 0\n10 1 0\n\n";
  const Link b = parse_link(txt, "txt", "txt-text");
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(b[1].rows(), 4);
  EXPECT_EQ(b[1].row(3), Vec3(10, 1, 0).transpose());
  EXPECT_EQ(parse_curve(txt, "txt", "txt-text").rows(), 8);  // read_curve ignores blank lines, as before
}

// Components that cross, a component of 3 vertices and a vertex on no
// l-element are one InputError naming the source and the component.
TEST(Link, BadLinksAreInputErrors) {
  const std::string crossing = "0 0 0\n2 0 0\n2 2 0\n0 2 0\n\n1 0 -1\n1 0 1\n1 -2 1\n1 -2 -1\n";
  const std::string square = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n";
  expect_input_error([&] { (void)parse_link(crossing, "txt", "cross.txt"); }, "cross.txt: components 1 and 2 touch or cross");
  expect_input_error([&] { (void)parse_link(square + "\n5 5 5\n6 5 5\n6 6 5\n", "txt", "three.txt"); },
                     "three.txt (component 2): a closed curve needs at least 4 vertices, got 3");
  expect_input_error([&] { (void)parse_link("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 9 9 9\nl 1 2 3 4 1\n", "obj", "lone.obj"); },
                     "lone.obj: vertex 5 is on no l-element");
  const std::string path = write_text("link_cross.txt", crossing);
  expect_input_error([&] { (void)read_link(path); }, "link_cross.txt: components 1 and 2 touch or cross");
  std::remove(path.c_str());
}
