#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "ek/analysis/attributes.hpp"
#include "ek/analysis/bounding_box.hpp"
#include "ek/core/errors.hpp"
#include "ek/geometry/curve_io.hpp"
#include "ek/geometry/polyline.hpp"
#include "testing.hpp"

using namespace ek;

namespace {

/// Helix (R cos θ, R sin θ, hθ) for θ in [0, 2π·turns], m vertices (closed by the chord).
Points helix_turns(int m, double R, double h, double turns) {
  Points P(m, 3);
  for (int i = 0; i < m; ++i) {
    const double t = 2 * M_PI * turns * i / (m - 1);
    P.row(i) << R * std::cos(t), R * std::sin(t), h * t;
  }
  return P;
}

/// A closed polygon through the 8 corners of the box [0,a]x[0,b]x[0,c] (a Hamiltonian
/// cycle of the cube graph), every edge subdivided into k pieces.
Points box_polygon(double a, double b, double c, int k) {
  const int corner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 1, 1}, {1, 1, 1}, {1, 0, 1}, {0, 0, 1}};
  Points P(8 * k, 3);
  for (int v = 0; v < 8; ++v) {
    const Vec3 p(a * corner[v][0], b * corner[v][1], c * corner[v][2]);
    const Vec3 q(a * corner[(v + 1) % 8][0], b * corner[(v + 1) % 8][1], c * corner[(v + 1) % 8][2]);
    for (int s = 0; s < k; ++s) P.row(v * k + s) = (p + (q - p) * (static_cast<double>(s) / k)).transpose();
  }
  return P;
}

}  // namespace

TEST(Attributes, Circle) {
  const int n = 100;
  const double R = 3.0;
  const Points C = fixtures::rigid_copy(fixtures::circle(n, R), fixtures::random_rotation(1), Vec3(1, 2, 3), 5);
  const GeometricAttributes g = geometric_attributes(C);
  EXPECT_NEAR(g.total_curvature, 2 * M_PI, 1e-12);
  EXPECT_NEAR(g.threedim, 0.0, 1e-12);
  EXPECT_NEAR(g.sphericity, 0.0, 1e-14);
  EXPECT_NEAR(g.diameter, 2 * R, 1e-12);  // n even: antipodal vertices
  EXPECT_NEAR(g.writhe, 0.0, 1e-12);
  // |κb| = 2 tan(φ/2) with φ = 2π/n at every node
  AttributeOptions mat;
  const Attributes a = compute_attributes(C, mat);
  ASSERT_TRUE(a.physical.max_stress.has_value());
  EXPECT_NEAR(*a.physical.max_stress, mat.radius * mat.young_modulus * 2 * std::tan(M_PI / n), 1e-10);
  EXPECT_FALSE(a.physical.energy.has_value());
  EXPECT_FALSE(a.physical.stiffness.has_value());
}

TEST(Attributes, Ellipse) {
  const int n = 256;
  const double a = 2.0, b = 0.8;
  const Points E = fixtures::rigid_copy(fixtures::ellipse(n, a, b), fixtures::random_rotation(2), Vec3(-1, 0, 4), 9);
  const GeometricAttributes g = geometric_attributes(E);
  EXPECT_NEAR(g.total_curvature, 2 * M_PI, 1e-12);  // convex planar
  EXPECT_NEAR(g.threedim, 0.0, 1e-12);
  EXPECT_NEAR(g.diameter, 2 * a, 1e-12);
  // r(t) = a sqrt(1 - e² sin² t): mean (2a/π) E(e), mean square (a² + b²)/2; uniform samples
  // of a periodic analytic function average exactly to spectral accuracy
  const double e = std::sqrt(1 - b * b / (a * a));
  const double mean = 2 * a / M_PI * std::comp_ellint_2(e);
  const double expected = std::sqrt((a * a + b * b) / 2 - mean * mean) / mean;
  EXPECT_NEAR(g.sphericity, expected, 1e-12);
  EXPECT_NEAR(g.writhe, 0.0, 1e-12);
}

