#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>

#include "ek/core/sparse_assembler.hpp"

using namespace ek;

namespace {

/// Dense reference: full symmetric matrix from local blocks.
struct Block {
  std::array<int, 3> idx;
  Eigen::Matrix3d H;
};

Eigen::MatrixXd dense_upper(const std::vector<Block>& blocks, int n) {
  Eigen::MatrixXd full = Eigen::MatrixXd::Zero(n, n);
  for (const auto& b : blocks)
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 3; ++c)
        if (b.idx[a] >= 0 && b.idx[c] >= 0) full(b.idx[a], b.idx[c]) += b.H(a, c);
  return full.triangularView<Eigen::Upper>();
}

std::vector<Block> random_blocks(std::mt19937& rng, int n, int count) {
  std::uniform_int_distribution<int> I(0, n - 1);
  std::normal_distribution<double> N;
  std::vector<Block> out;
  for (int k = 0; k < count; ++k) {
    Block b;
    b.idx = {I(rng), I(rng), k % 5 == 0 ? -1 : I(rng)};
    Eigen::Matrix3d A;
    for (int i = 0; i < 9; ++i) A(i) = N(rng);
    b.H = A + A.transpose();
    out.push_back(b);
  }
  return out;
}

}  // namespace

TEST(SparseAssembler, MatchesDenseAndReusesPattern) {
  std::mt19937 rng(3);
  const int n = 30;
  SparseAssembler A;
  auto fixed = random_blocks(rng, n, 40);
  std::vector<Block> contact;
  std::uint64_t version_before = 0;
  for (int pass = 0; pass < 6; ++pass) {
    // values change every pass; the contact structure changes on passes 0, 3 and 4
    for (auto& b : fixed) b.H *= 1.1;
    if (pass == 0 || pass == 3 || pass == 4) contact = random_blocks(rng, n, 5 + pass);
    A.begin(n);
    A.segment(0, 7);
    for (const auto& b : fixed) A.add_local(b.idx, b.H);
    A.segment(1, pass < 3 ? 100 : (pass == 3 ? 103 : 104));
    for (const auto& b : contact) A.add_local(b.idx, b.H);
    const bool changed = A.end();
    std::vector<Block> all = fixed;
    all.insert(all.end(), contact.begin(), contact.end());
    const Eigen::MatrixXd expected = dense_upper(all, n);
    const Eigen::MatrixXd got = Eigen::MatrixXd(A.matrix());
    EXPECT_LT((got - expected).cwiseAbs().maxCoeff(), 1e-12) << "pass " << pass;
    EXPECT_EQ(changed, pass == 0 || pass == 3 || pass == 4) << "pass " << pass;
    if (pass == 1 || pass == 5) {
      EXPECT_EQ(A.pattern_version(), version_before);
    }
    version_before = A.pattern_version();
  }
}

TEST(SparseAssembler, EmptySegmentsAreReplayed) {
  // A segment without entries (e.g. no active contacts) must not force a rebuild.
  SparseAssembler A;
  for (int pass = 0; pass < 3; ++pass) {
    A.begin(4);
    A.segment(0, 1);
    A.add(0, 0, 1.0);
    A.add(1, 2, 2.0);
    A.segment(1, 5);  // empty
    const bool changed = A.end();
    EXPECT_EQ(changed, pass == 0) << pass;
  }
}

TEST(SparseAssembler, StoresUpperTriangleOnly) {
  SparseAssembler A;
  A.begin(3);
  A.add(2, 0, 1.5);
  A.add(0, 2, 1.0);
  A.add(1, 1, 4.0);
  A.end();
  EXPECT_EQ(A.matrix().nonZeros(), 2);
  EXPECT_DOUBLE_EQ(A.matrix().coeff(0, 2), 2.5);
  EXPECT_DOUBLE_EQ(A.matrix().coeff(2, 0), 0.0);
}

// set_offset() shifts later adds (a block of the dofs adding at its own
// indices), on the recording and on the replay pass; begin() resets it.
TEST(SparseAssembler, OffsetShiftsAddsIntoTheirBlock) {
  SparseAssembler A;
  for (int pass = 0; pass < 2; ++pass) {
    A.begin(5);
    A.segment(0, 7);
    A.add(0, 1, 1.0);
    A.set_offset(3);
    A.add(0, 1, 2.0);
    A.add(1, 1, 3.0);
    A.set_offset(0);
    A.add(4, 4, 5.0);
    A.end();
    EXPECT_DOUBLE_EQ(A.matrix().coeff(0, 1), 1.0) << pass;
    EXPECT_DOUBLE_EQ(A.matrix().coeff(3, 4), 2.0) << pass;
    EXPECT_DOUBLE_EQ(A.matrix().coeff(4, 4), 8.0) << pass;
    EXPECT_EQ(A.matrix().nonZeros(), 3) << pass;
  }
  A.begin(5);
  A.set_offset(2);
  A.end();
  A.begin(5);
  A.add(0, 0, 1.0);  // begin() reset the offset
  A.end();
  EXPECT_DOUBLE_EQ(A.matrix().coeff(0, 0), 1.0);
}

