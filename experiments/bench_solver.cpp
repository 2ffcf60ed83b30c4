// Macro benchmark of the equilibrium solver (docs/performance.md).
//
// A fixed set of BFACF lattice samples (fixed seeds; default 20 each of 4_1,
// 8_19, 10_100 and 12a_1019 with n = 400 unit edges) is relaxed one after the
// other on the calling thread with the default material (E = 2000, r = 0.2)
// and tolerance (1e-8). For every knot and overall it prints and writes the
// median wall time per equilibrium, the median number of Newton iterations,
// the statuses, and the time split (assembly, factorisation, collision
// detection, line search, eigen-analysis). Pin it to one core for a
// measurement: `taskset -c 1 build/experiments/exp_bench_solver`.
//
//   exp_bench_solver [--quick] [--count K] [--knots A,B,...] [--seed S] [--out DIR]
//                    [--method default|projected|paper] [--continuation F[,F...]] [--max-iter N]
//                    [--trace] [--verbose] [--skips]
//
// --trace: every relaxation records its iteration trace (NewtonOptions::
// record_trace; a few percent slower), written to DIR/traces/<knot>-<sample>.csv
// (trace.hpp), and the benchmark prints where the iterations and the time
// went per knot (summarize_trace: iterations by excess energy over the end
// of their phase, full and short steps, steps cut by the collision bound,
// failed factorisations, time in exact-Hessian iterations), also written to
// DIR/solver_trace_summary.csv.
//
// --skips ("skip what a scene does not need", measured on and off):
// every sample is relaxed three times, one after the other: as by default
// (Θ free: the twist-free 3n-dof path; no eigen-analysis), with the full
// 4n+1-dof model (RelaxOptions::full_model, the twist-free skip off), and
// with the smallest non-rigid eigenvalue computed (the stiffness attribute
// of the data set, RelaxOptions::smallest_eigenvalue: the eigen-analysis
// skip off). Writes DIR/solver_skips.csv (one row per variant: runs,
// converged-stable, total and median seconds, median iterations).
//
// --method projected: the hybrid Hessian without its exact region
// (NewtonOptions::exact_after_full_steps = 0).
// --continuation F[,F...]: contact-stiffness continuation
// (RelaxOptions::contact_continuation; e.g. 1e-3): times, iterations and
// the split count every phase; the method column reads e.g.
// "default+continuation(0.001)".
// --quick: 2 samples per knot (smoke test). --method paper: the paper's plain
// method (NewtonOptions::paper(): the exact Hessian every iteration, no
// rigid-motion removal), for before/after comparisons. Writes DIR/solver_macro.csv (one row per knot and one "all"
// row) and DIR/solver_macro_runs.csv (one row per sample, with the energy,
// contacts and gradient norm at the result, to compare methods sample by
// sample). Exit status 1 when a run changed the knot type (its Alexander
// polynomial); other statuses (max-iterations, stalled) are measured
// outcomes, counted in the table.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "ek/core/errors.hpp"
#include "ek/knots/table.hpp"
#include "ek/lattice/lattice_polygon.hpp"
#include "ek/lattice/sampling.hpp"
#include "ek/solver/relax.hpp"
#include "ek/solver/trace.hpp"

namespace {

using Clock = std::chrono::steady_clock;

struct Run {
  std::string knot;
  int sample = 0;
  double seconds = 0.0;  // wall time of relax() (including the Alexander checks)
  ek::RelaxResult result;
};

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

/// One relaxation, timed on the calling thread (including the Alexander checks).
Run timed_relax(const std::string& knot, int sample, const ek::Points& P, const ek::RelaxOptions& options) {
  Run run;
  run.knot = knot;
  run.sample = sample;
  const auto t0 = Clock::now();
  run.result = ek::relax(P, options);
  run.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  return run;
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, sep))
    if (!item.empty()) out.push_back(item);
  return out;
}

