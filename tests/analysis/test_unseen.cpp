// Estimates of the unseen states (unseen.hpp): the formulas on counts whose
// values are worked out by hand, the edge cases, and the estimators on
// samples drawn from known distributions of states.
#include <gtest/gtest.h>

#include <iostream>
#include <numeric>
#include <random>

#include "ek/analysis/unseen.hpp"
#include "ek/core/errors.hpp"

using namespace ek;

namespace {

/// The samples per state of n draws from the probabilities p (zeros kept).
std::vector<int> draw(const std::vector<double>& p, int n, std::mt19937& rng) {
  std::discrete_distribution<int> d(p.begin(), p.end());
  std::vector<int> counts(p.size(), 0);
  for (int i = 0; i < n; ++i) ++counts[static_cast<size_t>(d(rng))];
  return counts;
}

/// The probability mass of the states no sample fell into.
double unseen_mass(const std::vector<double>& p, const std::vector<int>& counts) {
  double total = std::accumulate(p.begin(), p.end(), 0.0), m = 0.0;
  for (size_t k = 0; k < p.size(); ++k) m += counts[k] == 0 ? p[k] : 0.0;
  return m / total;
}

}  // namespace

// 12 samples in 6 states, counts 1, 1, 1, 2, 2, 5: f1 = 3, f2 = 2, r = 11/12.
// Chao1 = 6 + r·9/4 = 8.0625; var = 2·(r·(3/2)²/2 + r²(3/2)³ + r²(3/2)⁴/4)
// = 9.86133; t = 2.0625, K = exp(1.95996·√ln(1 + var/t²)) = 8.5557, so the
// 95% interval is [6 + t/K, 6 + t·K] = [6.2411, 23.6446]. Good–Turing 3/12;
// Chao–Jost 3/12 · 33/(33 + 4) = 0.222973.
TEST(Unseen, SingletonsAndDoubletonsByHand) {
  const UnseenEstimate e = estimate_unseen({1, 1, 1, 2, 2, 5});
  EXPECT_EQ(e.samples, 12);
  EXPECT_EQ(e.observed, 6);
  EXPECT_EQ(e.singletons, 3);
  EXPECT_EQ(e.doubletons, 2);
  EXPECT_DOUBLE_EQ(e.good_turing, 0.25);
  EXPECT_NEAR(e.new_state_probability, 0.222973, 1e-6);
  EXPECT_DOUBLE_EQ(e.states, 8.0625);
  EXPECT_NEAR(e.lower, 6.2411, 1e-4);
  EXPECT_NEAR(e.upper, 23.6446, 1e-4);
}

// 7 samples, counts 1, 1, 1, 1, 3: no doubleton, the bias-corrected form.
// Chao1 = 5 + (6/7)·4·3/2 = 10.142857; var = (6/7)·6 + (6/7)²·4·49/4
// − (6/7)²·256/(4·10.142857) = 36.50704; interval [5.8289, 36.9067].
TEST(Unseen, NoDoubletonsUseTheBiasCorrectedForm) {
  const UnseenEstimate e = estimate_unseen({1, 1, 0, 1, 1, 3});
  EXPECT_EQ(e.samples, 7);
  EXPECT_EQ(e.observed, 5);
  EXPECT_NEAR(e.states, 10.142857, 1e-6);
  EXPECT_NEAR(e.lower, 5.8289, 1e-4);
  EXPECT_NEAR(e.upper, 36.9067, 1e-4);
}

// Counts 3, 4, 5: nothing seen once or twice, so nothing is extrapolated:
// Chao1 = D = 3, the chance of a new state 0, and the almost-complete
// interval: P = (e⁻³ + e⁻⁴ + e⁻⁵)/3, var = Σ(e⁻ⁱ − e⁻²ⁱ) − (Σ i e⁻ⁱ)²/12
// = 0.066506: [max(3, 3/(1−P) − z√var/(1−P)), 3/(1−P) + z√var/(1−P)] = [3, 3.59514].
TEST(Unseen, NoSingletonsMeansNothingUnseen) {
  const UnseenEstimate e = estimate_unseen({3, 4, 5});
  EXPECT_EQ(e.states, 3.0);
  EXPECT_EQ(e.good_turing, 0.0);
  EXPECT_EQ(e.new_state_probability, 0.0);
  EXPECT_EQ(e.lower, 3.0);
  EXPECT_NEAR(e.upper, 3.59514, 1e-5);
  const UnseenEstimate none = estimate_unseen({});
  EXPECT_EQ(none.samples, 0);
  EXPECT_EQ(none.states, 0.0);
  const UnseenEstimate one = estimate_unseen({1});  // one sample: one state, nothing to say beyond it
  EXPECT_EQ(one.states, 1.0);
  EXPECT_GE(one.upper, 1.0);
  EXPECT_THROW(estimate_unseen({1, -1}), InputError);
  EXPECT_THROW(estimate_unseen({1, 2}, UnseenOptions{1.0}), InputError);
}

// A wider confidence gives a wider interval around the same estimate.
TEST(Unseen, IntervalGrowsWithTheConfidence) {
  const std::vector<int> c{1, 1, 1, 1, 2, 2, 3, 7, 9};
  const UnseenEstimate a = estimate_unseen(c, UnseenOptions{0.8}), b = estimate_unseen(c, UnseenOptions{0.99});
  EXPECT_EQ(a.states, b.states);
  EXPECT_GT(a.lower, b.lower);
  EXPECT_LT(a.upper, b.upper);
  EXPECT_LE(b.lower, b.states);
  EXPECT_GE(b.upper, b.states);
}

