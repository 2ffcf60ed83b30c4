#pragma once
// The shift ladder of the Newton solver (paper Section 6, "Numerical
// Solver"): H + s·I is factorised for s on the ladder first·growth^j, j >= 0,
// and the lowest rung that factorises is used. The paper climbs from
// first = ε·λ_min every time.
//
// Warm start: each search starts one rung below the last shift instead
// (the same shift up to a factor `growth`, far fewer failed factorisations);
// when that rung has just failed, the next 1, 2, 4, ... searches start at
// the last shift itself. At convergence the search starts at ε·λ_min (the
// stability test).
//
// Hint: the climb is not made rung by rung but probes the rung below the
// shift that the same kind of Hessian (projected or exact) needed last time.
// If it fails, every lower rung fails too (H + s·I is positive definite for
// every s above its smallest eigenvalue's negative) and the climb goes on
// above it; if it factorises, the search steps down while the rung below
// also factorises and, when one fails, takes the last good rung's factor
// back (CholeskySolver::recall). The rung found is the climb's.
//
// Proven failures: a failed attempt at s reports the extra shift δ it proves
// necessary (CholeskySolver::shift_deficit()); the climb skips the rungs
// below s + δ/2, which would fail too. The rung found is still the climb's.
// Where failures are skipped the hint is not used: its steps down cost a
// successful factorisation each, more than the skipping climb (measured).
#include <cstdint>

#include "ek/optim/cholesky.hpp"
#include "ek/optim/newton.hpp"

namespace ek {

class ShiftSearch {
 public:
  /// The outcome of one search.
  struct Result {
    double shift = 0.0;  ///< the rung used; +infinity when every attempt failed
    bool base_ok = false;  ///< H + ε·λ_min·I factorised (decided only when that rung was tried)
    int attempts = 0;    ///< numeric factorisations
    int failed = 0;      ///< of which failed
  };

  /// Starts a minimisation: the warm start from ε·λ_min; the hints are kept.
  void restart(const NewtonOptions& options);
  /// Factorises H + s·I (H: upper triangle) for the lowest rung s that
  /// succeeds, from the warm start (or ε·λ_min when `converged`), with the
  /// hint of the Hessian's kind (`exact`).
  Result factorize(CholeskySolver& cholesky, const CholeskySolver::Matrix& H, std::uint64_t pattern_version,
                   bool exact, bool converged);
  /// Damping after a step the line search had to cut short: the next search
  /// starts one rung above the last shift.
  void damp();

 private:
  double rung(double first, int j) const;
  int probe_rung(double first, double hint) const;
  int search(CholeskySolver& cholesky, const CholeskySolver::Matrix& H, std::uint64_t version, double first,
             double hint, Result& result) const;
  void update_warm_start(double first, double shift);
  // The next rung to try after rung `failed` failed: the one above it, or
  // above every rung the failure proves to fail.
  int next_rung(const CholeskySolver& cholesky, double first, int failed) const;

  double base_ = 0.0, growth_ = 10.0;
  int max_attempts_ = 40;
  bool warm_start_ = true, use_hint_ = true, skip_proven_ = true;
  double start_ = 0.0, last_ = 0.0;  // warm start: first rung of the next search, last shift
  int backoff_ = 0, wait_ = 0;
  double hint_[2] = {0.0, 0.0};      // last shift of the projected [0] and the exact [1] Hessian
};

}  // namespace ek