std::string fmt(double x, const char* f = "%.4g") {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, x);
  return buf;
}

void write_atomic(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::trunc);
    if (!out) throw ek::InputError("cannot write " + tmp);
    out << text;
    if (!out.flush()) throw ek::InputError("cannot write " + tmp);
  }
  std::filesystem::rename(tmp, path);
}

struct Summary {
  std::string name;
  int runs = 0, stable = 0;
  std::map<std::string, int> statuses;
  double median_seconds = 0.0, mean_seconds = 0.0, max_seconds = 0.0, median_iterations = 0.0;
  double assembly = 0.0, factorization = 0.0, collision = 0.0, line_search = 0.0, eigen = 0.0, other = 0.0;
  double symbolic = 0.0, numeric = 0.0, failed = 0.0;  // per run (mean); failed: shift-ladder rungs
};

Summary summarize(const std::string& name, const std::vector<const Run*>& runs) {
  Summary s;
  s.name = name;
  s.runs = static_cast<int>(runs.size());
  std::vector<double> secs, its;
  double total = 0.0;
  for (const Run* r : runs) {
    const ek::NewtonReport rep = r->result.all_phases();
    secs.push_back(r->seconds);
    its.push_back(rep.iterations);
    total += r->seconds;
    s.max_seconds = std::max(s.max_seconds, r->seconds);
    ++s.statuses[r->result.status()];
    if (r->result.status() == "converged-stable") ++s.stable;
    s.assembly += rep.time_assembly;
    s.factorization += rep.time_factorization;
    s.collision += rep.time_collision;
    s.line_search += rep.time_line_search;
    s.eigen += rep.time_eigen;
    s.symbolic += rep.symbolic_factorizations;
    s.numeric += rep.numeric_factorizations;
    s.failed += rep.failed_factorizations;
  }
  s.median_seconds = median(secs);
  s.median_iterations = median(its);
  if (!runs.empty()) {
    s.mean_seconds = total / s.runs;
    s.symbolic /= s.runs;
    s.numeric /= s.runs;
    s.failed /= s.runs;
  }
  // time split as fractions of the summed wall time
  if (total > 0.0) {
    s.other = (total - s.assembly - s.factorization - s.collision - s.line_search - s.eigen) / total;
    s.assembly /= total;
    s.factorization /= total;
    s.collision /= total;
    s.line_search /= total;
    s.eigen /= total;
  }
  return s;
}

std::string statuses_text(const Summary& s) {
  std::string out;
  for (const auto& [k, v] : s.statuses) out += (out.empty() ? "" : " ") + k + ":" + std::to_string(v);
  return out;
}

