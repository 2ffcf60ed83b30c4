#include <gtest/gtest.h>

#include "ek/core/errors.hpp"
#include "testing.hpp"
#include "ek/knots/codes.hpp"

using namespace ek;

using ek::fixtures::expect_input_error;

TEST(DTCode, ParsesTableSpelling) {
  auto dt = parse_dt("[4; 6; 8; 2]");
  EXPECT_EQ(dt.labels, (std::vector<int>{4, 6, 8, 2}));
  EXPECT_EQ(to_string(dt), "[4; 6; 8; 2]");
  auto dt2 = parse_dt("[4, 8, -12, 2, 14, -6, 16, 10]");  // 8_21 from paper Appendix A
  EXPECT_EQ(dt2.crossings(), 8);
  EXPECT_EQ(dt2.labels[2], -12);
}

TEST(DTCode, RejectsMalformed) {
  expect_input_error([] { parse_dt("[4; 7; 8; 2]"); }, "label 7 at position 2 is odd");
  expect_input_error([] { parse_dt("[4; 4; 8; 2]"); }, "label 4 at position 2 is repeated");
  expect_input_error([] { parse_dt("[4; 6; 10; 2]"); }, "exceeds 2c = 8");
  expect_input_error([] { parse_dt("[]"); }, "empty code");
  expect_input_error([] { parse_dt("[4; 0; 8; 2]"); }, "label 0");
  expect_input_error([] { parse_dt("[4; 6; 8; 2"); }, "missing closing");
  expect_input_error([] { parse_dt("4; 6; 8; 2]"); }, "expected '['");
  expect_input_error([] { parse_dt("[4; x; 8; 2]"); }, "unexpected token 'x'");
  expect_input_error([] { parse_dt("[4; 6; 8; 2] 5"); }, "text after");
  expect_input_error([] { parse_dt("[4; 99999999999999999999]"); }, "out of range");
}

TEST(PDCode, ParsesTableSpelling) {
  auto pd = parse_pd("[[4;2;5;1];[8;6;1;5];[6;3;7;4];[2;7;3;8]]");
  ASSERT_EQ(pd.size(), 4);
  EXPECT_EQ(pd.crossings[0].e, (std::array<int, 4>{4, 2, 5, 1}));
  EXPECT_EQ(to_string(pd), "[[4;2;5;1];[8;6;1;5];[6;3;7;4];[2;7;3;8]]");
  // 3_1: all crossings positive (b = d + 1)
  auto t = parse_pd("[[1;5;2;4];[3;1;4;6];[5;3;6;2]]");
  for (const auto& x : t.crossings) EXPECT_EQ(x.sign(6), +1);
  // 4_1: two of each sign (amphicheiral, writhe 0)
  int w = 0;
  for (const auto& x : pd.crossings) w += x.sign(8);
  EXPECT_EQ(w, 0);
}

TEST(PDCode, RejectsMalformed) {
  expect_input_error([] { parse_pd("[[4;2;5;1];[8;6;1;5];[6;3;7;4];[2;7;3;9]]"); }, "label 9");
  expect_input_error([] { parse_pd("[[4;2;5;1];[8;6;1;5];[6;3;7;4];[2;7;3;7]]"); }, "appears 3 times");
  expect_input_error([] { parse_pd("[[4;2;5];[8;6;1;5]]"); }, "has 3 labels, expected 4");
  expect_input_error([] { parse_pd("[[4;2;5;1;3]]"); }, "more than 4 labels");
  expect_input_error([] { parse_pd("[]"); }, "empty code");
  expect_input_error([] { parse_pd("[[0;2;5;1]]"); }, "not positive");
  expect_input_error([] { parse_pd("[[1;5;3;4];[3;1;4;6];[5;2;6;2]]"); }, "not consecutive");
  expect_input_error([] { parse_pd("[[4;2;5;1];[8;6;1;5]"); }, "missing closing");
  expect_input_error([] { parse_pd("[4;2;5;1]"); }, "expected '['");
  expect_input_error([] { parse_pd("[[4;2;5;1];[8;6;1;5];[6;3;7;4];[2;7;3;8]]]"); }, "text after");
}

TEST(BraidWord, ParsesTableSpelling) {
  auto b = parse_braid("{1;-2;1;-2}");
  EXPECT_EQ(b.strands, 3);
  EXPECT_EQ(b.letters, (std::vector<int>{1, -2, 1, -2}));
  EXPECT_EQ(to_string(b), "{1;-2;1;-2}");
  EXPECT_EQ(parse_braid("{1;-1;1}").strands, 2);  // the table's unknot
  EXPECT_EQ(parse_braid("{1;1;1}", 2).strands, 2);
}

TEST(BraidWord, RejectsMalformed) {
  expect_input_error([] { parse_braid("{}"); }, "empty word");
  expect_input_error([] { parse_braid("{1;0;1}"); }, "generator 0 at position 2");
  expect_input_error([] { parse_braid("{1;1}"); }, "2 components");
  expect_input_error([] { parse_braid("{1;1;2;2}"); }, "3 components");
  expect_input_error([] { parse_braid("{1;1;1}", 2 - 1); }, "needs more than 1 strands");
  expect_input_error([] { parse_braid("[1;1;1]"); }, "expected '{'");
  expect_input_error([] { parse_braid("{1;1;1"); }, "missing closing");
  expect_input_error([] { parse_braid("{1;a;1}"); }, "unexpected token 'a'");
}

