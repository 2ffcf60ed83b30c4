#pragma once
/// \file
/// The Newton solver's iteration trace (NewtonOptions::record_trace) as CSV,
/// one row per IterationRecord (newton.hpp), for `knots relax --trace` and
/// the solver benchmarks. Columns, in this order:
///
/// ~~~{.unparsed}
///   phase         index of the phase (minimize() call)
///   phase_name    its name (RelaxResult::phases), "" when not given
///   iteration     iterations taken before this one, in the phase
///   kind          step | saddle-escape | final
///   energy        [energy] E at the iterate
///   energy_<part> [energy] one column per part name met in the trace
///                 (stretch, bend, twist, contact, slab for a knot), in the
///                 order first met; 0 in rows of a phase without that part
///   gradient_norm [energy/length] ||g||₂
///   hessian       exact | projected
///   shift         [energy/length²] shift of the factorisation used
///   factorizations, failed_factorizations   numeric factorisations in the iteration
///   pattern_changed  1 when the Hessian's sparsity pattern changed
///   max_step      [1] collision-free bound of the step
///   step          [1] accepted step fraction (0: none)
///   line_search_trials, active_pairs
///   seconds       [s] wall time of the iteration
/// ~~~
#include <array>
#include <ostream>
#include <string>
#include <vector>

#include "ek/optim/newton.hpp"

namespace ek {

/// Writes the header and one row per record (17 significant digits).
void write_trace_csv(std::ostream& out, const std::vector<IterationRecord>& trace,
                     const std::vector<std::string>& phase_names = {});

}  // namespace ek

namespace ek {

/// Where a minimisation's iterations and time went, from its trace.
struct TraceSummary {
  int iterations = 0;             ///< records of kind Step or SaddleEscape
  /// Iterations by their excess energy E - E_end over the energy at the end
  /// of their phase: > 1e-1, (1e-2, 1e-1], (1e-3, 1e-2], (1e-4, 1e-3], <= 1e-4.
  std::array<int, 5> by_excess{};
  int full_steps = 0;             ///< accepted step t >= 1
  int short_steps = 0;            ///< accepted step t < 1/64 (cut by the line search or the collision bound)
  int collision_limited = 0;      ///< collision-free bound < 1
  int exact_iterations = 0;       ///< the exact Hessian's
  ///@{
  /// Sums over the records: numeric factorisations (failed included), failed
  /// factorisations, and iterations whose Hessian pattern changed.
  int factorizations = 0, failed_factorizations = 0, pattern_changes = 0;
  ///@}
  double seconds = 0.0;           ///< [s] summed iteration time
  double seconds_exact = 0.0;     ///< [s] of it in iterations with the exact Hessian
  void add(const TraceSummary& other);  ///< Adds `other`'s counts and times (summaries of several runs).
};

/// Summarises a trace (every phase; excess energies per phase).
TraceSummary summarize_trace(const std::vector<IterationRecord>& trace);

}  // namespace ek