/// Where the iterations and the time went, per knot (from the traces).
void print_trace_summary(const std::vector<std::string>& knots, const std::vector<Run>& runs, const std::string& out) {
  std::ostringstream csv;
  csv << "knot,iterations,excess_above_1e-1,excess_1e-2_1e-1,excess_1e-3_1e-2,excess_1e-4_1e-3,excess_below_1e-4,"
         "full_steps,short_steps,collision_limited,exact_iterations,factorizations,failed_factorizations,"
         "pattern_changes,seconds,seconds_exact\n";
  std::printf("where the iterations went (%% of iterations; excess energy over the end of the phase)\n");
  std::printf("%-9s %7s | %6s %6s %6s %6s %6s | %6s %6s %6s %6s | %7s %7s\n", "knot", "iters", ">1e-1", ">1e-2",
              ">1e-3", ">1e-4", "<1e-4", "t=1", "t<1/64", "ccd<1", "exact", "fail/fc", "exact s");
  auto row = [&](const std::string& name, const ek::TraceSummary& s) {
    const double it = std::max(1, s.iterations);
    std::printf("%-9s %7d | %5.1f%% %5.1f%% %5.1f%% %5.1f%% %5.1f%% | %5.1f%% %5.1f%% %5.1f%% %5.1f%% | %6.1f%% %6.1f%%\n",
                name.c_str(), s.iterations, 100 * s.by_excess[0] / it, 100 * s.by_excess[1] / it,
                100 * s.by_excess[2] / it, 100 * s.by_excess[3] / it, 100 * s.by_excess[4] / it,
                100 * s.full_steps / it, 100 * s.short_steps / it, 100 * s.collision_limited / it,
                100 * s.exact_iterations / it, 100.0 * s.failed_factorizations / std::max(1, s.factorizations),
                100 * s.seconds_exact / std::max(1e-300, s.seconds));
    csv << name << "," << s.iterations;
    for (int b : s.by_excess) csv << "," << b;
    csv << "," << s.full_steps << "," << s.short_steps << "," << s.collision_limited << "," << s.exact_iterations << ","
        << s.factorizations << "," << s.failed_factorizations << "," << s.pattern_changes << ","
        << fmt(s.seconds, "%.6g") << "," << fmt(s.seconds_exact, "%.6g") << "\n";
  };
  ek::TraceSummary all;
  for (const std::string& k : knots) {
    ek::TraceSummary s;
    for (const Run& r : runs)
      if (r.knot == k) s.add(ek::summarize_trace(r.result.trace));
    row(k, s);
    all.add(s);
  }
  row("all", all);
  write_atomic(out + "/solver_trace_summary.csv", csv.str());
}

void write_trace(const std::string& out, const Run& run) {
  std::ostringstream text;
  ek::write_trace_csv(text, run.result.trace, run.result.phases);
  write_atomic(out + "/traces/" + run.knot + "-" + std::to_string(run.sample) + ".csv", text.str());
}

