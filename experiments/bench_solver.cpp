// Macro benchmark of the equilibrium solver (docs/performance.md).
//
// A fixed set of BFACF lattice samples (fixed seeds; default 20 each of 4_1,
// 8_19, 10_100 and 12a_1019 with n = 400 unit edges) is relaxed on the
// calling thread with the default material (E = 2000, r = 0.2) and
// tolerance (1e-8), by each method asked for, the methods interleaved sample
// by sample (their order rotating) so that a drift of the machine's speed
// affects them alike. For every method and knot it prints and writes the
// median wall time per equilibrium (and thread CPU time), the median number
// of Newton iterations over all phases, the statuses and the time split
// (assembly, factorisation, collision detection, line search,
// eigen-analysis); with two methods, the ratio of their medians. Pin it to
// one core: `taskset -c 1 build/experiments/exp_bench_solver`.
//
//   exp_bench_solver --out DIR [--quick] [--count K] [--knots A,B,...] [--seed S]
//                    [--methods M[,M...]] [--continuation F[,F...]] [--max-iter N]
//                    [--trace] [--verbose] [--skips] [--peer DIR] [--scaling]
//
// Methods: default (RelaxOptions{}: multilevel), hybrid-simplicial (Direct,
// hybrid Hessian, CHOLMOD's simplicial LL': the direct method without the
// multilevel relaxation and the block factorisation), hybrid (Direct with the
// block factorisation), projected (hybrid without its exact region), exact (the
// exact Hessian every iteration), paper (NewtonOptions::paper()), levels3
// (default with three coarse levels, n/8, n/4 and n/2), levels1 (default
// with one, n/2, found by the default's coarsening, with its margin),
// gauss-newton and two-level (the same as default), one-level (one coarse level, n/2, no
// contact-pattern margin, the odd vertices collapsed: the default before two
// levels), eigen-projected (one-level with each contact pair's Hessian
// eigen-projected and no damping of short steps), no-skip (default climbing
// every rung of the shift ladder: NewtonOptions::shift_skip_proven off; the
// ladder then searched around the last shift, shift_hint), no-recheck (default
// with coarse levels of either parity but no soft iterations between tries),
// even-only (default with only the odd vertices collapsed, tried once),
// margin=X (default with the contact pattern's margin X, a length), soft=F[/G]
// (default with the coarsest level's continuation factors F, G, ...),
// exact-after=K (default entering the hybrid Hessian's exact region after K
// consecutive full projected steps: NewtonOptions::exact_after_full_steps). The
// default is "default,hybrid-simplicial". --method M is --methods M.
//
// --peer DIR: instead of the lattice samples, every curve file of DIR (the
// peer implementation's curves) relaxed as `knots relax FILE` does, by each
// method, three times (the fastest time kept); writes DIR_OUT/solver_peer.csv.
// --scaling: instead, 4_1 and 8_19 sampled at n = 200, 400 and 800 (K
// samples each, default 5), relaxed by each method; the median time per n
// and the exponent of a least-squares fit time ∝ n^p over the three n;
// writes solver_scaling.csv.
// --trace: every relaxation records its iteration trace (a few percent
// slower), written to DIR/traces/<method>-<knot>-<sample>.csv (trace.hpp);
// prints where the iterations and the time went (summarize_trace), also in
// DIR/solver_trace_summary.csv.
// --skips ("skip what a scene does not need", measured on and off): every
// sample relaxed three times by the first method: as it is (Θ free: the
// twist-free 3n-dof path; no eigen-analysis), with the full 4n+1-dof model
// and with the smallest non-rigid eigenvalue computed; writes
// solver_skips.csv.
// --continuation F[,F...]: contact-stiffness continuation before the solve
// at n (RelaxOptions::contact_continuation) for every method.
//
// Writes DIR/solver_macro.csv (one row per method and knot, and "all") and
// DIR/solver_macro_runs.csv (one row per method and sample, with the energy,
// contacts and gradient norm at the result). Exit status 1 when a run
// changed the knot type; other statuses (max-iterations, stalled) are
// measured outcomes, counted in the table.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "ek/core/errors.hpp"
#include "ek/core/parse.hpp"
#include "ek/geometry/curve_io.hpp"
#include "ek/knots/table.hpp"
#include "ek/lattice/lattice_polygon.hpp"
#include "ek/lattice/sampling.hpp"
#include "ek/solver/relax.hpp"
#include "ek/solver/trace.hpp"
#include "experiment.hpp"

