#include "shift_search.hpp"

#include <algorithm>
#include <limits>

namespace ek {

void ShiftSearch::restart(const NewtonOptions& o) {
  base_ = o.shift_epsilon * o.lambda_min;
  growth_ = o.shift_growth;
  max_attempts_ = o.max_shift_attempts;
  warm_start_ = o.shift_warm_start;
  use_hint_ = o.shift_hint;
  skip_proven_ = o.shift_skip_proven;
  start_ = last_ = base_;
  backoff_ = wait_ = 0;
}

double ShiftSearch::rung(double first, int j) const {
  double s = first;  // by repeated multiplication, as the climb makes it
  for (int k = 0; k < j; ++k) s *= growth_;
  return s;
}

int ShiftSearch::probe_rung(double first, double hint) const {
  if (!use_hint_ || !(hint > first)) return 0;
  int j = 0;
  for (double s = first; s < hint * (1.0 - 1e-12) && j < max_attempts_; s *= growth_) ++j;
  return j - 1;  // the hint's rung minus one
}

int ShiftSearch::next_rung(const CholeskySolver& cholesky, double first, int failed) const {
  int j = failed + 1;
  if (!skip_proven_) return j;
  const double proven = rung(first, failed) + 0.5 * cholesky.shift_deficit();
  for (double s = rung(first, j); j < max_attempts_ && s < proven; s *= growth_) ++j;
  return j;
}

int ShiftSearch::search(CholeskySolver& cholesky, const CholeskySolver::Matrix& H, std::uint64_t version,
                        double first, double hint, Result& result) const {
  auto attempt = [&](int j) {
    const bool ok = cholesky.factorize(H, rung(first, j), version);
    ++result.attempts;
    if (!ok) ++result.failed;
    return ok;
  };
  const bool skips = skip_proven_ && cholesky.reports_shift_deficit();
  const int probe = skips ? 0 : probe_rung(first, hint);  // with skips the climb is cheaper than the hint
  if (probe > 0 && attempt(probe)) {
    int found = probe;
    while (found > 0 && attempt(found - 1)) --found;
    if (found > 0 && !cholesky.recall(rung(first, found))) return -1;  // (cannot fail: same analysis, same H)
    return found;
  }
  for (int j = probe > 0 ? next_rung(cholesky, first, probe) : 0; j < max_attempts_;
       j = next_rung(cholesky, first, j))
    if (attempt(j)) return j;
  return -1;
}

void ShiftSearch::update_warm_start(double first, double shift) {
  // Next time try one rung lower, unless that rung has just failed; then
  // wait 1, 2, 4, ... searches before retrying it (a shift that stays
  // needed costs no failed attempts).
  if (shift > first) {
    backoff_ = std::min(2 * backoff_ + 1, 64);
    wait_ = backoff_;
  } else if (shift < last_) {
    backoff_ = 0;
  }
  last_ = shift;
  if (wait_ > 0) {
    --wait_;
    start_ = shift;
  } else {
    start_ = std::max(base_, shift / growth_);
  }
}

void ShiftSearch::damp() {
  start_ = std::max(base_, last_ * growth_);
  wait_ = 0;
}

ShiftSearch::Result ShiftSearch::factorize(CholeskySolver& cholesky, const CholeskySolver::Matrix& H,
                                           std::uint64_t pattern_version, bool exact, bool converged) {
  Result result;
  const double first = converged || !warm_start_ ? base_ : start_;
  const int found = search(cholesky, H, pattern_version, first, hint_[exact ? 1 : 0], result);
  result.base_ok = found == 0 && first <= base_;
  if (found < 0) {
    result.shift = std::numeric_limits<double>::infinity();
    return result;
  }
  result.shift = rung(first, found);
  hint_[exact ? 1 : 0] = result.shift;
  update_warm_start(first, result.shift);
  return result;
}

}  // namespace ek