int usage(const char* msg) {
  if (msg) std::cerr << "exp_bench_solver: " << msg << "\n";
  std::cerr << "usage: exp_bench_solver [--quick] [--count K] [--knots A,B,...] [--seed S] [--out DIR] "
               "[--method default|projected|paper] [--continuation F[,F...]] [--max-iter N] [--trace] [--verbose] "
               "[--skips]\n";
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> knots = {"4_1", "8_19", "10_100", "12a_1019"};
  int count = 20;
  std::uint64_t seed = 20230806;
  std::string out = "results/bench", method = "default";
  int max_iter = -1;
  std::vector<double> continuation;
  bool verbose = false, skips = false, trace = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw ek::InputError(a + " needs a value");
      return argv[++i];
    };
    try {
      if (a == "--quick") count = 2;
      else if (a == "--count") count = std::stoi(value());
      else if (a == "--knots") knots = split(value(), ',');
      else if (a == "--seed") seed = std::stoull(value());
      else if (a == "--out") out = value();
      else if (a == "--method") method = value();
      else if (a == "--max-iter") max_iter = std::stoi(value());
      else if (a == "--continuation")
        for (const std::string& f : split(value(), ',')) continuation.push_back(std::stod(f));
      else if (a == "--verbose") verbose = true;
      else if (a == "--trace") trace = true;
      else if (a == "--skips") skips = true;
      else if (a == "--help" || a == "-h") return usage(nullptr), 0;
      else return usage(("unknown argument " + a).c_str());
    } catch (const std::exception& e) {
      return usage(e.what());
    }
  }
  if (count < 1 || knots.empty()) return usage("need at least one knot and one sample");
  if (method != "default" && method != "paper" && method != "projected")
    return usage("--method must be default, projected or paper");

  ek::RelaxOptions options;
  if (method == "paper") options.newton = ek::NewtonOptions::paper();
  if (method == "projected") options.newton.exact_after_full_steps = 0;  // hybrid without the exact region
  if (max_iter >= 0) options.max_iterations = max_iter;
  options.newton.verbose = verbose;
  options.newton.record_trace = trace;
  options.contact_continuation = continuation;
  try {
    options.validate();
  } catch (const ek::InputError& e) {
    return usage(e.what());
  }
  if (!continuation.empty()) {
    method += "+continuation(";
    for (size_t k = 0; k < continuation.size(); ++k) method += (k ? ";" : "") + fmt(continuation[k], "%g");
    method += ")";
  }

  try {
    std::filesystem::create_directories(out);
    if (trace) std::filesystem::create_directories(out + "/traces");
    std::vector<Run> runs;
    const std::vector<std::string> skip_variants = {"default", "full-model", "eigen"};
    std::vector<std::vector<Run>> skip_runs(skip_variants.size());
    for (size_t k = 0; k < knots.size(); ++k) {
      ek::SampleOptions so;
      so.vertices = 400;
      so.count = count;
      so.seed = seed + k;  // one fixed walk per knot
      const ek::SampleBatch batch = ek::sample_knot(ek::KnotTable::global().at(knots[k]), so);
      if (skips) {
        for (int s = 0; s < count; ++s) {
          const ek::Points P = ek::to_points(batch.samples[static_cast<size_t>(s)]);
          for (size_t v = 0; v < skip_variants.size(); ++v) {
            ek::RelaxOptions vo = options;
            vo.full_model = v == 1;
            vo.smallest_eigenvalue = v == 2;
            Run run = timed_relax(knots[k], s, P, vo);
            std::fprintf(stderr, "%-9s #%02d  %-11s %-18s %5d it  %7.3f s  E %.10g\n", knots[k].c_str(), s,
                         skip_variants[v].c_str(), run.result.status().c_str(), run.result.all_phases().iterations,
                         run.seconds, run.result.energy.total);
            skip_runs[v].push_back(std::move(run));
          }
        }
        continue;
      }
      for (int s = 0; s < count; ++s) {
        Run run = timed_relax(knots[k], s, ek::to_points(batch.samples[static_cast<size_t>(s)]), options);
        std::fprintf(stderr, "%-9s #%02d  %-18s %5d it  %7.3f s  E %.10g  contacts %d\n", run.knot.c_str(), s,
                     run.result.status().c_str(), run.result.all_phases().iterations, run.seconds,
                     run.result.energy.total, run.result.contacts);
        if (trace) write_trace(out, run);
        runs.push_back(std::move(run));
      }
    }

    if (skips) {
      std::ostringstream csv;
      csv << "variant,runs,converged_stable,total_seconds,median_seconds,median_iterations\n";
      std::printf("solver skips (n = 400, %d samples each of %zu knots, one after the other)\n", count, knots.size());
      std::printf("%-11s %5s %7s %9s %9s %7s\n", "variant", "runs", "stable", "total s", "median s", "med it");
      bool topology_kept = true;
      for (size_t v = 0; v < skip_variants.size(); ++v) {
        std::vector<const Run*> sel;
        for (const Run& r : skip_runs[v]) sel.push_back(&r);
        const Summary sm = summarize(skip_variants[v], sel);
        const double total = sm.mean_seconds * sm.runs;
        topology_kept = topology_kept && !sm.statuses.count("topology-changed");
        std::printf("%-11s %5d %7d %9.3f %9.3f %7.0f\n", sm.name.c_str(), sm.runs, sm.stable, total,
                    sm.median_seconds, sm.median_iterations);
        csv << sm.name << "," << sm.runs << "," << sm.stable << "," << fmt(total, "%.6g") << ","
            << fmt(sm.median_seconds, "%.6g") << "," << sm.median_iterations << "\n";
      }
      write_atomic(out + "/solver_skips.csv", csv.str());
      std::printf("wrote %s/solver_skips.csv\n", out.c_str());
      return topology_kept ? 0 : 1;
    }
    std::vector<Summary> table;
    std::vector<const Run*> all;
    for (const Run& r : runs) all.push_back(&r);
    for (const std::string& k : knots) {
      std::vector<const Run*> sel;
      for (const Run& r : runs)
        if (r.knot == k) sel.push_back(&r);
      table.push_back(summarize(k, sel));
    }
    table.push_back(summarize("all", all));

    std::ostringstream csv;
    csv << "knot,method,runs,converged_stable,statuses,median_seconds,mean_seconds,max_seconds,median_iterations,"
           "symbolic_per_run,numeric_per_run,frac_assembly,frac_factorization,frac_collision,frac_line_search,"
           "frac_eigen,frac_other,failed_per_run\n";
    std::printf("solver macro benchmark (n = 400, %d samples per knot, method %s)\n", count, method.c_str());
    std::printf("%-9s %5s %7s %9s %9s %9s %7s %7s %7s %8s | %6s %6s %6s %6s %6s %6s | %s\n", "knot", "runs",
                "stable", "median s", "mean s", "max s", "med it", "sym/run", "num/run", "fail/run", "asm", "fact", "ccd",
                "ls", "eig", "other", "statuses");
    for (const Summary& s : table) {
      std::printf("%-9s %5d %7d %9.3f %9.3f %9.3f %7.0f %7.0f %7.0f %8.0f | %5.1f%% %5.1f%% %5.1f%% %5.1f%% %5.1f%% %5.1f%% | %s\n",
                  s.name.c_str(), s.runs, s.stable, s.median_seconds, s.mean_seconds, s.max_seconds,
                  s.median_iterations, s.symbolic, s.numeric, s.failed, 100 * s.assembly, 100 * s.factorization,
                  100 * s.collision, 100 * s.line_search, 100 * s.eigen, 100 * s.other, statuses_text(s).c_str());
      csv << s.name << "," << method << "," << s.runs << "," << s.stable << "," << statuses_text(s) << ","
          << fmt(s.median_seconds, "%.6g") << "," << fmt(s.mean_seconds, "%.6g") << "," << fmt(s.max_seconds, "%.6g")
          << "," << s.median_iterations << "," << fmt(s.symbolic, "%.6g") << "," << fmt(s.numeric, "%.6g") << ","
          << fmt(s.assembly, "%.4f") << "," << fmt(s.factorization, "%.4f") << "," << fmt(s.collision, "%.4f")
          << "," << fmt(s.line_search, "%.4f") << "," << fmt(s.eigen, "%.4f") << "," << fmt(s.other, "%.4f")
          << "," << fmt(s.failed, "%.6g") << "\n";
    }
    std::ostringstream runs_csv;
    runs_csv << "knot,sample,method,status,seconds,iterations,energy,gradient_norm,contacts,min_distance,writhe,"
                "symbolic,numeric,line_search_trials,saddle_escapes,marginal,failed\n";
    for (const Run& r : runs) {
      const ek::NewtonReport rep = r.result.all_phases();
      runs_csv << r.knot << "," << r.sample << "," << method << "," << r.result.status() << ","
               << fmt(r.seconds, "%.6g") << "," << rep.iterations << "," << fmt(r.result.energy.total, "%.15g") << ","
               << fmt(rep.gradient_norm, "%.3e") << "," << r.result.contacts << ","
               << fmt(r.result.min_distance, "%.6g") << "," << fmt(r.result.writhe, "%.6g") << ","
               << rep.symbolic_factorizations << "," << rep.numeric_factorizations << "," << rep.line_search_trials
               << "," << rep.saddle_escapes << "," << (rep.marginal ? 1 : 0) << "," << rep.failed_factorizations
               << "\n";
    }
    if (trace) print_trace_summary(knots, runs, out);
    write_atomic(out + "/solver_macro.csv", csv.str());
    write_atomic(out + "/solver_macro_runs.csv", runs_csv.str());
    std::printf("wrote %s/solver_macro.csv and %s/solver_macro_runs.csv\n", out.c_str(), out.c_str());
    return table.back().statuses.count("topology-changed") ? 1 : 0;
  } catch (const ek::InputError& e) {
    std::cerr << "exp_bench_solver: " << e.what() << "\n";
    return 2;
  }
}