namespace {

using Clock = std::chrono::steady_clock;

struct Method {
  std::string name;
  ek::RelaxOptions options;
};

struct Run {
  std::string knot, method;
  int sample = 0;
  double seconds = 0.0;      // wall time of relax() (including the Alexander checks)
  double cpu_seconds = 0.0;  // thread CPU time of the same
  ek::RelaxResult result;
};

double thread_cpu() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

using ek::exp::median;

std::string fmt(double x, const char* f = "%.4g") {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, x);
  return buf;
}

/// A cell as a stream prints it (integers, names, and the medians of iteration counts).
template <class T>
std::string cell(const T& value) {
  std::ostringstream s;
  s << value;
  return s.str();
}

Method method_named(const std::string& name, const ek::RelaxOptions& base) {
  if (name == "hybrid-simplicial") {  // hybrid at n with CHOLMOD's simplicial factorisation
    Method m{name, ek::with_method(base, "hybrid")};
    m.options.newton.cholesky.mode = ek::CholeskyMode::Simplicial;
    return m;
  }
  if (name == "projected") {
    Method m{name, ek::with_method(base, "hybrid")};
    m.options.newton.exact_after_full_steps = 0;
    return m;
  }
  if (name == "no-skip") {  // every rung of the shift ladder tried, none skipped as proven to fail
    Method m{name, ek::with_method(base, "default")};
    m.options.newton.shift_skip_proven = false;
    return m;
  }
  if (name == "levels1" || name == "levels3") {  // default with one coarse level (n/2) or three (n/8, n/4, n/2)
    Method m{name, ek::with_method(base, "default")};
    m.options.coarse_levels = name == "levels1" ? 1 : 3;
    return m;
  }
  if (name == "no-recheck" || name == "even-only") {  // default: either parity without rechecks, or the odd vertices
    Method m{name, ek::with_method(base, "default")};
    m.options.coarsening.recheck_iterations = m.options.coarsening.rechecks = 0;
    m.options.coarsening.either_parity = name == "no-recheck";
    return m;
  }
  if (name.rfind("margin=", 0) == 0) {  // the contact Hessian pattern's margin [length]
    Method m{name, ek::with_method(base, "default")};
    m.options.contact_hessian_margin = std::stod(name.substr(7));
    return m;
  }
  if (name.rfind("exact-after=", 0) == 0) {  // default entering the exact region after K full projected steps
    Method m{name, ek::with_method(base, "default")};
    m.options.newton.exact_after_full_steps = std::stoi(name.substr(12));
    return m;
  }
  if (name.rfind("soft=", 0) == 0) {  // the coarsest level's continuation factors F[/G...]
    Method m{name, ek::with_method(base, "default")};
    m.options.coarse_continuation.clear();
    std::stringstream factors(name.substr(5));
    for (std::string f; std::getline(factors, f, '/');) m.options.coarse_continuation.push_back(std::stod(f));
    return m;
  }
  return Method{name, ek::with_method(base, name)};
}

/// One relaxation, timed on the calling thread (including the Alexander checks).
Run timed_relax(const std::string& knot, int sample, const ek::Points& P, const Method& method) {
  Run run;
  run.knot = knot;
  run.method = method.name;
  run.sample = sample;
  const auto t0 = Clock::now();
  const double c0 = thread_cpu();
  run.result = ek::relax(P, method.options);
  run.cpu_seconds = thread_cpu() - c0;
  run.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  return run;
}

void print_run(const Run& run) {
  std::fprintf(stderr, "%-9s #%02d  %-9s %-18s %5d it  %7.3f s  E %.10g  contacts %d\n", run.knot.c_str(),
               run.sample, run.method.c_str(), to_string(run.result.status()).c_str(), run.result.all_phases().iterations,
               run.seconds, run.result.energy.total, run.result.contacts);
}

// ---------------------------------------------------------------------------
// Summaries

struct Summary {
  std::string method, name;
  int runs = 0, stable = 0;
  std::map<std::string, int> statuses;
  double median_seconds = 0.0, mean_seconds = 0.0, max_seconds = 0.0, median_cpu = 0.0, median_iterations = 0.0;
  double assembly = 0.0, factorization = 0.0, collision = 0.0, line_search = 0.0, eigen = 0.0, other = 0.0;
  double symbolic = 0.0, numeric = 0.0, failed = 0.0;  // per run (mean); failed: shift-ladder rungs
};

void add_split(Summary& s, const ek::NewtonReport& rep) {
  s.assembly += rep.time_assembly;
  s.factorization += rep.time_factorization;
  s.collision += rep.time_collision;
  s.line_search += rep.time_line_search;
  s.eigen += rep.time_eigen;
  s.symbolic += rep.symbolic_factorizations;
  s.numeric += rep.numeric_factorizations;
  s.failed += rep.failed_factorizations;
}

