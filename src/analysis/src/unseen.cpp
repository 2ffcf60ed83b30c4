#include "ek/analysis/unseen.hpp"

#include <gsl/gsl_cdf.h>

#include <cmath>
#include <map>

#include "ek/core/errors.hpp"

namespace ek {
namespace {

/// Chao1 and the variance of its unseen part, when there are singletons to
/// extrapolate from (f1 > 0 and f2 > 0, or f1 > 1 and f2 = 0).
void chao1(UnseenEstimate& e, double& variance) {
  const double n = e.samples, D = e.observed, f1 = e.singletons, f2 = e.doubletons, r = (n - 1.0) / n;
  if (f2 > 0) {
    const double q = f1 / f2;
    e.states = D + r * f1 * f1 / (2.0 * f2);
    variance = f2 * (r * q * q / 2.0 + r * r * q * q * q + r * r * q * q * q * q / 4.0);
  } else {
    e.states = D + r * f1 * (f1 - 1.0) / 2.0;
    variance = r * f1 * (f1 - 1.0) / 2.0 + r * r * f1 * (2.0 * f1 - 1.0) * (2.0 * f1 - 1.0) / 4.0 -
               r * r * f1 * f1 * f1 * f1 / (4.0 * e.states);
  }
}

/// Chao's interval for an almost complete sample (no unseen part to scale).
void complete_interval(UnseenEstimate& e, const std::map<int, int>& f, double z) {
  const double n = e.samples, D = e.observed;
  double variance = 0.0, weighted = 0.0, P = 0.0;
  for (const auto& [i, fi] : f) {
    variance += fi * (std::exp(-i) - std::exp(-2.0 * i));
    weighted += i * std::exp(-i) * fi;
    P += fi * std::exp(-i) / D;
  }
  variance = std::max(0.0, variance - weighted * weighted / n);
  const double centre = D / (1.0 - P), half = z * std::sqrt(variance) / (1.0 - P);
  e.lower = std::max(D, centre - half);
  e.upper = std::max(D, centre + half);
}

}  // namespace

UnseenEstimate estimate_unseen(const std::vector<int>& counts, const UnseenOptions& options) {
  if (!(options.confidence > 0.0 && options.confidence < 1.0))
    throw InputError("the confidence of the unseen states' interval must be in (0, 1)");
  UnseenEstimate e;
  std::map<int, int> f;  // f[i]: states seen i times
  for (int c : counts) {
    if (c < 0) throw InputError("a state's sample count is negative");
    if (c == 0) continue;
    e.samples += c;
    ++e.observed;
    ++f[c];
  }
  if (e.samples == 0) return e;
  e.singletons = f.count(1) ? f[1] : 0;
  e.doubletons = f.count(2) ? f[2] : 0;
  const double n = e.samples, f1 = e.singletons, f2 = e.doubletons;
  e.good_turing = f1 / n;
  e.new_state_probability = f1 > 0 ? f1 / n * (n - 1.0) * f1 / ((n - 1.0) * f1 + 2.0 * f2) : 0.0;
  const double z = gsl_cdf_ugaussian_Pinv(0.5 + options.confidence / 2.0);
  if (f1 > 0 && (f2 > 0 || f1 > 1)) {
    double variance = 0.0;
    chao1(e, variance);
    const double t = e.states - e.observed;  // > 0 here
    const double K = std::exp(z * std::sqrt(std::log(1.0 + std::max(variance, 0.0) / (t * t))));
    e.lower = e.observed + t / K;
    e.upper = e.observed + t * K;
  } else {  // no singleton, or one without doubletons: nothing to extrapolate
    e.states = e.observed;
    complete_interval(e, f, z);
  }
  return e;
}

double new_state_probability_of_kind(const std::vector<int>& counts, const std::vector<bool>& of_kind) {
  if (counts.size() != of_kind.size()) throw InputError("one kind flag per state's count expected");
  long n = 0, singletons = 0;
  for (size_t i = 0; i < counts.size(); ++i) {
    if (counts[i] < 0) throw InputError("a state's sample count is negative");
    n += counts[i];
    singletons += counts[i] == 1 && of_kind[i];
  }
  return n > 0 ? static_cast<double>(singletons) / static_cast<double>(n) : 0.0;
}

double new_state_probability_in_batch(double p, int batch) {
  if (!(p >= 0.0 && p <= 1.0) || batch < 0) throw InputError("a probability in [0, 1] and a batch >= 0 expected");
  return 1.0 - std::pow(1.0 - p, batch);
}

}  // namespace ek
