#pragma once
// Options shared by `knots explore` and `knots dataset`.
#include "args.hpp"
#include "ek/core/errors.hpp"
#include "ek/dataset/pipeline.hpp"

namespace ek::cli {

struct ExploreArgs {
  ExploreOptions options;
  long long seed = 1;
  bool adaptive = false;
  std::optional<int> samples;
  bool no_stiffness = false;
  bool quiet = false;
  std::string continuation;
  std::string method = "default";
  std::optional<int> coarse_levels;  ///< --coarse-levels; unset: the method's
  std::string stopping = "score";
};

/// Whether the named method relaxes knots by the multilevel method.
inline bool multilevel_method(const std::string& method) {
  return with_method(RelaxOptions{}, method).method == RelaxMethod::Multilevel;
}

inline void add_explore_options(ArgParser& args, ExploreArgs& a) {
  args.option("--samples", &a.samples, "lattice samples per knot (default 50); not with --adaptive");
  args.flag("--adaptive", &a.adaptive, "adaptive sampling: 50, then batches of 10 while the importance score S > 0.1, at most 500");
  args.option("--max-samples", &a.options.max_samples, "adaptive sampling: at most this many samples (default 500)");
  args.option("--stopping", &a.stopping,
              "adaptive sampling's rule: score (the importance score S, the paper's rule; default) or unseen (while "
              "the estimated chance of a new low-energy state in the next batch is above --new-state-threshold)");
  args.option("--new-state-threshold", &a.options.new_state_threshold,
              "adaptive sampling by the unseen rule: continue while the chance of a new low-energy state in the next "
              "batch is above this (default 0.1)");
  args.option("--novelty-distance", &a.options.novelty_distance,
              "adaptive sampling: δ, the distance 1 - similarity at which a state counts as new (default 0.1; the "
              "experiments use the cluster cut 0.05)");
  args.option("--burn-in", &a.options.burn_in,
              "lattice samples the walk makes and discards before sample 0 (default 0, at most 100000); sample k is "
              "then the walk's sample burn-in + k");
  args.option("--jobs,-j", &a.options.jobs, "relaxations in parallel (default 1)");
  args.option("--seed", &a.seed, "run seed (default 1); each knot's walk seed derives from it and the name");
  args.option("-n,--vertices", &a.options.sampling.vertices, "vertices per curve, even (default 400)");
  args.option("--radius", &a.options.relax.material.radius, "wire radius r (default 0.2)");
  args.option("--young", &a.options.relax.material.young, "Young's modulus E (default 2000)");
  args.option("--poisson", &a.options.relax.material.poisson, "Poisson ratio (default 0.3)");
  args.option("--tol", &a.options.relax.tolerance, "gradient tolerance (default 1e-8 for the default material)");
  args.option("--max-iter", &a.options.relax.max_iterations,
              "Newton iterations per relaxation (default " + std::to_string(RelaxOptions{}.max_iterations) + ")");
  args.option("--continuation", &a.continuation,
              "contact-stiffness continuation F[,F...]: each relaxation first solves with the stiffness times each "
              "factor in (0, 1), then at the stiffness (default: off; recorded in the data set)");
  args.option("--method", &a.method,
              "relaxation method as for knots relax: default (multilevel from n/4 with the contact pairs' "
              "Gauss-Newton Hessians; gauss-newton and two-level are the same), one-level (multilevel from n/2, "
              "the default before two levels), eigen-projected (one-level with the contact pairs' eigen-projected "
              "Hessians), hybrid (Newton at n from the sample), exact or paper (recorded in the data set)");
  args.option("--coarse-levels", &a.coarse_levels,
              "multilevel: coarse levels below n (default " + std::to_string(kDefaultCoarseLevels) +
                  "; 1 for one-level and eigen-projected; recorded in the data set)");
  args.flag("--no-stiffness", &a.no_stiffness, "skip the stiffness attribute (an eigenvalue per equilibrium)");
  args.flag("--quiet", &a.quiet, "no progress output");
}

/// The options of a run that holds links (explore_link): the direct method
/// and no stiffness attribute. A run of links only gets them (`--method
/// default` becomes `hybrid`); a run that mixes knots and links must ask for
/// them, so the knots' method is never changed behind the user's back.
inline void prepare_for_links(ExploreArgs& a, bool knots_too) {
  if (knots_too) {
    if (multilevel_method(a.method) || !a.no_stiffness)
      throw InputError("links are relaxed by the direct method without the stiffness attribute: give --method hybrid "
                       "(or exact, paper) and --no-stiffness to compute knots and links in one data set");
    return;
  }
  if (multilevel_method(a.method) && a.method != "default")
    throw InputError("links are relaxed by the direct method: give --method default, hybrid, exact or paper");
  if (a.method == "default") a.method = "hybrid";
  a.no_stiffness = true;
}

inline void finish_explore_options(ExploreArgs& a) {
  if (a.adaptive && a.samples) throw InputError("--samples and --adaptive exclude each other");
  if (a.seed < 0) throw InputError("--seed must be non-negative");
  a.options.seed = static_cast<std::uint64_t>(a.seed);
  a.options.adaptive = a.adaptive;
  a.options.stopping = parse_stopping_rule(a.stopping);
  if (!a.adaptive && a.options.stopping != StoppingRule::Score) throw InputError("--stopping needs --adaptive");
  if (a.samples) a.options.samples = *a.samples;
  a.options.stiffness = !a.no_stiffness;
  a.options.relax = with_method(a.options.relax, a.method);
  if (a.coarse_levels) a.options.relax.coarse_levels = *a.coarse_levels;
  a.options.relax.contact_continuation = parse_number_list(a.continuation, "--continuation");
  if (a.adaptive && a.options.max_samples < a.options.initial_samples) a.options.initial_samples = a.options.max_samples;
  a.options.validate();
}

}  // namespace ek::cli