void normalise_split(Summary& s, double total) {
  if (s.runs > 0) {
    s.mean_seconds = total / s.runs;
    s.symbolic /= s.runs;
    s.numeric /= s.runs;
    s.failed /= s.runs;
  }
  if (total <= 0.0) return;  // the split as fractions of the summed wall time
  s.other = (total - s.assembly - s.factorization - s.collision - s.line_search - s.eigen) / total;
  for (double* f : {&s.assembly, &s.factorization, &s.collision, &s.line_search, &s.eigen}) *f /= total;
}

Summary summarize(const std::string& method, const std::string& name, const std::vector<const Run*>& runs) {
  Summary s;
  s.method = method;
  s.name = name;
  s.runs = static_cast<int>(runs.size());
  std::vector<double> secs, cpu, its;
  double total = 0.0;
  for (const Run* r : runs) {
    const ek::NewtonReport rep = r->result.all_phases();
    secs.push_back(r->seconds);
    cpu.push_back(r->cpu_seconds);
    its.push_back(rep.iterations);
    total += r->seconds;
    s.max_seconds = std::max(s.max_seconds, r->seconds);
    ++s.statuses[to_string(r->result.status())];
    if (r->result.status() == ek::RelaxStatus::ConvergedStable) ++s.stable;
    add_split(s, rep);
  }
  s.median_seconds = median(secs);
  s.median_cpu = median(cpu);
  s.median_iterations = median(its);
  normalise_split(s, total);
  return s;
}

std::string statuses_text(const Summary& s) {
  std::string out;
  for (const auto& [k, v] : s.statuses) out += (out.empty() ? "" : " ") + k + ":" + std::to_string(v);
  return out;
}

std::vector<const Run*> select(const std::vector<Run>& runs, const std::string& method, const std::string& knot) {
  std::vector<const Run*> sel;
  for (const Run& r : runs)
    if (r.method == method && (knot == "all" || r.knot == knot)) sel.push_back(&r);
  return sel;
}

std::vector<Summary> summary_table(const std::vector<Run>& runs, const std::vector<Method>& methods,
                                   const std::vector<std::string>& knots) {
  std::vector<Summary> table;
  for (const Method& m : methods) {
    for (const std::string& k : knots) table.push_back(summarize(m.name, k, select(runs, m.name, k)));
    table.push_back(summarize(m.name, "all", select(runs, m.name, "all")));
  }
  return table;
}

/// The columns of solver_macro.csv (docs/performance.md).
const std::vector<ek::exp::CsvColumn<Summary>> kSummaryColumns = {
    {"knot", [](const Summary& s) { return s.name; }},
    {"method", [](const Summary& s) { return s.method; }},
    {"runs", [](const Summary& s) { return cell(s.runs); }},
    {"converged_stable", [](const Summary& s) { return cell(s.stable); }},
    {"statuses", [](const Summary& s) { return statuses_text(s); }},
    {"median_seconds", [](const Summary& s) { return fmt(s.median_seconds, "%.6g"); }},
    {"mean_seconds", [](const Summary& s) { return fmt(s.mean_seconds, "%.6g"); }},
    {"max_seconds", [](const Summary& s) { return fmt(s.max_seconds, "%.6g"); }},
    {"median_cpu_seconds", [](const Summary& s) { return fmt(s.median_cpu, "%.6g"); }},
    {"median_iterations", [](const Summary& s) { return cell(s.median_iterations); }},
    {"symbolic_per_run", [](const Summary& s) { return fmt(s.symbolic, "%.6g"); }},
    {"numeric_per_run", [](const Summary& s) { return fmt(s.numeric, "%.6g"); }},
    {"frac_assembly", [](const Summary& s) { return fmt(s.assembly, "%.4f"); }},
    {"frac_factorization", [](const Summary& s) { return fmt(s.factorization, "%.4f"); }},
    {"frac_collision", [](const Summary& s) { return fmt(s.collision, "%.4f"); }},
    {"frac_line_search", [](const Summary& s) { return fmt(s.line_search, "%.4f"); }},
    {"frac_eigen", [](const Summary& s) { return fmt(s.eigen, "%.4f"); }},
    {"frac_other", [](const Summary& s) { return fmt(s.other, "%.4f"); }},
    {"failed_per_run", [](const Summary& s) { return fmt(s.failed, "%.6g"); }},
};