TEST(BraidWord, ParsesLists) {
  auto list = parse_braid_list("[{-1;-1;-2;3;-2;1;-2;-2;3;2;2};{-1;2;-1;2;3;-2;-2;-4;3;-4}]");
  ASSERT_EQ(list.size(), 2u);
  EXPECT_EQ(list[0].strands, 4);
  EXPECT_EQ(list[1].strands, 5);
  EXPECT_EQ(parse_braid_list("{1;1;1}").size(), 1u);
  expect_input_error([] { parse_braid_list("[{1;1;1};x]"); }, "unexpected 'x'");
  expect_input_error([] { parse_braid_list("[{1;1;1}"); }, "missing closing ']'");
  expect_input_error([] { parse_braid_list("[]"); }, "empty list");
  expect_input_error([] { parse_braid_list("[{1;1;1};{1;1}]"); }, "2 components");
}

TEST(BraidWord, ClosureComponents) {
  BraidWord w{3, {1, 2}};
  EXPECT_EQ(closure_components(w), 1);
  BraidWord link{3, {1, 1, 2, 2}};
  EXPECT_EQ(closure_components(link), 3);
}

namespace {

/// f() throws InputError with a one-line message.
template <class F>
void expect_one_line_error(F f) {
  try {
    f();
    ADD_FAILURE() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
  }
}

std::string bytes(const char* s, size_t n) { return std::string(s, n); }

}  // namespace

// Inputs found by fuzzing (tests/fuzz/corpus/*/regression-*): the error
// message quoted a newline of the input and was two lines.
TEST(Codes, FuzzRegressionsGiveOneLineErrors) {
  expect_one_line_error([] { parse_dt(bytes("[46\x9d 8; 2] 4\n\0\0\0 8; 2]10", 24)); });
  expect_one_line_error([] { parse_pd(bytes("[\n\0\0\0[4;2\x01\xf7\xfe\0\0;[8;6;1;5]", 24)); });
  expect_one_line_error([] { parse_braid_list(bytes("};\x85\n\xfb\xff\xff\xef\xff\xff\0", 11)); });
  expect_input_error([] { parse_dt("[4\n; x]"); }, "[4\\n; x]");
}

// PD codes of links (LinkInfo's convention: each component's labels in a row).
// The Hopf link: components {1, 2} and {3, 4}, each passing over once; the
// over strands of two-edge components are ordered by their under ends.
TEST(PDLinkCode, HopfLink) {
  const PDLinkCode h = parse_pd_link("[[4;1;3;2];[2;3;1;4]]");
  EXPECT_EQ(h.components, (std::vector<std::array<int, 2>>{{1, 2}, {3, 4}}));
  // label 1 leaves crossing 2 (its c) and enters crossing 1: over 1 -> 2 there, b -> d: negative
  EXPECT_EQ(h.over_in, (std::vector<int>{1, 3}));
  EXPECT_EQ(h.sign(0), -1);
  EXPECT_EQ(h.sign(1), -1);
  EXPECT_EQ(to_string(h.code), "[[4;1;3;2];[2;3;1;4]]");
}

// A knot's code reads as one component [1, 2c] with parse_pd's signs.
TEST(PDLinkCode, AKnotsCodeIsOneComponent) {
  const std::string trefoil = "[[1;5;2;4];[3;1;4;6];[5;3;6;2]]";
  const PDLinkCode k = parse_pd_link(trefoil);
  const PDCode p = parse_pd(trefoil);
  EXPECT_EQ(k.components, (std::vector<std::array<int, 2>>{{1, 6}}));
  for (int i = 0; i < p.size(); ++i) EXPECT_EQ(k.sign(i), p.crossings[static_cast<size_t>(i)].sign(6)) << i;
}

// A two-edge component that only passes over ({1, 2} over {3, 4} twice): its
// orientation is the choice of the smaller label into the first crossing,
// and its two crossings then have opposite signs (linking number 0).
TEST(PDLinkCode, ATwoEdgeComponentThatOnlyPassesOver) {
  const PDLinkCode u = parse_pd_link("[[3;1;4;2];[4;1;3;2]]");
  EXPECT_EQ(u.components, (std::vector<std::array<int, 2>>{{1, 2}, {3, 4}}));
  EXPECT_EQ(u.over_in, (std::vector<int>{1, 2}));
  EXPECT_EQ(u.sign(0) + u.sign(1), 0);
}

TEST(PDLinkCode, RejectsMalformed) {
  expect_input_error([] { parse_pd_link("[[1;2;3;4];[3;4;1;2]]"); }, "are not consecutive");
  expect_input_error([] { parse_pd_link("[[1;2;1;2]]"); }, "a component of one edge");
  expect_input_error([] { parse_pd_link("[[4;1;3;2];[2;3;1]]"); }, "has 3 labels");
  expect_input_error([] { parse_pd_link("[[4;1;3;2];[2;3;1;5]]"); }, "exceeds 2c");
  // component {1..4}: under strand 1 -> 3 skips a label
  expect_input_error([] { parse_pd_link("[[1;2;3;4];[3;4;2;1]]"); }, "under-strand edges 1 -> 3 are not consecutive labels");
}
