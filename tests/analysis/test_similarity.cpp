#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <thread>

#include "ek/analysis/similarity.hpp"
#include "ek/geometry/resample.hpp"
#include "testing.hpp"

using namespace ek;

namespace {

Points reverse_order(const Points& P) { return P.colwise().reverse(); }

std::vector<SimilarityOptions> all_option_sets() {
  std::vector<SimilarityOptions> v;
  for (bool r : {false, true})
    for (bool m : {false, true}) {
      SimilarityOptions o;
      o.reversal = r;
      o.mirror = m;
      v.push_back(o);
    }
  return v;
}

std::vector<Points> test_curves(int n) {
  std::vector<Points> c;
  c.push_back(fixtures::torus_knot(n, 2, 3));
  c.push_back(fixtures::torus_knot(n, 3, 2, 2.0, 0.7));
  c.push_back(fixtures::torus_knot(n, 2, 5));
  for (std::uint64_t seed = 1; seed <= 5; ++seed) c.push_back(fixtures::random_fourier_curve(n, 4, seed));
  c.push_back(fixtures::circle(n, 1.0));
  c.push_back(fixtures::ellipse(n, 2.0, 1.0));
  return c;
}

}  // namespace

TEST(Similarity, SelfSimilarityIsExactlyOne) {
  for (const SimilarityOptions& o : all_option_sets())
    for (const Points& P : test_curves(200)) {
      const SimilarityResult r = compare_curves(P, P, o);
      EXPECT_EQ(r.similarity, 1.0);
      EXPECT_NEAR(r.curvature_correlation, 1.0, 1e-12);
    }
}

TEST(Similarity, InvariantUnderRigidMotionAndCyclicReindexing) {
  const int n = 400;
  int k = 0;
  for (const Points& P : test_curves(n)) {
    const int shift = 37 + 11 * k;
    const Points Q = fixtures::rigid_copy(P, fixtures::random_rotation(100 + static_cast<std::uint64_t>(k)),
                                          Vec3(5.0, -3.0, 2.0), shift);
    const SimilarityResult r = compare_curves(P, Q);
    EXPECT_GE(r.similarity, 0.999) << k;
    EXPECT_NEAR(r.similarity, 1.0, 1e-12) << k;  // measured: exactly 1 after the snap
    // vertex i of P matches vertex i - shift of Q (Q_j = R P_{j+shift} + t); symmetric curves
    // (circle, ellipse, torus knots) also match at other shifts, so check only the generic ones
    if (k >= 3 && k < 8) {
      EXPECT_EQ(r.best_shift, ((-shift) % n + n) % n) << k;
    }
    EXPECT_FALSE(r.reversed);
    EXPECT_FALSE(r.mirrored);
    ++k;
  }
}

TEST(Similarity, ResampledCopyWithAnotherVertexCountIsClose) {
  // two discretisations of one trefoil: 400 vertices at equal arc length, and a
  // fine 4000-vertex rigid copy, resampled by the comparison to the smaller count
  const Points fine = fixtures::torus_knot(4000, 2, 3);
  const Points P = resample_arclength(fixtures::rigid_copy(fine, Mat3::Identity(), Vec3::Zero(), 1234), 400);
  const Points Q = fixtures::rigid_copy(fine, fixtures::random_rotation(8), Vec3(1, 2, 3), 50);
  const double s = similarity(P, Q);
  EXPECT_GE(s, 0.99);  // measured 0.9999
  EXPECT_LE(s, 1.0);
}

TEST(Similarity, InUnitIntervalAndSymmetric) {
  const int n = 128;
  std::vector<Points> curves = test_curves(n);
  for (std::uint64_t seed = 20; seed < 30; ++seed)
    curves.push_back(fixtures::random_fourier_curve(n, 3 + static_cast<int>(seed % 4), seed, 0.5));
  for (const SimilarityOptions& o : all_option_sets()) {
    SimilarityEngine engine(n, o);
    std::vector<SignatureSpectrum> spectra;
    for (const Points& c : curves) spectra.push_back(engine.spectrum(c));
    double lo = 1.0, hi = 0.0;
    for (size_t i = 0; i < curves.size(); ++i)
      for (size_t j = 0; j < curves.size(); ++j) {
        const double sij = engine.similarity(spectra[i], spectra[j]);
        const double sji = engine.similarity(spectra[j], spectra[i]);
        EXPECT_GE(sij, 0.0);
        EXPECT_LE(sij, 1.0);
        EXPECT_NEAR(sij, sji, 1e-12) << i << " " << j;
        if (i != j) {
          lo = std::min(lo, sij);
          hi = std::max(hi, sij);
        }
      }
    EXPECT_LT(lo, 0.6);  // the test set is not degenerate: scores spread out
    EXPECT_GT(hi - lo, 0.2);
  }
}