void print_summary_table(const std::vector<Summary>& table, int count, const std::string& out) {
  std::printf("solver macro benchmark (n = 400, %d samples per knot)\n", count);
  std::printf("%-9s %-9s %5s %6s %8s %8s %8s %8s %6s %7s %7s %8s | %6s %6s %6s %6s %6s %6s | %s\n", "knot", "method",
              "runs", "stable", "median s", "mean s", "max s", "cpu s", "med it", "sym/run", "num/run", "fail/run", "asm",
              "fact", "ccd", "ls", "eig", "other", "statuses");
  for (const Summary& s : table) {
    std::printf("%-9s %-9s %5d %6d %8.3f %8.3f %8.3f %8.3f %6.0f %7.0f %7.0f %8.0f | %5.1f%% %5.1f%% %5.1f%% %5.1f%% "
                "%5.1f%% %5.1f%% | %s\n",
                s.name.c_str(), s.method.c_str(), s.runs, s.stable, s.median_seconds, s.mean_seconds, s.max_seconds,
                s.median_cpu, s.median_iterations, s.symbolic, s.numeric, s.failed, 100 * s.assembly,
                100 * s.factorization, 100 * s.collision, 100 * s.line_search, 100 * s.eigen, 100 * s.other,
                statuses_text(s).c_str());
  }
  ek::exp::write_csv(out + "/solver_macro.csv", kSummaryColumns, table);
}

/// With two or more methods: each method's median time and iterations over
/// the first method's, per knot (the first is the new default by default).
void print_ratio_table(const std::vector<Summary>& table, const std::vector<Method>& methods,
                       const std::string& out) {
  if (methods.size() < 2) return;
  struct Ratio {
    std::string knot, method, reference;
    double time, cpu, iterations;
  };
  std::vector<Ratio> rows;
  std::printf("ratios to %s (median time and iterations of the method / of %s)\n", methods[0].name.c_str(),
              methods[0].name.c_str());
  std::printf("%-9s %-9s %9s %9s %9s\n", "knot", "method", "time", "cpu", "iters");
  const size_t per_method = table.size() / methods.size();
  for (size_t m = 1; m < methods.size(); ++m)
    for (size_t k = 0; k < per_method; ++k) {
      const Summary& ref = table[k];
      const Summary& s = table[m * per_method + k];
      const double t = s.median_seconds / ref.median_seconds, c = s.median_cpu / ref.median_cpu;
      const double it = s.median_iterations / std::max(1.0, ref.median_iterations);
      std::printf("%-9s %-9s %8.2fx %8.2fx %8.2fx\n", s.name.c_str(), s.method.c_str(), t, c, it);
      rows.push_back({s.name, s.method, ref.method, t, c, it});
    }
  ek::exp::write_csv<Ratio>(out + "/solver_ratio.csv",
                            {{"knot", [](const Ratio& r) { return r.knot; }},
                             {"method", [](const Ratio& r) { return r.method; }},
                             {"reference", [](const Ratio& r) { return r.reference; }},
                             {"time_ratio", [](const Ratio& r) { return fmt(r.time, "%.4f"); }},
                             {"cpu_ratio", [](const Ratio& r) { return fmt(r.cpu, "%.4f"); }},
                             {"iteration_ratio", [](const Ratio& r) { return fmt(r.iterations, "%.4f"); }}},
                            rows);
}

void write_runs_csv(const std::vector<Run>& runs, const std::string& out) {
  struct Row {
    const Run& run;
    ek::NewtonReport all;  ///< of every phase
  };
  std::vector<Row> rows;
  for (const Run& r : runs) rows.push_back({r, r.result.all_phases()});
  ek::exp::write_csv<Row>(
      out + "/solver_macro_runs.csv",
      {{"knot", [](const Row& r) { return r.run.knot; }},
       {"sample", [](const Row& r) { return cell(r.run.sample); }},
       {"method", [](const Row& r) { return r.run.method; }},
       {"status", [](const Row& r) { return to_string(r.run.result.status()); }},
       {"seconds", [](const Row& r) { return fmt(r.run.seconds, "%.6g"); }},
       {"cpu_seconds", [](const Row& r) { return fmt(r.run.cpu_seconds, "%.6g"); }},
       {"iterations", [](const Row& r) { return cell(r.all.iterations); }},
       {"energy", [](const Row& r) { return fmt(r.run.result.energy.total, "%.15g"); }},
       {"gradient_norm", [](const Row& r) { return fmt(r.all.gradient_norm, "%.3e"); }},
       {"contacts", [](const Row& r) { return cell(r.run.result.contacts); }},
       {"min_distance", [](const Row& r) { return fmt(r.run.result.min_distance, "%.6g"); }},
       {"writhe", [](const Row& r) { return fmt(r.run.result.writhe, "%.6g"); }},
       {"symbolic", [](const Row& r) { return cell(r.all.symbolic_factorizations); }},
       {"numeric", [](const Row& r) { return cell(r.all.numeric_factorizations); }},
       {"line_search_trials", [](const Row& r) { return cell(r.all.line_search_trials); }},
       {"saddle_escapes", [](const Row& r) { return cell(r.all.saddle_escapes); }},
       {"marginal", [](const Row& r) { return std::string(r.all.marginal ? "1" : "0"); }},
       {"failed", [](const Row& r) { return cell(r.all.failed_factorizations); }}},
      rows);
}

