// The Conway polynomial of knots and links and Milnor's triple linking
// number, on known answers: the table's knots (∇ from the PD code's Δ and from
// the braid word's, c_0 = 1); braid closures by two independent routes (the
// Burau formula and the Fox matrix of the closure's diagram) against their
// published polynomials (the Hopf link z, T(2,4) 2z + z³, T(2,6)
// 3z + 4z³ + z⁵, the Whitehead link z³, the Borromean rings z⁴, 3_1 # Hopf
// z + z³, unlinks 0); curves: two round circles through each other, the
// Borromean rings as three perpendicular ellipses (μ̄(123) = 1, also
// mirrored), three separate circles (∇ = 0, μ̄ = 0), a (2, 4) torus link on a
// torus; Hoste's c_{m−1} from the linking numbers alone.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "ek/knots/alexander.hpp"
#include "ek/knots/conway.hpp"
#include "ek/knots/invariants.hpp"
#include "ek/knots/table.hpp"

using namespace ek;

namespace {

using Coeffs = std::vector<std::int64_t>;

BraidWord word(int strands, std::vector<int> letters) { return BraidWord{strands, std::move(letters)}; }

/// The ellipse (a cos s, b sin s) in the plane of axes (u, v), shifted by c.
Points ellipse(const Vec3& u, const Vec3& v, double a, double b, const Vec3& c = Vec3::Zero(), int n = 96) {
  Points P(n, 3);
  for (int i = 0; i < n; ++i) {
    const double s = 2.0 * M_PI * i / n;
    P.row(i) = (c + a * std::cos(s) * u + b * std::sin(s) * v).transpose();
  }
  return P;
}

Link borromean_ellipses() {
  const Vec3 x = Vec3::UnitX(), y = Vec3::UnitY(), z = Vec3::UnitZ();
  return {ellipse(x, y, 2.0, 1.0), ellipse(y, z, 2.0, 1.0), ellipse(z, x, 2.0, 1.0)};
}

/// Component j of the (2, 2k) torus link: once along the torus, k times around its tube.
Points torus_link_component(int k, int j, int n = 160) {
  Points P(n, 3);
  for (int i = 0; i < n; ++i) {
    const double s = 2.0 * M_PI * i / n, psi = k * s + M_PI * j;
    const double r = 2.0 + 0.7 * std::cos(psi);
    P.row(i) << r * std::cos(s), r * std::sin(s), 0.7 * std::sin(psi);
  }
  return P;
}

Eigen::MatrixXi rounded_linking(const Link& link) { return linking_matrix(link).array().round().cast<int>(); }

}  // namespace

TEST(Conway, OfTableKnotsFromBothRoutes) {
  const KnotTable& t = KnotTable::global();
  EXPECT_EQ(conway_from_alexander(table_alexander(t.at("3_1")).coefficients, 1).coefficients, (Coeffs{1, 0, 1}));
  EXPECT_EQ(conway_from_alexander(table_alexander(t.at("4_1")).coefficients, 1).coefficients, (Coeffs{1, 0, -1}));
  EXPECT_EQ(conway_from_alexander({1}, 1).coefficients, (Coeffs{1}));
  int checked = 0;
  for (const KnotRecord& k : t.records()) {
    if (k.crossing_number > 10 || !k.braid) continue;
    const ConwayPolynomial from_pd = conway_from_alexander(table_alexander(k).coefficients, 1);
    ASSERT_FALSE(from_pd.zero()) << k.name;
    EXPECT_EQ(from_pd.coefficients[0], 1) << k.name;            // ∇(0) = Δ(1) = 1
    EXPECT_EQ(from_pd.coefficients.size() % 2, 1u) << k.name;  // even powers only
    EXPECT_EQ(conway(*k.braid), from_pd) << k.name;
    ++checked;
  }
  EXPECT_GT(checked, 200);
}

TEST(Conway, OfBraidClosuresByBurauAndByTheDiagramAgree) {
  struct Case {
    const char* name;
    BraidWord word;
    Coeffs expected;
  };
  for (const Case& c : {Case{"Hopf", word(2, {1, 1}), {0, 1}},
                        Case{"Hopf mirror", word(2, {-1, -1}), {0, 1}},  // −z, up to the sign
                        Case{"T(2,4)", word(2, {1, 1, 1, 1}), {0, 2, 0, 1}},
                        Case{"T(2,6)", word(2, {1, 1, 1, 1, 1, 1}), {0, 3, 0, 4, 0, 1}},
                        Case{"Whitehead", word(3, {1, -2, 1, -2, -2}), {0, 0, 0, 1}},
                        Case{"Borromean", word(3, {1, -2, 1, -2, 1, -2}), {0, 0, 0, 0, 1}},
                        Case{"3_1 # Hopf", word(3, {1, 1, 1, 2, 2}), {0, 1, 0, 1}},
                        Case{"two-component unlink", word(2, {1, -1}), {}},
                        Case{"three-component unlink", word(3, {}), {}},
                        Case{"trefoil", word(2, {1, 1, 1}), {1, 0, 1}}}) {
    EXPECT_EQ(conway(c.word).coefficients, c.expected) << c.name;
    const LinkDiagram d = link_diagram_from_braid(c.word);
    EXPECT_EQ(static_cast<int>(d.components.size()), closure_components(c.word)) << c.name;
    EXPECT_EQ(conway(d).coefficients, c.expected) << c.name;
  }
}

