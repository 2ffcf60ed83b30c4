#pragma once
/// \file
/// The options of `knots relax` as a user gives them (docs/cli.md): the
/// command-line options, which are also the Python module's relax() keyword
/// arguments (snake_case of the option names), turned into RelaxOptions in
/// one place, so the command and the module relax with the same options.
#include <optional>
#include <string>
#include <vector>

#include "ek/rod/material.hpp"
#include "ek/solver/relax.hpp"

namespace ek {

/// The options of `knots relax` (and the Python module's relax()) as given,
/// before options() turns them into RelaxOptions.
struct RelaxRequest {
  std::optional<double> link;          ///< [1] --link: prescribed Lk = Tw + Wr (full model, Θ fixed); none: Θ free
  std::optional<double> planar;        ///< [length] --planar H: keep every vertex in the slab |z| < H
  bool release = false;                ///< --release: after the slab phase, drop the slab and continue
  std::optional<double> tol;           ///< [energy/length] --tol; unset: 1e-8·(EI/EI_ref)/ℓ²
  int max_iter = RelaxOptions{}.max_iterations;  ///< [1] --max-iter: Newton iterations per phase
  double radius = RodMaterial{}.radius;          ///< [length] --radius r
  double young = RodMaterial{}.young;            ///< [pressure] --young E
  double poisson = RodMaterial{}.poisson;        ///< [1] --poisson ν
  std::optional<double> contact_stiffness;  ///< [energy/length²] --contact-stiffness ω; unset: 1e3·(E/2000)·(r/0.2)³
  std::vector<double> continuation;    ///< [1] --continuation F[,F...]: factors in (0, 1); empty: off
  bool full_model = false;             ///< --full-model: positions, θ and Θ even when Θ is free
  std::string method = "default";      ///< --method: a name of method_names() (with_method())
  /// [1] --coarse-levels: multilevel levels below n; unset: the method's
  /// (kDefaultCoarseLevels; 1 for one-level and eigen-projected).
  std::optional<int> coarse_levels;
  std::string factorization = "block"; ///< --factorization: block or cholmod
  bool eigen = false;                  ///< --eigen: also the smallest non-rigid Hessian eigenvalue
  bool stop_at_saddle = false;         ///< --stop-at-saddle: report converged-unstable at a saddle
  bool trace = false;                  ///< record every Newton iteration (--trace FILE.csv writes them)
  bool verbose = false;                ///< --verbose: one line per Newton iteration on stderr

  /// The relaxation's options. Throws InputError, naming the option, for a
  /// value no relaxation accepts (an unknown method or factorisation,
  /// --release without --planar, a continuation factor outside (0, 1), ...).
  RelaxOptions options() const;
};

/// Empty when the result kept the input's knot or link type; otherwise one
/// line (a topology error: the result must not be used): for a knot "the
/// Alexander polynomial changed from [..] to [..]", for a link what changed,
/// e.g. "a linking number and the Conway polynomial of the link changed".
std::string topology_change(const RelaxResult& result);

/// Writes the result's iteration trace (RelaxRequest::trace) as CSV
/// (trace.hpp) to `path`, atomically.
void write_trace_file(const std::string& path, const RelaxResult& result);

}  // namespace ek