/// Where the iterations and the time went, per method and knot (from the traces).
void print_trace_summary(const std::vector<Run>& runs, const std::vector<Method>& methods,
                         const std::vector<std::string>& knots, const std::string& out) {
  struct Row {
    std::string knot, method;
    ek::TraceSummary s;
  };
  std::vector<Row> rows;
  std::printf("where the iterations went (%% of iterations; excess energy over the end of the phase)\n");
  std::printf("%-9s %-9s %7s | %6s %6s %6s %6s %6s | %6s %6s %6s %6s | %7s %7s\n", "knot", "method", "iters", ">1e-1",
              ">1e-2", ">1e-3", ">1e-4", "<1e-4", "t=1", "t<1/64", "ccd<1", "exact", "fail/fc", "exact s");
  auto row = [&](const std::string& name, const std::string& method, const ek::TraceSummary& s) {
    const double it = std::max(1, s.iterations);
    std::printf("%-9s %-9s %7d | %5.1f%% %5.1f%% %5.1f%% %5.1f%% %5.1f%% | %5.1f%% %5.1f%% %5.1f%% %5.1f%% | %6.1f%% "
                "%6.1f%%\n",
                name.c_str(), method.c_str(), s.iterations, 100 * s.by_excess[0] / it, 100 * s.by_excess[1] / it,
                100 * s.by_excess[2] / it, 100 * s.by_excess[3] / it, 100 * s.by_excess[4] / it,
                100 * s.full_steps / it, 100 * s.short_steps / it, 100 * s.collision_limited / it,
                100 * s.exact_iterations / it, 100.0 * s.failed_factorizations / std::max(1, s.factorizations),
                100 * s.seconds_exact / std::max(1e-300, s.seconds));
    rows.push_back({name, method, s});
  };
  for (const Method& m : methods) {
    ek::TraceSummary all;
    for (const std::string& k : knots) {
      ek::TraceSummary s;
      for (const Run* r : select(runs, m.name, k)) s.add(ek::summarize_trace(r->result.trace));
      row(k, m.name, s);
      all.add(s);
    }
    row("all", m.name, all);
  }
  std::vector<ek::exp::CsvColumn<Row>> columns = {{"knot", [](const Row& r) { return r.knot; }},
                                                  {"method", [](const Row& r) { return r.method; }},
                                                  {"iterations", [](const Row& r) { return cell(r.s.iterations); }}};
  const char* excess[] = {"excess_above_1e-1", "excess_1e-2_1e-1", "excess_1e-3_1e-2", "excess_1e-4_1e-3",
                          "excess_below_1e-4"};
  for (size_t b = 0; b < 5; ++b) columns.push_back({excess[b], [b](const Row& r) { return cell(r.s.by_excess[b]); }});
  const std::pair<const char*, int ek::TraceSummary::*> counts[] = {
      {"full_steps", &ek::TraceSummary::full_steps},
      {"short_steps", &ek::TraceSummary::short_steps},
      {"collision_limited", &ek::TraceSummary::collision_limited},
      {"exact_iterations", &ek::TraceSummary::exact_iterations},
      {"factorizations", &ek::TraceSummary::factorizations},
      {"failed_factorizations", &ek::TraceSummary::failed_factorizations},
      {"pattern_changes", &ek::TraceSummary::pattern_changes}};
  for (const auto& [name, m] : counts) columns.push_back({name, [m = m](const Row& r) { return cell(r.s.*m); }});
  columns.push_back({"seconds", [](const Row& r) { return fmt(r.s.seconds, "%.6g"); }});
  columns.push_back({"seconds_exact", [](const Row& r) { return fmt(r.s.seconds_exact, "%.6g"); }});
  ek::exp::write_csv(out + "/solver_trace_summary.csv", columns, rows);
}

void write_trace(const std::string& out, const Run& run) {
  std::ostringstream text;
  ek::write_trace_csv(text, run.result.trace, run.result.phases);
  ek::exp::write_text(out + "/traces/" + run.method + "-" + run.knot + "-" + std::to_string(run.sample) + ".csv", text.str());
}

