// knots relax FILE [-o OUT] [--link LK] [--planar H [--release]] [--tol T] [--max-iter N]
//             [--radius R] [--young E] [--poisson NU] [--contact-stiffness W] [--continuation F[,F...]]
//             [--full-model] [--method M] [--coarse-levels L] [--factorization F] [--eigen] [--stop-at-saddle]
//             [--trace FILE.csv] [--verbose] [--json]
#include <algorithm>
#include <iostream>

#include "args.hpp"
#include "commands.hpp"
#include "ek/core/atomic_file.hpp"
#include "ek/core/errors.hpp"
#include "ek/geometry/curve_io.hpp"
#include "ek/geometry/link.hpp"
#include "ek/solver/json.hpp"
#include "ek/solver/relax_request.hpp"
#include "output.hpp"

namespace ek::cli {
namespace {

/// The command line of `knots relax`.
struct RelaxCommand {
  std::string file, out, continuation, trace;
  bool json = false;
  RelaxRequest request;
};

/// False after --help.
bool parse_relax(int argc, char** argv, RelaxCommand& c) {
  RelaxRequest& r = c.request;
  ArgParser args("relax", "FILE [-o OUT] [--link LK] [--planar H [--release]] [--tol T] [--max-iter N] [--radius R] "
                          "[--young E] [--poisson NU] [--contact-stiffness W] [--continuation F[,F...]] [--full-model] "
                          "[--method M] [--coarse-levels L] [--factorization F] [--eigen] "
                          "[--stop-at-saddle] [--trace FILE.csv] [--verbose] [--json]");
  args.positional("FILE", &c.file,
                  "closed curve or link (.obj or .txt, docs/cli.md 'Curve files'); its edge lengths are the rest "
                  "lengths");
  args.option("-o,--output", &c.out, "write the equilibrium here (.obj or .txt), atomically");
  args.option("--link", &r.link, "prescribe the link Lk = Tw + Wr (full model with Theta fixed); default: Theta free");
  args.option("--planar", &r.planar, "keep every vertex in the slab |z| < H (barrier)");
  args.flag("--release", &r.release, "after relaxing in the slab, drop it and continue (jumping knots)");
  args.option("--tol", &r.tol, "gradient-norm tolerance (default 1e-8 scaled by EI and edge length)");
  args.option("--max-iter", &r.max_iter,
              "Newton iterations per phase (default " + std::to_string(RelaxOptions{}.max_iterations) + ")");
  args.option("--radius", &r.radius, "wire radius r (default 0.2)");
  args.option("--young", &r.young, "Young's modulus E (default 2000)");
  args.option("--poisson", &r.poisson, "Poisson ratio nu (default 0.3)");
  args.option("--contact-stiffness", &r.contact_stiffness, "contact stiffness omega (default 1e3 (E/2000)(r/0.2)^3)");
  args.option("--continuation", &c.continuation,
              "contact-stiffness continuation before the solve at n vertices: first with the stiffness times each "
              "factor F in (0, 1), in order, then at the stiffness (default: off)");
  args.flag("--full-model", &r.full_model, "use the full model (positions, theta, Theta) even when Theta is free");
  args.flag("--eigen", &r.eigen, "also report the smallest non-rigid eigenvalue of the Hessian");
  args.flag("--stop-at-saddle", &r.stop_at_saddle, "report converged-unstable at a saddle instead of leaving it");
  args.option("--method", &r.method,
              "default (multilevel: coarse-to-fine from n/4 vertices with contact-stiffness continuation at the "
              "coarsest level, for the twist-free model without a slab; a level below n/2 of at least 100 "
              "vertices, a crowded level's coarsening retried after soft iterations; hybrid Newton directions: "
              "projected Hessian far from equilibrium, exact near it; the contact pairs' Gauss-Newton Hessians in "
              "the projected iterations), gauss-newton and two-level (the same as default), one-level (the default "
              "from n/2 vertices, as before two levels), eigen-projected (one-level with the contact pairs' "
              "eigen-projected Hessians), hybrid (hybrid Newton at n vertices from the input), exact (exact "
              "Hessian every iteration, at n) or paper (NewtonOptions::paper(), at n)");
  args.option("--coarse-levels", &r.coarse_levels,
              "multilevel: coarse levels below n, each halving the vertices (default " +
                  std::to_string(kDefaultCoarseLevels) + "; 1 for one-level and eigen-projected)");
  args.option("--factorization", &r.factorization,
              "sparse Cholesky: block (3 x 3 blocks, default) or cholmod (CHOLMOD's simplicial LL')");
  args.option("--trace", &c.trace,
              "write one CSV row per Newton iteration of every phase (energy and its parts, gradient norm, "
              "shift, factorisations, collision-free bound, step, active pairs, time)");
  args.flag("--verbose", &r.verbose, "print one line per Newton iteration on stderr");
  args.flag("--json", &c.json, "print one JSON object");
  if (!args.parse(argc, argv)) return false;
  r.continuation = parse_number_list(c.continuation, "--continuation");
  r.trace = !c.trace.empty();
  return true;
}

Json result_json(const RelaxCommand& c, const RelaxResult& r) {
  Json j;
  j["file"] = c.file;
  j.update(relax_json(r, c.request.method));
  if (!c.out.empty() && r.topology_preserved()) j["output"] = c.out;
  if (!c.trace.empty()) j["trace"] = c.trace;
  return j;
}

void print_result(const RelaxCommand& c, const RelaxResult& r) {
  const NewtonReport all = r.all_phases();
  std::cout << "status:       " << r.status() << " (" << all.iterations << " iterations, " << fmt(all.seconds, 4)
            << " s)\n"
            << "energy:       " << fmt(r.energy.total) << " (stretch " << fmt(r.energy.stretch, 6) << ", bend "
            << fmt(r.energy.bend, 6) << ", twist " << fmt(r.energy.twist, 6) << ", contact "
            << fmt(r.energy.contact, 6) << ")\n"
            << "gradient:     " << fmt(r.report.gradient_norm, 4) << "\n"
            << "contacts:     " << r.contacts << " (closest " << fmt(r.min_distance, 6) << ")\n"
            << "link:         " << fmt(r.link) << " = twist " << fmt(r.twist) << " + writhe " << fmt(r.writhe) << "\n"
            << "Alexander:    " << r.result_alexander.to_string()
            << (r.alexander_preserved ? " (preserved)" : " (CHANGED: the result is rejected)") << "\n";
  if (r.smallest_eigenvalue) std::cout << "smallest eigenvalue: " << fmt(*r.smallest_eigenvalue) << "\n";
  if (!c.out.empty() && r.topology_preserved()) std::cout << "wrote " << c.out << "\n";
}

/// The JSON keys of `knots relax` on a link (docs/cli.md).
Json link_result_json(const RelaxCommand& c, const RelaxResult& r) {
  Json j;
  j["file"] = c.file;
  j.update(link_relax_json(r));
  if (!c.out.empty() && r.topology_preserved()) j["output"] = c.out;
  return j;
}

/// The options of `knots relax` that a link of several components does not have (InputError).
void check_link_request(const RelaxCommand& c, const Link& link) {
  const RelaxRequest& q = c.request;
  if (q.link || q.planar || q.release || q.full_model || q.eigen || q.stop_at_saddle || !c.trace.empty())
    throw InputError("--link, --planar, --release, --full-model, --eigen, --stop-at-saddle and --trace apply to a "
                     "knot, not to a link of " + std::to_string(link.size()) + " components");
}

void print_link_result(const RelaxCommand& c, const RelaxResult& r) {
  const bool kept = r.topology_preserved();
  std::cout << "components:   " << r.component_sizes.size() << "\n"
            << "status:       " << r.status() << " (" << r.report.iterations << " iterations, "
            << fmt(r.report.seconds, 4) << " s)\n"
            << "energy:       " << fmt(r.energy.total) << "\n"
            << "gradient:     " << fmt(r.report.gradient_norm, 4) << "\n"
            << "closest:      " << fmt(r.min_distance, 6) << "\n"
            << "topology:     " << (kept ? "every component's Alexander polynomial, every linking number and the Conway polynomial kept"
                                         : "CHANGED: the result is rejected")
            << "\n";
  if (!c.out.empty() && kept) std::cout << "wrote " << c.out << "\n";
}

}  // namespace

int cmd_relax(int argc, char** argv) {
  RelaxCommand c;
  if (!parse_relax(argc, argv, c)) return 0;
  if (!c.out.empty()) check_writable(c.out);
  const Link link = read_link(c.file);  // a curve file is a link of one component
  const bool several = link.size() > 1;
  if (several) check_link_request(c, link);
  if (!c.trace.empty()) check_writable(c.trace);
  const RelaxResult r = relax(link, c.request.options());
  const bool kept = r.topology_preserved();
  if (!c.out.empty() && kept) write_link(c.out, r.components());  // one component: as write_curve()
  if (!c.trace.empty()) write_trace_file(c.trace, r);
  if (c.json) print_json(several ? link_result_json(c, r) : result_json(c, r));
  else if (several) print_link_result(c, r);
  else print_result(c, r);
  if (!kept) {
    std::cerr << "knots relax: topology error: " << topology_change(r) << "; no output written" << std::endl;
    return 1;
  }
  return r.converged() ? 0 : 1;
}

}  // namespace ek::cli