TEST(SparseAssembler, MisuseThrows) {
  SparseAssembler A;
  EXPECT_THROW(A.end(), std::invalid_argument);
  A.begin(3);
  EXPECT_THROW(A.segment(1, 0), std::invalid_argument);
}

// The rebuilt matrix equals, bit for bit, Eigen's setFromTriplets of every
// add of the pass in call order (duplicates summed left to right), whichever
// segments were replayed and whichever recorded, over passes that change,
// keep, grow and shrink the segments' structures.
TEST(SparseAssembler, RebuildSumsInCallOrderBitForBit) {
  std::mt19937 rng(11);
  const int n = 40;
  SparseAssembler A;
  auto fixed = random_blocks(rng, n, 60);
  std::vector<Block> contact, extra;
  for (int pass = 0; pass < 12; ++pass) {
    for (auto& b : fixed) b.H *= 1.0 + 1e-3 * pass;
    if (pass % 3 == 0) contact = random_blocks(rng, n, 3 + 4 * (pass % 2) + pass);
    if (pass % 4 == 1) extra = random_blocks(rng, n, 2 + pass % 3);
    std::vector<Eigen::Triplet<double, int>> calls;
    auto add_blocks = [&](const std::vector<Block>& blocks) {
      for (const auto& b : blocks) {
        A.add_local(b.idx, b.H);
        for (int a = 0; a < 3; ++a)
          for (int c = a; c < 3; ++c) {
            if (b.idx[a] < 0 || b.idx[c] < 0) continue;
            const double v = a == c ? b.H(a, a) : b.H(a, c);
            const int i = std::min(b.idx[a], b.idx[c]), j = std::max(b.idx[a], b.idx[c]);
            calls.emplace_back(i, j, (b.idx[a] == b.idx[c] && a != c) ? 2.0 * v : v);
          }
      }
    };
    A.begin(n);
    A.segment(0, 1);
    add_blocks(fixed);
    A.segment(1, 100 + static_cast<std::uint64_t>(pass / 3));
    add_blocks(contact);
    A.segment(2, 200 + static_cast<std::uint64_t>(pass / 4 * 4 + (pass % 4 == 1)));
    add_blocks(extra);
    A.end();
    Eigen::SparseMatrix<double, Eigen::ColMajor, int> reference(n, n);
    reference.setFromTriplets(calls.begin(), calls.end());
    const Eigen::MatrixXd got = Eigen::MatrixXd(A.matrix()), want = Eigen::MatrixXd(reference);
    EXPECT_TRUE((got.array() == want.array()).all()) << "pass " << pass;
    EXPECT_EQ(A.matrix().nonZeros(), reference.nonZeros()) << "pass " << pass;
    EXPECT_TRUE(A.matrix().isCompressed());
  }
}

// A segment whose structure id stays the same while its number of adds
// changes (a caller's bug or a hash collision; the positions of the adds it
// had before are the same) still gives the right matrix: more adds than last
// time fall back to recording and keep the adds already written into slots;
// fewer adds drop the slots not written.
TEST(SparseAssembler, WrongStructureIdStillGivesTheRightMatrix) {
  SparseAssembler A;
  auto pass = [&A](const std::vector<std::array<double, 3>>& adds) {
    A.begin(5);
    A.segment(0, 42);
    Eigen::MatrixXd want = Eigen::MatrixXd::Zero(5, 5);
    for (const auto& a : adds) {
      const int i = static_cast<int>(a[0]), j = static_cast<int>(a[1]);
      A.add(i, j, a[2]);
      want(std::min(i, j), std::max(i, j)) += a[2];
    }
    A.end();
    return (Eigen::MatrixXd(A.matrix()) - want).cwiseAbs().maxCoeff();
  };
  EXPECT_EQ(pass({{0, 0, 1.0}, {1, 2, 2.0}}), 0.0);
  EXPECT_EQ(pass({{0, 0, 1.5}, {1, 2, 2.5}, {3, 4, 3.0}, {0, 0, 0.25}}), 0.0);  // more adds
  EXPECT_EQ(pass({{0, 0, 4.0}, {1, 2, 5.0}, {3, 4, 6.0}, {0, 0, 7.0}}), 0.0);   // same: replayed
  EXPECT_EQ(pass({{0, 0, 1.0}}), 0.0);                                           // fewer adds
  EXPECT_EQ(A.matrix().nonZeros(), 1);
}