// ---------------------------------------------------------------------------
// The runs

struct Config {
  std::vector<std::string> knots = {"4_1", "8_19", "10_100", "12a_1019"};
  int count = 20;
  std::uint64_t seed = 20230806;
  std::string out = "results/bench";
  std::vector<Method> methods;
  bool trace = false, skips = false, scaling = false;
  std::string peer;
};

std::vector<ek::Points> lattice_samples(const std::string& knot, int n, int count, std::uint64_t seed) {
  ek::SampleOptions so;
  so.vertices = n;
  so.count = count;
  so.seed = seed;  // one fixed walk per knot and n
  const ek::SampleBatch batch = ek::sample_knot(ek::KnotTable::global().at(knot), so);
  std::vector<ek::Points> out;
  for (const auto& s : batch.samples) out.push_back(ek::to_points(s));
  return out;
}

/// Every sample by every method, the methods' order rotating from sample to sample.
std::vector<Run> relax_interleaved(const std::string& knot, const std::vector<ek::Points>& samples,
                                   const Config& c) {
  std::vector<Run> runs;
  const size_t m = c.methods.size();
  for (size_t s = 0; s < samples.size(); ++s)
    for (size_t j = 0; j < m; ++j) {
      const Method& method = c.methods[(s + j) % m];
      Run run = timed_relax(knot, static_cast<int>(s), samples[s], method);
      print_run(run);
      if (c.trace) write_trace(c.out, run);
      runs.push_back(std::move(run));
    }
  return runs;
}

int macro(const Config& c) {
  std::vector<Run> runs;
  for (size_t k = 0; k < c.knots.size(); ++k) {
    const std::vector<Run> r = relax_interleaved(c.knots[k], lattice_samples(c.knots[k], 400, c.count, c.seed + k), c);
    runs.insert(runs.end(), r.begin(), r.end());
  }
  const std::vector<Summary> table = summary_table(runs, c.methods, c.knots);
  print_summary_table(table, c.count, c.out);
  print_ratio_table(table, c.methods, c.out);
  if (c.trace) print_trace_summary(runs, c.methods, c.knots, c.out);
  write_runs_csv(runs, c.out);
  std::printf("wrote %s/solver_macro.csv and %s/solver_macro_runs.csv\n", c.out.c_str(), c.out.c_str());
  for (const Run& r : runs)
    if (!r.result.alexander_preserved) return 1;
  return 0;
}

/// The "skip what a scene does not need" variants of the first method.
int skips(const Config& c) {
  const std::vector<std::string> variants = {"default", "full-model", "eigen"};
  std::vector<std::vector<Run>> runs(variants.size());
  for (size_t k = 0; k < c.knots.size(); ++k) {
    const std::vector<ek::Points> samples = lattice_samples(c.knots[k], 400, c.count, c.seed + k);
    for (size_t s = 0; s < samples.size(); ++s)
      for (size_t v = 0; v < variants.size(); ++v) {
        Method m = c.methods.front();
        m.name = variants[v];
        m.options.full_model = v == 1;
        m.options.smallest_eigenvalue = v == 2;
        runs[v].push_back(timed_relax(c.knots[k], static_cast<int>(s), samples[s], m));
        print_run(runs[v].back());
      }
  }
  std::vector<Summary> rows;
  std::printf("solver skips (n = 400, %d samples each of %zu knots, method %s)\n", c.count, c.knots.size(),
              c.methods.front().name.c_str());
  std::printf("%-11s %5s %7s %9s %9s %7s\n", "variant", "runs", "stable", "total s", "median s", "med it");
  bool kept = true;
  for (size_t v = 0; v < variants.size(); ++v) {
    std::vector<const Run*> sel;
    for (const Run& r : runs[v]) sel.push_back(&r);
    const Summary sm = summarize(variants[v], variants[v], sel);
    const double total = sm.mean_seconds * sm.runs;
    kept = kept && !sm.statuses.count(to_string(ek::RelaxStatus::TopologyChanged));
    std::printf("%-11s %5d %7d %9.3f %9.3f %7.0f\n", sm.name.c_str(), sm.runs, sm.stable, total, sm.median_seconds,
                sm.median_iterations);
    rows.push_back(sm);
  }
  ek::exp::write_csv<Summary>(
      c.out + "/solver_skips.csv",
      {{"variant", [](const Summary& s) { return s.name; }},
       {"runs", [](const Summary& s) { return cell(s.runs); }},
       {"converged_stable", [](const Summary& s) { return cell(s.stable); }},
       {"total_seconds", [](const Summary& s) { return fmt(s.mean_seconds * s.runs, "%.6g"); }},
       {"median_seconds", [](const Summary& s) { return fmt(s.median_seconds, "%.6g"); }},
       {"median_iterations", [](const Summary& s) { return cell(s.median_iterations); }}},
      rows);
  std::printf("wrote %s/solver_skips.csv\n", c.out.c_str());
  return kept ? 0 : 1;
}

