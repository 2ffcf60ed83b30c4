// Pretzel knots P(p_1, ..., p_k) from their standard diagram: known knot
// types (Alexander polynomial), the sign convention (writhe of the trefoils),
// and links and bad input rejected.
#include <gtest/gtest.h>

#include <cstdlib>

#include "ek/core/errors.hpp"
#include "ek/knots/alexander.hpp"
#include "ek/knots/pretzel.hpp"
#include "ek/knots/table.hpp"

using namespace ek;
using Coeffs = std::vector<std::int64_t>;

namespace {

Coeffs pretzel_alexander(const std::vector<int>& p) { return alexander(pretzel_pd(p)).coefficients; }
Coeffs table_alexander(const std::string& name) { return alexander(*KnotTable::global().at(name).pd).coefficients; }
int pretzel_writhe(const std::vector<int>& p) { return diagram_from_pd(pretzel_pd(p)).writhe(); }

}  // namespace

TEST(Pretzel, CodeIsValidWithOneCrossingPerHalfTwist) {
  for (const std::vector<int>& p : std::vector<std::vector<int>>{{3, 3, 3}, {3, 3, 5}, {-2, 3, 7}, {1, 1, 1}, {5, -1, -1}, {1, 2}, {3, 5, 7, 9, 11}}) {
    const PDCode pd = pretzel_pd(p);
    int c = 0;
    for (int x : p) c += std::abs(x);
    EXPECT_EQ(pd.size(), c) << pretzel_name(p);
    // parse_pd checks labels, consecutive under/over edges and one component
    const PDCode back = parse_pd(to_string(pd));
    ASSERT_EQ(back.size(), pd.size());
    for (int k = 0; k < pd.size(); ++k) EXPECT_EQ(back.crossings[k].e, pd.crossings[k].e) << pretzel_name(p);
  }
}

// P(1,1,1) and P(1,2) are trefoils, P(5,-1,-1) = 6_1 (the
// stevedore knot), P(3,3,3) = 9_35 (its table entry's Montesinos notation is
// K(1/3;1/3;1/3)), P(-2,3,7) = 12n_242 whose Alexander polynomial is
// Lehmer's polynomial t^10 - t^9 + t^7 - t^6 + t^5 - t^4 + t^3 - t + 1.
TEST(Pretzel, KnownKnotTypes) {
  EXPECT_EQ(pretzel_alexander({1, 1, 1}), (Coeffs{1, -1, 1}));
  // two columns: P(1,3) = T(2,5)... as a sum of two twists: 1/1 + 1/3 gives the (2,4)... only odd sums are knots
  EXPECT_EQ(pretzel_alexander({1, 2}), (Coeffs{1, -1, 1}));  // three crossings, determinant 3: the trefoil
  EXPECT_EQ(pretzel_alexander({5, -1, -1}), (Coeffs{-2, 5, -2}));
  EXPECT_EQ(pretzel_alexander({5, -1, -1}), table_alexander("6_1"));
  EXPECT_EQ(pretzel_alexander({3, 3, 3}), table_alexander("9_35"));
  EXPECT_EQ(pretzel_alexander({3, 3, 3}), (Coeffs{7, -13, 7}));
  EXPECT_EQ(pretzel_alexander({-2, 3, 7}), (Coeffs{1, -1, 0, 1, -1, 1, -1, 1, 0, -1, 1}));
  EXPECT_EQ(pretzel_alexander({-2, 3, 7}), table_alexander("12n_242"));
  // the relative signs of the columns matter: P(2,3,7) is another knot
  EXPECT_NE(pretzel_alexander({2, 3, 7}), pretzel_alexander({-2, 3, 7}));
  // permuting the columns cyclically does not change the knot
  EXPECT_EQ(pretzel_alexander({3, 5, 7}), pretzel_alexander({5, 7, 3}));
}

// Sign convention: P(-1,-1,-1) is the right-handed trefoil (three positive
// crossings), P(1,1,1) the left-handed one; the diagram of P(p,q,r) with
// p, q, r odd has the two strands of every column oriented oppositely, so all
// its crossings have the sign -sign(p_i) of their column.
TEST(Pretzel, SignConvention) {
  EXPECT_EQ(pretzel_writhe({-1, -1, -1}), 3);
  EXPECT_EQ(pretzel_writhe({1, 1, 1}), -3);
  EXPECT_EQ(pretzel_writhe({3, 3, 3}), -9);
  EXPECT_EQ(pretzel_writhe({-3, -5, -5}), 13);
  EXPECT_EQ(pretzel_writhe({3, -5, 7}), -3 + 5 - 7);
  // mirror images have the same Alexander polynomial
  EXPECT_EQ(pretzel_alexander({-3, -3, -5}), pretzel_alexander({3, 3, 5}));
}

// The determinant of P(p_1, ..., p_k) is |Σ_i Π_{j≠i} p_j| (for three
// columns |pq + qr + rp|): an independent check of every column's sign.
TEST(Pretzel, DeterminantFormula) {
  for (const std::vector<int>& p : std::vector<std::vector<int>>{
           {3, 3, 3}, {3, 3, 5}, {3, 5, 5}, {5, 5, 5}, {3, 3, 7}, {-2, 3, 7}, {-3, 5, 7}, {3, -5, -7}, {1, 1, 1},
           {2, 3, 7}, {-3, -3, 5}, {3, 5, 7, 9, 11}, {-1, 4, 3}}) {
    long long sum = 0;
    for (size_t i = 0; i < p.size(); ++i) {
      long long prod = 1;
      for (size_t j = 0; j < p.size(); ++j)
        if (j != i) prod *= p[j];
      sum += prod;
    }
    EXPECT_EQ(alexander(pretzel_pd(p)).determinant(), std::llabs(sum)) << pretzel_name(p);
  }
}

TEST(Pretzel, LinksAndBadInputAreRejected) {
  EXPECT_THROW(pretzel_pd({3, 3}), InputError);        // all odd, even count: two components
  EXPECT_THROW(pretzel_pd({2, 2, 2}), InputError);     // all even: three components
  EXPECT_THROW(pretzel_pd({2, 4, 3}), InputError);     // two even columns
  EXPECT_THROW(pretzel_pd({1, 1, 1, 1}), InputError);
  EXPECT_THROW(pretzel_pd({}), InputError);
  EXPECT_THROW(pretzel_pd({3}), InputError);  // one column
  EXPECT_THROW(pretzel_pd({3, 0, 3}), InputError);
  try {
    pretzel_pd({2, 2, 2});
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("3 components"), std::string::npos) << e.what();
  }
}

TEST(Pretzel, NamesParseAndPrint) {
  EXPECT_EQ(pretzel_name({3, -5, 7}), "P(3,-5,7)");
  EXPECT_EQ(parse_pretzel("P(3,-5,7)"), (std::vector<int>{3, -5, 7}));
  EXPECT_EQ(parse_pretzel("3, 3, 5"), (std::vector<int>{3, 3, 5}));
  EXPECT_EQ(parse_pretzel("(3,3,5)"), (std::vector<int>{3, 3, 5}));
  for (const char* bad : {"", "P()", "P(3,,3)", "P(3,x)", "P(3,0,3)", "P(3,3", "P(3;3)"})
    EXPECT_THROW(parse_pretzel(bad), InputError) << bad;
}