TEST(Attributes, Helix) {
  const double R = 1.0, h = 0.5, turns = 4;  // height H = 2π·4·0.5 ≈ 12.6 > 2R
  const int m = 1001;
  const Points P = helix_turns(m, R, h, turns);
  const GeometricAttributes g = geometric_attributes(P);
  const double H = 2 * M_PI * turns * h;
  // bounding box: 2R x 2R x H (the vertex set reaches ±R in every direction to O(1/m²))
  EXPECT_NEAR(g.threedim, 2 * R / H, 1e-3 * 2 * R / H);
  // sphericity: d(z) = sqrt(R² + (z - H/2)²) with z uniform on [0, H] (the centroid is (0, 0, H/2) for whole turns)
  auto F = [&](double u) { return 0.5 * u * std::sqrt(R * R + u * u) + 0.5 * R * R * std::asinh(u / R); };
  const double mean = (F(H / 2) - F(-H / 2)) / H;
  const double meansq = R * R + H * H / 12;
  EXPECT_NEAR(g.sphericity, std::sqrt(meansq - mean * mean) / mean, 1e-3);  // O(1/m) sampling error (measured 1.4e-4)
  // diameter: max over Δθ in [0, 2π·turns] of sqrt(2R²(1 - cos Δθ) + h²Δθ²), by a dense scan
  double best = 0.0;
  for (int k = 0; k <= 200000; ++k) {
    const double d = 2 * M_PI * turns * k / 200000;
    best = std::max(best, std::sqrt(2 * R * R * (1 - std::cos(d)) + h * h * d * d));
  }
  EXPECT_NEAR(g.diameter, best, 1e-6 * best);
  // a helix closed by its chord writhes; its mirror image has the opposite writhe
  EXPECT_GT(std::abs(g.writhe), 0.5);
  EXPECT_NEAR(geometric_attributes(fixtures::mirror_x(P)).writhe, -g.writhe, 1e-10);
}

TEST(Attributes, BoxPolygonGivesItsAspectRatio) {
  // a polygon through the corners of an a x b x c box: the minimal box is that box
  const Points B = box_polygon(4.0, 2.0, 1.0, 3);
  for (std::uint64_t seed : {1u, 2u, 3u, 4u}) {
    const Points P = fixtures::rigid_copy(B, fixtures::random_rotation(seed), Vec3(0.3, -2, 5), 0);
    const OrientedBox box = min_volume_bounding_box(P);
    EXPECT_NEAR(box.extents(0), 4.0, 1e-6) << seed;
    EXPECT_NEAR(box.extents(1), 2.0, 1e-6) << seed;
    EXPECT_NEAR(box.extents(2), 1.0, 1e-6) << seed;
    EXPECT_NEAR(threedim(P), 0.25, 1e-6) << seed;
  }
  // a cube: the PCA axes are undetermined (isotropic covariance), the minimal box is the cube
  const Points cube = box_polygon(1.0, 1.0, 1.0, 4);
  for (std::uint64_t seed : {5u, 6u, 7u}) {
    const Points P = fixtures::rigid_copy(cube, fixtures::random_rotation(seed), Vec3::Zero(), 0);
    EXPECT_NEAR(threedim(P), 1.0, 1e-6) << seed;
    EXPECT_NEAR(min_volume_bounding_box(P).volume(), 1.0, 1e-6) << seed;
  }
}

TEST(Attributes, MinimalBoxContainsThePointsAndBeatsPca) {
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    const Points P = fixtures::random_fourier_curve(150, 4, seed);
    const OrientedBox m = min_volume_bounding_box(P), p = pca_bounding_box(P);
    EXPECT_LE(m.volume(), p.volume() * (1 + 1e-12)) << seed;
    for (const OrientedBox* b : {&m, &p}) {
      EXPECT_LT((b->axes.transpose() * b->axes - Mat3::Identity()).norm(), 1e-12);
      EXPECT_NEAR(b->axes.determinant(), 1.0, 1e-12);
      EXPECT_GE(b->extents(0), b->extents(1));
      EXPECT_GE(b->extents(1), b->extents(2));
      for (Eigen::Index i = 0; i < P.rows(); ++i) {
        const Vec3 y = b->axes.transpose() * (P.row(i).transpose() - b->center);
        for (int k = 0; k < 3; ++k) EXPECT_LE(std::abs(y(k)), 0.5 * b->extents(k) + 1e-9) << seed;
      }
    }
  }
}

TEST(Attributes, MinimalBoxFromTheHullBoundaryIsTheBoxFromEveryPoint) {
  // Every box evaluation reads only the convex hull's boundary points; the
  // result must be the all-points search's to the last bit, on smooth curves,
  // a torus knot, a box polygon (coplanar points), integer lattice points
  // (many coplanar and collinear ones), a planar curve and the peer's curves.
  std::vector<Points> curves;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) curves.push_back(fixtures::random_fourier_curve(300, 4, seed));
  curves.push_back(fixtures::torus_knot(400, 2, 3));
  curves.push_back(fixtures::rigid_copy(box_polygon(4.0, 2.0, 1.0, 5), fixtures::random_rotation(2), Vec3(1, 2, 3), 0));
  curves.push_back(fixtures::random_lattice_walk(400, 11));
  curves.push_back(fixtures::ellipse(100, 3.0, 1.0));
  for (const char* name : {"4_1-smooth.obj", "12n_838-braid.obj", "9_47-cubiclattice.txt"})
    curves.push_back(read_curve(fixtures::peer_dir() + "/" + name));
  for (size_t c = 0; c < curves.size(); ++c) {
    const OrientedBox a = min_volume_bounding_box(curves[c]), b = min_volume_bounding_box_all_points(curves[c]);
    EXPECT_EQ(a.extents, b.extents) << c;
    EXPECT_EQ(a.axes, b.axes) << c;
    EXPECT_EQ(a.center, b.center) << c;
  }
}