/// The peer implementation's curves, each by every method, the fastest of three.
int peer(const Config& c) {
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(c.peer)) {
    const std::string ext = e.path().extension().string();
    if (ext == ".obj" || ext == ".txt") files.push_back(e.path().string());
  }
  std::sort(files.begin(), files.end());
  if (files.empty()) throw ek::InputError("--peer: no .obj or .txt curve in " + c.peer);
  struct Row {
    std::string file;
    Run best;  ///< the fastest of three
    int vertices;
  };
  std::vector<Row> rows;
  std::printf("peer curves (knots relax FILE, fastest of 3 runs)\n%-28s %-9s %6s %-18s %9s %7s %14s\n", "file",
              "method", "n", "status", "seconds", "iters", "energy");
  bool kept = true;
  for (const std::string& f : files) {
    const ek::Points P = ek::read_curve(f);
    const std::string name = std::filesystem::path(f).filename().string();
    for (const Method& m : c.methods) {
      Run best;
      for (int rep = 0; rep < 3; ++rep) {
        Run run = timed_relax(name, 0, P, m);
        if (rep == 0 || run.seconds < best.seconds) best = std::move(run);
      }
      kept = kept && best.result.topology_preserved();
      const int it = best.result.all_phases().iterations;
      std::printf("%-28s %-9s %6d %-18s %9.4f %7d %14.10f\n", name.c_str(), m.name.c_str(), static_cast<int>(P.rows()),
                  to_string(best.result.status()).c_str(), best.seconds, it, best.result.energy.total);
      rows.push_back({name, std::move(best), static_cast<int>(P.rows())});
    }
  }
  ek::exp::write_csv<Row>(c.out + "/solver_peer.csv",
                          {{"file", [](const Row& r) { return r.file; }},
                           {"method", [](const Row& r) { return r.best.method; }},
                           {"vertices", [](const Row& r) { return cell(r.vertices); }},
                           {"status", [](const Row& r) { return to_string(r.best.result.status()); }},
                           {"seconds", [](const Row& r) { return fmt(r.best.seconds, "%.6g"); }},
                           {"iterations", [](const Row& r) { return cell(r.best.result.all_phases().iterations); }},
                           {"energy", [](const Row& r) { return fmt(r.best.result.energy.total, "%.15g"); }}},
                          rows);
  std::printf("wrote %s/solver_peer.csv\n", c.out.c_str());
  return kept ? 0 : 1;
}

/// Slope of the least-squares line through (log n, log t).
double fitted_exponent(const std::vector<double>& n, const std::vector<double>& t) {
  double mx = 0.0, my = 0.0;
  for (size_t i = 0; i < n.size(); ++i) {
    mx += std::log(n[i]) / static_cast<double>(n.size());
    my += std::log(t[i]) / static_cast<double>(n.size());
  }
  double sxy = 0.0, sxx = 0.0;
  for (size_t i = 0; i < n.size(); ++i) {
    sxy += (std::log(n[i]) - mx) * (std::log(t[i]) - my);
    sxx += (std::log(n[i]) - mx) * (std::log(n[i]) - mx);
  }
  return sxy / sxx;
}

