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

}  // namespace

int cmd_relax(int argc, char** argv) {
  std::string file, out;
  std::optional<double> link, planar;
  bool release = false, json = false, eigen = false, full = false, stop_at_saddle = false;
  std::string method = "default";
  RelaxOptions opt;
  ArgParser args("relax", "FILE [-o OUT] [--link LK] [--planar H [--release]] [--tol T] [--max-iter N] [--radius R] "
                          "[--young E] [--poisson NU] [--contact-stiffness W] [--continuation F[,F...]] [--full-model] "
                          "[--method M] [--coarse-levels L] [--factorization F] [--eigen] "
                          "[--stop-at-saddle] [--trace FILE.csv] [--verbose] [--json]");
  args.positional("FILE", &file, "closed curve (.obj or .txt); its edge lengths are the rest lengths");
  args.option("-o,--output", &out, "write the equilibrium here (.obj or .txt), atomically");
  args.option("--link", &link, "prescribe the link Lk = Tw + Wr (full model with Theta fixed); default: Theta free");
  args.option("--planar", &planar, "keep every vertex in the slab |z| < H (barrier)");
  args.flag("--release", &release, "after relaxing in the slab, drop it and continue (jumping knots)");
  args.option("--tol", &opt.tolerance, "gradient-norm tolerance (default 1e-8 scaled by EI and edge length)");
  args.option("--max-iter", &opt.max_iterations,
              "Newton iterations per phase (default " + std::to_string(RelaxOptions{}.max_iterations) + ")");
  args.option("--radius", &opt.material.radius, "wire radius r (default 0.2)");
  args.option("--young", &opt.material.young, "Young's modulus E (default 2000)");
  args.option("--poisson", &opt.material.poisson, "Poisson ratio nu (default 0.3)");
  args.option("--contact-stiffness", &opt.contact_stiffness, "contact stiffness omega (default 1e3 (E/2000)(r/0.2)^3)");
  std::string continuation;
  args.option("--continuation", &continuation,
              "contact-stiffness continuation: solve first with the stiffness times each factor F in (0, 1), "
              "in order, then at the stiffness (default: off; 1e-3 halves the run time of typical knots)");
  args.flag("--full-model", &full, "use the full model (positions, theta, Theta) even when Theta is free");
  args.flag("--eigen", &eigen, "also report the smallest non-rigid eigenvalue of the Hessian");
  args.flag("--stop-at-saddle", &stop_at_saddle, "report converged-unstable at a saddle instead of leaving it");
  args.option("--method", &method,
              "default (multilevel: coarse-to-fine from n/2 vertices with contact-stiffness continuation at the "
              "coarse level, for the twist-free model without a slab; hybrid Newton directions: projected Hessian "
              "far from equilibrium, exact near it), hybrid (hybrid Newton at n vertices from the input), "
              "exact (exact Hessian every iteration, at n) or paper (NewtonOptions::paper(), at n)");
  args.option("--coarse-levels", &opt.coarse_levels,
              "multilevel: coarse levels below n, each halving the vertices (default " +
                  std::to_string(kDefaultCoarseLevels) + ")");
  std::string factorization = "block";
  args.option("--factorization", &factorization,
              "sparse Cholesky: block (3 x 3 blocks, default) or cholmod (CHOLMOD's simplicial LL')");
  std::string trace;
  args.option("--trace", &trace,
              "write one CSV row per Newton iteration of every phase (energy and its parts, gradient norm, "
              "shift, factorisations, collision-free bound, step, active pairs, time)");
  args.flag("--verbose", &opt.newton.verbose, "print one line per Newton iteration on stderr");
  args.flag("--json", &json, "print one JSON object");
  if (!args.parse(argc, argv)) return 0;
  if (method == "hybrid") {
    opt.method = RelaxMethod::Direct;
  } else if (method == "exact") {
    opt.method = RelaxMethod::Direct;
    opt.newton.hessian = HessianMode::Exact;
  } else if (method == "paper") {
    const bool verbose = opt.newton.verbose;
    opt.method = RelaxMethod::Direct;
    opt.newton = NewtonOptions::paper();
    opt.newton.verbose = verbose;
  } else if (method != "default") {
    throw InputError("--method must be default, hybrid, exact or paper, not '" + method + "'");
  }
  if (factorization == "cholmod") opt.newton.cholesky.mode = CholeskyMode::Simplicial;
  else if (factorization != "block")
    throw InputError("--factorization must be block or cholmod, not '" + factorization + "'");
  // the factors' range (0, 1) is checked by RelaxOptions::validate() in relax()
  opt.contact_continuation = parse_number_list(continuation, "--continuation");
  if (!out.empty()) check_writable(out);
  if (!trace.empty()) check_writable(trace);
  opt.newton.record_trace = !trace.empty();
  if (release && !planar) throw InputError("--release needs --planar H");
  opt.link = link;
  opt.full_model = full;
  opt.smallest_eigenvalue = eigen;
  opt.stop_at_critical_point = stop_at_saddle;
  if (planar) {
    SlabOptions s;
    s.half_thickness = *planar;
    opt.slab = s;
    opt.release_slab = release;
  }
  const Points curve = read_curve(file);
  const RelaxResult r = relax(curve, opt);
  const NewtonReport all = r.all_phases();
  if (!out.empty() && r.alexander_preserved) write_curve(out, r.positions);
  if (!trace.empty()) {
    AtomicFile f(trace);
    write_trace_csv(f.stream(), r.trace, r.phases);
    f.commit();
  }
  if (json) {
    Json j;
    j["file"] = file;
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
    j["method"] = method;
    j["phases"] = r.phases;
    j["report"] = report_json(r.report);
    if (!r.coarse_reports.empty()) {
      Json c = Json::array();
      for (const NewtonReport& cr : r.coarse_reports) c.push_back(report_json(cr));
      j["coarse_reports"] = c;
      j["coarse_vertices"] = r.coarse_vertices;
    }
    if (!r.continuation_reports.empty()) {
      Json c = Json::array();
      for (const NewtonReport& cr : r.continuation_reports) c.push_back(report_json(cr));
      j["continuation_reports"] = c;
    }
    if (r.slab_report) {
      j["slab_report"] = report_json(*r.slab_report);
      j["slab_energy"] = energy_json(*r.slab_energy);
    }
    if (!out.empty() && r.alexander_preserved) j["output"] = out;
    if (!trace.empty()) j["trace"] = trace;
    print_json(j);
  } else {
    std::cout << "status:       " << r.status() << " (" << all.iterations << " iterations, "
              << fmt(all.seconds, 4) << " s)\n"
              << "energy:       " << fmt(r.energy.total) << " (stretch " << fmt(r.energy.stretch, 6) << ", bend "
              << fmt(r.energy.bend, 6) << ", twist " << fmt(r.energy.twist, 6) << ", contact "
              << fmt(r.energy.contact, 6) << ")\n"
              << "gradient:     " << fmt(r.report.gradient_norm, 4) << "\n"
              << "contacts:     " << r.contacts << " (closest " << fmt(r.min_distance, 6) << ")\n"
              << "link:         " << fmt(r.link) << " = twist " << fmt(r.twist) << " + writhe " << fmt(r.writhe)
              << "\n"
              << "Alexander:    " << r.result_alexander.to_string()
              << (r.alexander_preserved ? " (preserved)" : " (CHANGED: the result is rejected)") << "\n";
    if (r.smallest_eigenvalue) std::cout << "smallest eigenvalue: " << fmt(*r.smallest_eigenvalue) << "\n";
    if (!out.empty() && r.alexander_preserved) std::cout << "wrote " << out << "\n";
  }
  if (!r.alexander_preserved) {
    std::cerr << "knots relax: topology error: the Alexander polynomial changed from " << r.alexander.to_string()
              << " to " << r.result_alexander.to_string() << "; no output written" << std::endl;
    return 1;
  }
  return r.converged() ? 0 : 1;
}

}  // namespace ek::cli