TEST(Similarity, ReversalOption) {
  // a generic curve (no symmetry mapping it to its reverse)
  const int n = 256;
  const Points P = fixtures::random_fourier_curve(n, 5, 42);
  const Points Q = fixtures::rigid_copy(reverse_order(P), fixtures::random_rotation(3), Vec3(0, 1, 0), 40);
  SimilarityOptions with;
  with.reversal = true;
  const SimilarityResult r = compare_curves(P, Q, with);
  EXPECT_GE(r.similarity, 0.999);
  EXPECT_TRUE(r.reversed);
  EXPECT_FALSE(r.mirrored);
  // Q_j = R P_{n-1-(j+40)} + t, so reverse(Q)_j = Q_{n-1-j} = R P_{j-40} + t: P_i <-> reverse(Q)_{i+40}
  EXPECT_EQ(r.best_shift, 40);
  const double without = similarity(P, Q);
  EXPECT_LT(without, 0.95);  // measured 0.86: orientation matters without the option
}

TEST(Similarity, MirrorOptionOnAChiralCurve) {
  // the trefoil torus knot is chiral: its mirror image is no rigid copy of it
  const int n = 300;
  const Points P = fixtures::torus_knot(n, 2, 3);
  const Points M = fixtures::rigid_copy(fixtures::mirror_x(P), fixtures::random_rotation(5), Vec3(1, 1, 1), 13);
  SimilarityOptions with;
  with.mirror = true;
  const SimilarityResult r = compare_curves(P, M, with);
  EXPECT_GE(r.similarity, 0.999);
  EXPECT_TRUE(r.mirrored);
  const SimilarityResult r0 = compare_curves(P, M);
  EXPECT_LT(r0.similarity, 0.75);  // measured 0.5: torsion anti-correlated (-1), only the curvature half remains
  EXPECT_FALSE(r0.mirrored);
  // mirrored and reversed at once needs both options
  const Points MR = reverse_order(fixtures::mirror_x(fixtures::random_fourier_curve(n, 5, 9)));
  const Points G = fixtures::random_fourier_curve(n, 5, 9);
  SimilarityOptions both;
  both.mirror = both.reversal = true;
  const SimilarityResult rb = compare_curves(G, MR, both);
  EXPECT_GE(rb.similarity, 0.999);
  EXPECT_TRUE(rb.mirrored);
  EXPECT_TRUE(rb.reversed);
  EXPECT_LT(similarity(G, MR, with), 0.95);  // measured 0.88
}

TEST(Similarity, FftEqualsDirectEvaluation) {
  for (int n : {64, 97, 128, 255, 400}) {
    std::vector<Points> curves = test_curves(n);
    curves.push_back(fixtures::random_fourier_curve(n, 8, 77, 2.0));
    for (const SimilarityOptions& o : all_option_sets()) {
      SimilarityEngine engine(n, o);
      for (size_t i = 0; i < curves.size(); ++i)
        for (size_t j = i; j < curves.size(); j += 2) {
          const CurveSignature a = curve_signature(curves[i]), b = curve_signature(curves[j]);
          const SimilarityResult f = engine.compare(engine.spectrum(a), engine.spectrum(b));
          const SimilarityResult d = similarity_direct(a, b, o);
          EXPECT_NEAR(f.similarity, d.similarity, 1e-12) << n << " " << i << " " << j;
          // symmetric curves tie between shifts and symmetries: compare the rest only when both
          // evaluations picked the same candidate
          if (f.reversed == d.reversed && f.mirrored == d.mirrored && f.best_shift == d.best_shift) {
            EXPECT_NEAR(f.curvature_correlation, d.curvature_correlation, 1e-12);
            EXPECT_NEAR(f.torsion_correlation, d.torsion_correlation, 1e-12);
          }
        }
    }
  }
}