/// Median time per equilibrium at n = 200, 400, 800 for 4_1 and 8_19.
int scaling(const Config& c) {
  const std::vector<int> sizes = {200, 400, 800};
  struct Row {
    Summary s;  ///< of one knot, method and n
    int vertices;
    double exponent;
  };
  std::vector<Row> rows;
  std::printf("cost against n (median per equilibrium, %d samples per knot and n)\n", c.count);
  std::printf("%-9s %-9s %9s %9s %9s %9s\n", "knot", "method", "n=200 s", "n=400 s", "n=800 s", "exponent");
  bool kept = true;
  for (const std::string knot : {"4_1", "8_19"}) {
    std::map<std::string, std::vector<Summary>> by_method;
    for (const int n : sizes) {
      const std::vector<Run> runs = relax_interleaved(knot, lattice_samples(knot, n, c.count, c.seed + n), c);
      for (const Run& r : runs) kept = kept && r.result.alexander_preserved;
      for (const Method& m : c.methods) by_method[m.name].push_back(summarize(m.name, knot, select(runs, m.name, knot)));
    }
    for (const Method& m : c.methods) {
      const std::vector<Summary>& s = by_method[m.name];
      const double p = fitted_exponent({200.0, 400.0, 800.0},
                                       {s[0].median_seconds, s[1].median_seconds, s[2].median_seconds});
      std::printf("%-9s %-9s %9.3f %9.3f %9.3f %9.2f\n", knot.c_str(), m.name.c_str(), s[0].median_seconds,
                  s[1].median_seconds, s[2].median_seconds, p);
      for (size_t i = 0; i < sizes.size(); ++i) rows.push_back({s[i], sizes[i], p});
    }
  }
  ek::exp::write_csv<Row>(c.out + "/solver_scaling.csv",
                          {{"knot", [](const Row& r) { return r.s.name; }},
                           {"method", [](const Row& r) { return r.s.method; }},
                           {"vertices", [](const Row& r) { return cell(r.vertices); }},
                           {"runs", [](const Row& r) { return cell(r.s.runs); }},
                           {"converged_stable", [](const Row& r) { return cell(r.s.stable); }},
                           {"median_seconds", [](const Row& r) { return fmt(r.s.median_seconds, "%.6g"); }},
                           {"median_iterations", [](const Row& r) { return cell(r.s.median_iterations); }},
                           {"exponent", [](const Row& r) { return fmt(r.exponent, "%.4f"); }}},
                          rows);
  std::printf("wrote %s/solver_scaling.csv\n", c.out.c_str());
  return kept ? 0 : 1;
}

/// The options this benchmark adds to the experiments' common ones, filling `c` and `base`.
std::vector<ek::exp::ExtraOption> options(Config& c, ek::RelaxOptions& base, std::vector<std::string>& names,
                                          bool& count_given) {
  using ek::exp::split_list;
  const auto integer = [](const std::string& v) { return static_cast<int>(ek::parse_integer(v, "a count")); };
  return {
      {"--quick", "[--quick]", nullptr, [&] { c.count = 2, count_given = true; }},
      {"--count", "[--count K]", [&](const std::string& v) { c.count = integer(v), count_given = true; }, nullptr},
      {"--knots", "[--knots A,B,...]", [&](const std::string& v) { c.knots = split_list(v); }, nullptr},
      {"--seed", "[--seed S]",
       [&](const std::string& v) { c.seed = static_cast<std::uint64_t>(ek::parse_integer(v, "--seed")); }, nullptr},
      {"--methods", "[--methods M[,M...]]", [&](const std::string& v) { names = split_list(v); }, nullptr},
      {"--method", "[--method M]", [&](const std::string& v) { names = split_list(v); }, nullptr},
      {"--max-iter", "[--max-iter N]", [&](const std::string& v) { base.max_iterations = integer(v); }, nullptr},
      {"--continuation", "[--continuation F[,F...]]",
       [&](const std::string& v) {
         for (const std::string& f : split_list(v)) base.contact_continuation.push_back(ek::parse_number(f, "a factor"));
       },
       nullptr},
      {"--verbose", "[--verbose]", nullptr, [&] { base.newton.verbose = true; }},
      {"--trace", "[--trace]", nullptr, [&] { c.trace = base.newton.record_trace = true; }},
      {"--skips", "[--skips]", nullptr, [&] { c.skips = true; }},
      {"--scaling", "[--scaling]", nullptr, [&] { c.scaling = true; }},
      {"--peer", "[--peer DIR]", [&](const std::string& v) { c.peer = v; }, nullptr},
  };
}

}  // namespace

int main(int argc, char** argv) {
  Config c;
  ek::RelaxOptions base;
  std::vector<std::string> names = {"default", "hybrid-simplicial"};
  bool count_given = false;
  int status = 0;
  const int parsed = ek::exp::run_experiment(
      argc, argv, "exp_bench_solver", "The solver's macro benchmark (docs/performance.md).",
      [&](const ek::exp::Args& a) {
        c.out = a.out;
        if (c.scaling && !count_given) c.count = 5;
        ek::require_input(c.count >= 1 && !c.knots.empty() && !names.empty(),
                          "need at least one knot, one sample and one method");
        base.validate();
        for (const std::string& n : names) c.methods.push_back(method_named(n, base));
        if (c.trace) std::filesystem::create_directories(c.out + "/traces");
        status = !c.peer.empty() ? peer(c) : c.scaling ? scaling(c) : c.skips ? skips(c) : macro(c);
      },
      options(c, base, names, count_given));
  return parsed != 0 ? parsed : status;
}