// 40 equally likely states, 60 samples, 2,000 draws: Chao1's 95% interval
// holds the true 40 in at least 85% of the draws (measured: printed), and
// its mean is within 10% of 40 (it is unbiased for equal probabilities).
TEST(Unseen, IntervalCoversEqualStatesAtItsRate) {
  std::mt19937 rng(7);
  const std::vector<double> p(40, 1.0);
  int covered = 0;
  double mean = 0.0;
  const int trials = 2000;
  for (int t = 0; t < trials; ++t) {
    const UnseenEstimate e = estimate_unseen(draw(p, 60, rng));
    covered += e.lower <= 40.0 && 40.0 <= e.upper;
    mean += e.states / trials;
  }
  std::cout << "[ measured ] coverage " << static_cast<double>(covered) / trials << ", mean Chao1 " << mean
            << " of 40 states" << std::endl;
  EXPECT_GE(covered, 0.85 * trials);
  EXPECT_NEAR(mean, 40.0, 4.0);
}

// 60 states of geometric probabilities (ratio 0.93: the most likely 80
// times the least), 100 samples, 2,000 draws. Good–Turing's f1/n and the
// Chao–Jost probability estimate the unseen states' mass without bias to
// within 15% of it on average; Chao1 is, as stated, a lower bound in
// expectation for unequal probabilities: above the states seen, below the
// true 60 on average (its coverage is printed, not asserted).
TEST(Unseen, UnequalStatesNewStateChanceAndLowerBound) {
  std::mt19937 rng(11);
  std::vector<double> p(60);
  for (size_t k = 0; k < p.size(); ++k) p[k] = std::pow(0.93, static_cast<double>(k));
  const int trials = 2000;
  double mass = 0.0, gt = 0.0, cj = 0.0, chao = 0.0, seen = 0.0;
  int covered = 0;
  for (int t = 0; t < trials; ++t) {
    const std::vector<int> c = draw(p, 100, rng);
    const UnseenEstimate e = estimate_unseen(c);
    mass += unseen_mass(p, c) / trials;
    gt += e.good_turing / trials;
    cj += e.new_state_probability / trials;
    chao += e.states / trials;
    seen += static_cast<double>(e.observed) / trials;
    covered += e.lower <= 60.0 && 60.0 <= e.upper;
  }
  std::cout << "[ measured ] unseen mass " << mass << ", Good-Turing " << gt << ", Chao-Jost " << cj
            << "; Chao1 " << chao << " (seen " << seen << ", true 60), coverage "
            << static_cast<double>(covered) / trials << std::endl;
  EXPECT_NEAR(gt, mass, 0.15 * mass);
  EXPECT_NEAR(cj, mass, 0.15 * mass);
  EXPECT_GT(chao, seen);
  EXPECT_LT(chao, 60.0);
}

// Good–Turing for one kind: counts 1, 1, 3, 5 (n = 10), the first and third
// of the kind: one singleton of the kind, so 1/10; nothing of the kind seen
// once: 0. In a batch of 10 with p = 0.1: 1 − 0.9¹⁰ = 0.651322.
TEST(Unseen, KindsSingletonsOverAllSamples) {
  EXPECT_DOUBLE_EQ(new_state_probability_of_kind({1, 1, 3, 5}, {true, false, true, false}), 0.1);
  EXPECT_DOUBLE_EQ(new_state_probability_of_kind({1, 1, 3, 5}, {false, false, true, true}), 0.0);
  EXPECT_DOUBLE_EQ(new_state_probability_of_kind({}, {}), 0.0);
  EXPECT_NEAR(new_state_probability_in_batch(0.1, 10), 0.651322, 1e-6);
  EXPECT_DOUBLE_EQ(new_state_probability_in_batch(0.0, 10), 0.0);
  EXPECT_DOUBLE_EQ(new_state_probability_in_batch(0.3, 0), 0.0);
  EXPECT_THROW(new_state_probability_of_kind({1, 2}, {true}), InputError);
  EXPECT_THROW(new_state_probability_of_kind({-1}, {true}), InputError);
  EXPECT_THROW(new_state_probability_in_batch(1.5, 3), InputError);
  EXPECT_THROW(new_state_probability_in_batch(0.5, -1), InputError);
}

// The geometric states of the test above, every third of them of the kind
// (as if low in energy), 100 samples, 2,000 draws: the kind's singletons
// over all samples estimate the unseen mass of the kind without bias to
// within 15% of it on average.
TEST(Unseen, KindsUnseenMassOnKnownStates) {
  std::mt19937 rng(13);
  std::vector<double> p(60);
  std::vector<bool> kind(p.size());
  for (size_t k = 0; k < p.size(); ++k) {
    p[k] = std::pow(0.93, static_cast<double>(k));
    kind[k] = k % 3 == 0;
  }
  const double total = std::accumulate(p.begin(), p.end(), 0.0);
  const int trials = 2000;
  double mass = 0.0, estimate = 0.0;
  for (int t = 0; t < trials; ++t) {
    const std::vector<int> c = draw(p, 100, rng);
    for (size_t k = 0; k < p.size(); ++k) mass += c[k] == 0 && kind[k] ? p[k] / total / trials : 0.0;
    estimate += new_state_probability_of_kind(c, kind) / trials;
  }
  std::cout << "[ measured ] unseen mass of the kind " << mass << ", its Good-Turing estimate " << estimate
            << std::endl;
  EXPECT_GT(mass, 0.01);
  EXPECT_NEAR(estimate, mass, 0.15 * mass);
}
