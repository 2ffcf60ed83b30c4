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
#include "ek/solver/relax.hpp"
#include "ek/solver/trace.hpp"
#include "output.hpp"

namespace ek::cli {
namespace {

Json energy_json(const EnergyParts& e) {
  Json j;
  j["energy"] = number(e.total);
  j["energy_stretch"] = number(e.stretch);
  j["energy_bend"] = number(e.bend);
  j["energy_twist"] = number(e.twist);
  j["energy_contact"] = number(e.contact);
  j["energy_slab"] = number(e.slab);
  return j;
}

Json report_json(const NewtonReport& r) {
  Json j;
  j["status"] = to_string(r.status);
  j["iterations"] = r.iterations;
  j["seconds"] = number(r.seconds);
  j["gradient_norm"] = number(r.gradient_norm);
  j["saddle_escapes"] = r.saddle_escapes;
  j["marginal"] = r.marginal;
  j["symbolic_factorizations"] = r.symbolic_factorizations;
  j["numeric_factorizations"] = r.numeric_factorizations;
  j["failed_factorizations"] = r.failed_factorizations;
  j["line_search_trials"] = r.line_search_trials;
  j["time_assembly"] = number(r.time_assembly);
  j["time_factorization"] = number(r.time_factorization);
  j["time_collision"] = number(r.time_collision);
  j["time_line_search"] = number(r.time_line_search);
  j["time_eigen"] = number(r.time_eigen);
  return j;
}
/// The command line of `knots relax`.
struct RelaxCommand {
  std::string file, out, method = "default", factorization = "block", continuation, trace;
  std::optional<double> link, planar;
  bool release = false, json = false, eigen = false, full = false, stop_at_saddle = false;
  RelaxOptions options;
};

/// False after --help.
bool parse_relax(int argc, char** argv, RelaxCommand& c) {
  RelaxOptions& opt = c.options;
  ArgParser args("relax", "FILE [-o OUT] [--link LK] [--planar H [--release]] [--tol T] [--max-iter N] [--radius R] "
                          "[--young E] [--poisson NU] [--contact-stiffness W] [--continuation F[,F...]] [--full-model] "
                          "[--method M] [--coarse-levels L] [--factorization F] [--eigen] "
                          "[--stop-at-saddle] [--trace FILE.csv] [--verbose] [--json]");
  args.positional("FILE", &c.file, "closed curve (.obj or .txt); its edge lengths are the rest lengths");
  args.option("-o,--output", &c.out, "write the equilibrium here (.obj or .txt), atomically");
  args.option("--link", &c.link, "prescribe the link Lk = Tw + Wr (full model with Theta fixed); default: Theta free");
  args.option("--planar", &c.planar, "keep every vertex in the slab |z| < H (barrier)");
  args.flag("--release", &c.release, "after relaxing in the slab, drop it and continue (jumping knots)");
  args.option("--tol", &opt.tolerance, "gradient-norm tolerance (default 1e-8 scaled by EI and edge length)");
  args.option("--max-iter", &opt.max_iterations,
              "Newton iterations per phase (default " + std::to_string(RelaxOptions{}.max_iterations) + ")");
  args.option("--radius", &opt.material.radius, "wire radius r (default 0.2)");
  args.option("--young", &opt.material.young, "Young's modulus E (default 2000)");
  args.option("--poisson", &opt.material.poisson, "Poisson ratio nu (default 0.3)");
  args.option("--contact-stiffness", &opt.contact_stiffness, "contact stiffness omega (default 1e3 (E/2000)(r/0.2)^3)");
  args.option("--continuation", &c.continuation,
              "contact-stiffness continuation before the solve at n vertices: first with the stiffness times each "
              "factor F in (0, 1), in order, then at the stiffness (default: off)");
  args.flag("--full-model", &c.full, "use the full model (positions, theta, Theta) even when Theta is free");
  args.flag("--eigen", &c.eigen, "also report the smallest non-rigid eigenvalue of the Hessian");
  args.flag("--stop-at-saddle", &c.stop_at_saddle, "report converged-unstable at a saddle instead of leaving it");
  args.option("--method", &c.method,
              "default (multilevel: coarse-to-fine from n/2 vertices with contact-stiffness continuation at the "
              "coarse level, for the twist-free model without a slab; hybrid Newton directions: projected Hessian "
              "far from equilibrium, exact near it), hybrid (hybrid Newton at n vertices from the input), "
              "exact (exact Hessian every iteration, at n) or paper (NewtonOptions::paper(), at n)");
  args.option("--coarse-levels", &opt.coarse_levels,
              "multilevel: coarse levels below n, each halving the vertices (default " +
                  std::to_string(kDefaultCoarseLevels) + ")");
  args.option("--factorization", &c.factorization,
              "sparse Cholesky: block (3 x 3 blocks, default) or cholmod (CHOLMOD's simplicial LL')");
  args.option("--trace", &c.trace,
              "write one CSV row per Newton iteration of every phase (energy and its parts, gradient norm, "
              "shift, factorisations, collision-free bound, step, active pairs, time)");
  args.flag("--verbose", &opt.newton.verbose, "print one line per Newton iteration on stderr");
  args.flag("--json", &c.json, "print one JSON object");
  return args.parse(argc, argv);
}

/// The relaxation's options from the command line (InputError for bad values).
RelaxOptions relax_options(const RelaxCommand& c) {
  RelaxOptions opt = with_method(c.options, c.method);
  if (c.factorization == "cholmod") opt.newton.cholesky.mode = CholeskyMode::Simplicial;
  else if (c.factorization != "block")
    throw InputError("--factorization must be block or cholmod, not '" + c.factorization + "'");
  // the factors' range (0, 1) is checked by RelaxOptions::validate() in relax()
  opt.contact_continuation = parse_number_list(c.continuation, "--continuation");
  opt.newton.record_trace = !c.trace.empty();
  if (c.release && !c.planar) throw InputError("--release needs --planar H");
  opt.link = c.link;
  opt.full_model = c.full;
  opt.smallest_eigenvalue = c.eigen;
  opt.stop_at_critical_point = c.stop_at_saddle;
  if (c.planar) {
    SlabOptions s;
    s.half_thickness = *c.planar;
    opt.slab = s;
    opt.release_slab = c.release;
  }
  return opt;
}

Json reports_json(const std::vector<NewtonReport>& reports) {
  Json a = Json::array();
  for (const NewtonReport& r : reports) a.push_back(report_json(r));
  return a;
}

Json result_json(const RelaxCommand& c, const RelaxResult& r) {
  const NewtonReport all = r.all_phases();
  Json j;
  j["file"] = c.file;
  j["status"] = r.status();
  j["converged"] = r.converged();
  j["stable"] = r.stable();
  j["iterations"] = r.report.iterations;
  j["total_iterations"] = all.iterations;
  j["seconds"] = number(all.seconds);
  const Json energies = energy_json(r.energy);
  for (auto& [k, v] : energies.items()) j[k] = v;
  j["gradient_norm"] = number(r.report.gradient_norm);
  j["contacts"] = r.contacts;
  j["min_distance"] = number(r.min_distance);
  j["link"] = number(r.link);
  j["twist"] = number(r.twist);
  j["writhe"] = number(r.writhe);
  j["alexander_preserved"] = r.alexander_preserved;
  j["alexander"] = r.alexander.coefficients;
  j["model"] = r.model;
  j["vertices"] = r.positions.rows();
  j["smallest_eigenvalue"] = r.smallest_eigenvalue ? number(*r.smallest_eigenvalue) : Json(nullptr);
  j["method"] = c.method;
  j["phases"] = r.phases;
  j["report"] = report_json(r.report);
  if (!r.coarse_reports.empty()) {
    j["coarse_reports"] = reports_json(r.coarse_reports);
    j["coarse_vertices"] = r.coarse_vertices;
  }
  if (!r.continuation_reports.empty()) j["continuation_reports"] = reports_json(r.continuation_reports);
  if (r.slab_report) {
    j["slab_report"] = report_json(*r.slab_report);
    j["slab_energy"] = energy_json(*r.slab_energy);
  }
  if (!c.out.empty() && r.alexander_preserved) j["output"] = c.out;
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
  if (!c.out.empty() && r.alexander_preserved) std::cout << "wrote " << c.out << "\n";
}

}  // namespace

int cmd_relax(int argc, char** argv) {
  RelaxCommand c;
  if (!parse_relax(argc, argv, c)) return 0;
  const RelaxOptions opt = relax_options(c);
  if (!c.out.empty()) check_writable(c.out);
  if (!c.trace.empty()) check_writable(c.trace);
  const RelaxResult r = relax(read_curve(c.file), opt);
  if (!c.out.empty() && r.alexander_preserved) write_curve(c.out, r.positions);
  if (!c.trace.empty()) {
    AtomicFile f(c.trace);
    write_trace_csv(f.stream(), r.trace, r.phases);
    f.commit();
  }
  if (c.json) print_json(result_json(c, r));
  else print_result(c, r);
  if (!r.alexander_preserved) {
    std::cerr << "knots relax: topology error: the Alexander polynomial changed from " << r.alexander.to_string()
              << " to " << r.result_alexander.to_string() << "; no output written" << std::endl;
    return 1;
  }
  return r.converged() ? 0 : 1;
}

}  // namespace ek::cli