TEST(Attributes, InvariantUnderRigidMotionAndReindexing) {
  const Points P = fixtures::torus_knot(200, 2, 3);
  const Points Q = fixtures::rigid_copy(P, fixtures::random_rotation(9), Vec3(10, -5, 2), 77);
  const Attributes a = compute_attributes(P), b = compute_attributes(Q);
  for (const std::string& name : attribute_names()) {
    const auto va = attribute_value(a, name), vb = attribute_value(b, name);
    ASSERT_EQ(va.has_value(), vb.has_value()) << name;
    if (va) {
      EXPECT_NEAR(*va, *vb, 1e-6 * std::max(1.0, std::abs(*va))) << name;  // threedim: measured 1e-8
    }
  }
  EXPECT_GT(a.geometric.threedim, 0.2);  // a genuinely 3D curve
  EXPECT_GT(a.geometric.total_curvature, 2 * M_PI * 2);  // Milnor: trefoil has bridge index 2
}

TEST(Attributes, CurvatureBinormalsAndStress) {
  const Points P = fixtures::random_fourier_curve(120, 5, 3);
  const Points KB = curvature_binormals(P);
  const VecX phi = turning_angles(P);
  const auto n = P.rows();
  for (Eigen::Index i = 0; i < n; ++i) {
    const Vec3 a = (P.row(i) - P.row((i + n - 1) % n)).transpose(), b = (P.row((i + 1) % n) - P.row(i)).transpose();
    const Vec3 kb = KB.row(i).transpose();
    EXPECT_NEAR(kb.norm(), 2 * std::tan(phi(i) / 2), 1e-12 * (1 + kb.norm()));
    EXPECT_NEAR(kb.dot(a), 0.0, 1e-12 * kb.norm() * a.norm());
    EXPECT_NEAR(kb.dot(b), 0.0, 1e-12 * kb.norm() * b.norm());
    EXPECT_GE(kb.dot(a.cross(b)), 0.0);  // along e_{i-1} × e_i
  }
  // the paper's σ = r E max|κb| is linear in r and E and (κb being dimensionless) scale-invariant
  const double s = max_bending_stress(P, 0.2, 2000.0);
  EXPECT_NEAR(max_bending_stress(P, 0.4, 2000.0), 2 * s, 1e-12 * s);
  EXPECT_NEAR(max_bending_stress(P, 0.2, 1000.0), 0.5 * s, 1e-12 * s);
  EXPECT_NEAR(max_bending_stress(Points(3.0 * P), 0.2, 2000.0), s, 1e-12 * s);
  EXPECT_THROW(max_bending_stress(P, 0.0, 2000.0), InputError);
  EXPECT_THROW(max_bending_stress(P, 0.2, -1.0), InputError);
}

TEST(Attributes, NamesAndValues) {
  const Attributes a = compute_attributes(fixtures::circle(20, 1.0));
  EXPECT_EQ(attribute_names().size(), 11u);
  EXPECT_EQ(attribute_names().front(), "total_curvature");
  EXPECT_EQ(*attribute_value(a, "diameter"), a.geometric.diameter);
  EXPECT_EQ(*attribute_value(a, "max_stress"), *a.physical.max_stress);
  EXPECT_FALSE(attribute_value(a, "energy_bend").has_value());
  EXPECT_THROW(attribute_value(a, "colour"), InputError);
}

TEST(Attributes, DiameterMatchesBruteForceAndSphericityIsScaleFree) {
  const Points P = fixtures::random_fourier_curve(300, 6, 11);
  const Diameter d = diameter(P);
  double best = 0.0;
  for (Eigen::Index i = 0; i < P.rows(); ++i)
    for (Eigen::Index j = 0; j < P.rows(); ++j) best = std::max(best, (P.row(i) - P.row(j)).norm());
  EXPECT_EQ(d.distance, best);
  EXPECT_NEAR((P.row(d.i) - P.row(d.j)).norm(), best, 0.0);
  EXPECT_NEAR(sphericity(Points(5.0 * P)), sphericity(P), 1e-12);
  EXPECT_GT(sphericity(P), 0.05);
}