TEST(Conway, HopfLinkOfTwoCircles) {
  const Link hopf{ellipse(Vec3::UnitX(), Vec3::UnitY(), 1.0, 1.0),
                  ellipse(Vec3::UnitX(), Vec3::UnitZ(), 1.0, 1.0, Vec3(1.0, 0.0, 0.0))};
  EXPECT_EQ(conway(hopf).coefficients, (Coeffs{0, 1}));
  EXPECT_EQ(std::abs(hoste_coefficient(rounded_linking(hopf))), 1);
  EXPECT_FALSE(milnor_triple_linking(conway(hopf), rounded_linking(hopf)));  // not 3 components
}

TEST(Conway, BorromeanRingsAreNotTheUnlink) {
  const Link b = borromean_ellipses();
  ASSERT_EQ(rounded_linking(b), Eigen::MatrixXi::Zero(3, 3));  // the linking numbers cannot tell
  for (const Points& P : b) EXPECT_EQ(alexander(P).to_string(), "[1]");  // nor the components
  const ConwayPolynomial nabla = conway(b);
  EXPECT_EQ(nabla.coefficients, (Coeffs{0, 0, 0, 0, 1}));
  EXPECT_EQ(milnor_triple_linking(nabla, rounded_linking(b)), 1);
  Link mirror = b;
  for (Points& P : mirror) P.col(2) *= -1.0;
  EXPECT_EQ(milnor_triple_linking(conway(mirror), rounded_linking(mirror)), 1);
  // Three circles far apart: the unlink.
  const Link unlink{ellipse(Vec3::UnitX(), Vec3::UnitY(), 1.0, 1.0),
                    ellipse(Vec3::UnitY(), Vec3::UnitZ(), 1.0, 1.0, Vec3(5.0, 0.0, 0.0)),
                    ellipse(Vec3::UnitZ(), Vec3::UnitX(), 1.0, 1.0, Vec3(0.0, 5.0, 0.0))};
  EXPECT_TRUE(conway(unlink).zero());
  EXPECT_EQ(milnor_triple_linking(conway(unlink), rounded_linking(unlink)), 0);
  // Each ring lifted off the other two would be split: one ring moved away.
  Link apart = b;
  apart[2].col(0).array() += 10.0;
  EXPECT_TRUE(conway(apart).zero());
}

TEST(Conway, TorusLinkOnATorusAndHoste) {
  for (int k = 1; k <= 3; ++k) {
    const Link l{torus_link_component(k, 0), torus_link_component(k, 1)};
    const Eigen::MatrixXi lk = rounded_linking(l);
    EXPECT_EQ(std::abs(lk(0, 1)), k);
    const ConwayPolynomial nabla = conway(l);
    EXPECT_EQ(nabla, conway(word(2, std::vector<int>(static_cast<size_t>(2 * k), 1)))) << k;
    ASSERT_GE(nabla.coefficients.size(), 2u);
    EXPECT_EQ(std::abs(hoste_coefficient(lk)), nabla.coefficients[1]) << k;  // c_1 = Lk
  }
  // T(3,3): three components, every pair linked once: c_2 = 3 (Hoste).
  Eigen::MatrixXi lk = Eigen::MatrixXi::Ones(3, 3);
  lk.diagonal().setZero();
  EXPECT_EQ(hoste_coefficient(lk), 3);
  EXPECT_EQ(conway(word(3, {1, 2, 1, 2, 1, 2})).coefficients.at(2), 3);
}

TEST(Conway, RefusesAPolynomialOfTheWrongShape) {
  EXPECT_THROW(conway_from_alexander({-1, 1}, 1), std::logic_error);     // t − 1 is no knot's
  EXPECT_THROW(conway_from_alexander({1, 0, 0, 1}, 2), std::logic_error);  // not antisymmetric
  EXPECT_TRUE(conway_from_alexander({}, 3).zero());
  EXPECT_THROW(milnor_triple_linking(ConwayPolynomial{{0, 0, 0, 0, 2}}, Eigen::MatrixXi::Zero(3, 3)),
               std::logic_error);
}