TEST(Similarity, ZeroTorsionRule) {
  const int n = 160;
  const Points C = fixtures::circle(n, 1.0);
  const Points E = fixtures::ellipse(n, 2.0, 1.0);
  const Points K = fixtures::torus_knot(n, 2, 3);
  SimilarityEngine engine(n);
  const SignatureSpectrum sc = engine.spectrum(C), se = engine.spectrum(E), sk = engine.spectrum(K);
  EXPECT_TRUE(sc.torsion_is_zero());
  EXPECT_TRUE(se.torsion_is_zero());
  EXPECT_FALSE(sk.torsion_is_zero());
  // two planar curves: torsion correlation 1 by definition, score (1 + max K correlation)/2
  const SimilarityResult ce = engine.compare(sc, se);
  EXPECT_EQ(ce.torsion_correlation, 1.0);
  const CurveSignature a = curve_signature(C), b = curve_signature(E);
  double best = -1.0;
  for (int s = 0; s < n; ++s) {
    double d = 0.0;
    for (int i = 0; i < n; ++i) d += a.curvature(i) * b.curvature((i + s) % n);
    best = std::max(best, d / (a.curvature.norm() * b.curvature.norm()));
  }
  EXPECT_NEAR(ce.similarity, 0.5 * (1.0 + best), 1e-13);
  // planar against 3D: the torsion term is 0, so at most 1/2
  const SimilarityResult ck = engine.compare(sc, sk);
  EXPECT_EQ(ck.torsion_correlation, 0.0);
  EXPECT_LE(ck.similarity, 0.5);
  // a planar curve moved rigidly keeps T = 0 (no rounding noise in the torsion term)
  const SignatureSpectrum sm = engine.spectrum(fixtures::rigid_copy(E, fixtures::random_rotation(4), Vec3(7, 7, 7), 3));
  EXPECT_TRUE(sm.torsion_is_zero());
  EXPECT_EQ(engine.similarity(se, sm), 1.0);
}

TEST(Similarity, MatrixIsSymmetricWithUnitDiagonal) {
  const int n = 100;
  std::vector<Points> curves = test_curves(n);
  curves.push_back(fixtures::torus_knot(1000, 2, 3));  // another vertex count: resampled to 100
  SimilarityOptions o;
  o.reversal = true;
  const Eigen::MatrixXd S = similarity_matrix(curves, o);
  ASSERT_EQ(S.rows(), static_cast<Eigen::Index>(curves.size()));
  EXPECT_EQ((S - S.transpose()).cwiseAbs().maxCoeff(), 0.0);
  for (Eigen::Index i = 0; i < S.rows(); ++i) EXPECT_EQ(S(i, i), 1.0);
  EXPECT_GE(S.minCoeff(), 0.0);
  EXPECT_LE(S.maxCoeff(), 1.0);
  // entries equal the one-shot comparison at the common count
  EXPECT_NEAR(S(0, 1), similarity(curves[0], curves[1], o), 1e-14);
  // the finer trefoil resembles the coarse one (index 0)
  EXPECT_GT(S(0, S.rows() - 1), 0.98);  // measured 0.993
  // cross matrix of two sets agrees with the full matrix
  SimilarityEngine engine(n, o);
  std::vector<SignatureSpectrum> sp;
  for (const Points& c : curves) sp.push_back(engine.spectrum(c));
  const std::vector<SignatureSpectrum> first(sp.begin(), sp.begin() + 4), rest(sp.begin() + 4, sp.end());
  const Eigen::MatrixXd X = engine.cross_matrix(first, rest);
  EXPECT_LT((X - S.block(0, 4, 4, S.cols() - 4)).cwiseAbs().maxCoeff(), 1e-14);
}

TEST(Similarity, MisuseThrows) {
  EXPECT_THROW(SimilarityEngine(2), std::invalid_argument);
  SimilarityOptions bad;
  bad.zero_tolerance = -1.0;
  EXPECT_THROW(SimilarityEngine(10, bad), std::invalid_argument);
  bad = {};
  bad.samples = 2;
  EXPECT_THROW(similarity(fixtures::circle(10, 1), fixtures::circle(10, 1), bad), std::invalid_argument);
  SimilarityEngine e10(10), e12(12);
  const SignatureSpectrum s12 = e12.spectrum(fixtures::torus_knot(12, 2, 3));
  EXPECT_THROW(e10.compare(s12, s12), std::invalid_argument);
  EXPECT_THROW(e10.spectrum(curve_signature(fixtures::torus_knot(12, 2, 3))), std::invalid_argument);
  EXPECT_EQ(e10.spectrum(fixtures::torus_knot(12, 2, 3)).size(), 10);  // a curve is resampled
}

TEST(Similarity, EnginesInSeveralThreads) {
  // one engine per thread (created concurrently: the FFTW planner is guarded), shared spectra
  const int n = 200;
  const std::vector<Points> curves = test_curves(n);
  const Eigen::MatrixXd serial = similarity_matrix(curves);
  std::vector<SignatureSpectrum> spectra;
  {
    SimilarityEngine e(n);
    for (const Points& c : curves) spectra.push_back(e.spectrum(c));
  }
  std::vector<Eigen::MatrixXd> results(4);
  std::vector<std::thread> threads;
  for (size_t k = 0; k < results.size(); ++k)
    threads.emplace_back([&, k] {
      SimilarityEngine e(n);
      results[k] = e.matrix(spectra);
    });
  for (std::thread& t : threads) t.join();
  for (const Eigen::MatrixXd& r : results) EXPECT_EQ(r, serial);
}
