// exp_time_vs_error: run time against error, one core (docs/performance.md).
//
//  Unit edges throughout: the contact barrier acts between non-adjacent edges
//  closer than d̂ = 2r = 0.4, so edges shorter than d̂ would put neighbours
//  along the wire inside it (the model needs ℓ > d̂).
//  1. k-covered circles (k = 1, 2, 3), unit edges (L = n), n = 50 .. 3200:
//     the discrete bending energy against the exact 2π²k²·EI/L. k = 1 is
//     solved (relax() from an ellipse with semi-axes 1.2 R and R/1.2, the
//     circle's length, to the circle); k = 2, 3 self-intersect, so their
//     energy is evaluated on the exact k-covered regular polygon (an
//     equilibrium of the rod energy alone).
//  2. Michell's instability (Appendix C): a circle with prescribed link Lk
//     is stable below Lk_c = √3·(1 + ν) (GJ = EI/(1 + ν) for a circular
//     section). Bisection on Lk (relax() with stop_at_critical_point: stable
//     or unstable) to 1e-6 relative, for n = 50 .. 3200 (ci: up to 800), L = n.
//  3. Knots: a fixed lattice sample of 4_1, 8_19 and 12a_1019 (n = 400) is
//     relaxed; its equilibrium is resampled to n = 100 .. 800 (same length
//     400, same wire; n = 1600 would make edges of 0.25 < d̂) and relaxed again. Reference: Richardson extrapolation
//     of the three finest energies (observed order p). And at n = 400 the
//     gradient tolerance is swept from 1e-4 to 1e-10 (reference 1e-12).
// Writes circles.csv, michell.csv, knots.csv, tolerance.csv, summary.json.
#include <chrono>
#include <cmath>
#include <iostream>

#include "ek/geometry/polyline.hpp"
#include "ek/geometry/resample.hpp"
#include "ek/knots/table.hpp"
#include "ek/lattice/lattice_polygon.hpp"
#include "ek/lattice/sampling.hpp"
#include "ek/rod/elastic_rod.hpp"
#include "ek/solver/relax.hpp"
#include "experiment.hpp"
#include "time_vs_error_summary.hpp"
#include "scales.hpp"

using namespace ek;
using namespace ek::exp;

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

Points covered_circle(int n, int k, double radius, double squash = 1.0) {
  Points P(n, 3);
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * M_PI * k * i / n;
    P.row(i) << radius * squash * std::cos(a), radius / squash * std::sin(a), 0.0;
  }
  return P;
}

/// 1. k-covered circles: the bending energy 2π²k²EI/L; k = 1 relaxed from an
/// ellipse with the circle's rest lengths, k = 2, 3 evaluated on the polygon.
void circles(const Args& a, const std::vector<int>& ns) {
  const RodMaterial mat;
  const double EI = mat.bending_stiffness();
  Csv csv(a.out + "/circles.csv", {"k", "n", "energy", "exact", "relative_error", "seconds", "how"});
  for (int k : {1, 2, 3})
    for (int n : ns) {
      const double L = n;
      const double R = L / (2.0 * M_PI * k), exact = 2.0 * M_PI * M_PI * k * k * EI / L;
      double E = 0.0, secs = 0.0;
      const auto t0 = Clock::now();
      if (k == 1) {
        RelaxOptions ro;
        ro.rest_lengths = VecX::Constant(n, L / n);
        ro.check_topology = false;  // the unknot
        Points start = covered_circle(n, 1, R, 1.2);
        start *= L / curve_length(start);
        const RelaxResult r = relax(start, ro);
        if (!r.converged())
          std::cout << "exp_time_vs_error: circle n = " << n << " ended " << to_string(r.status()) << " after "
                    << r.report.iterations << " iterations, |g| " << r.report.gradient_norm << std::endl;
        E = r.energy.bend;
      } else {
        E = ElasticRod(covered_circle(n, k, R), mat, TwistModel::TwistFree).energy(EnergyTerm::Bend);
      }
      secs = seconds_since(t0);
      csv.row({std::to_string(k), std::to_string(n), Csv::num(E), Csv::num(exact),
               Csv::num(std::fabs(E - exact) / exact), Csv::num(secs), k == 1 ? "relax" : "evaluate"});
    }
  csv.commit();
}

/// Whether the twisted circle at link `lk` is stable (the stability test at convergence).
bool twisted_circle_stable(const Points& circle, double lk) {
  RelaxOptions ro;
  ro.link = lk;
  ro.check_topology = false;
  ro.stop_at_critical_point = true;
  ro.max_iterations = 1000;
  const RelaxResult r = relax(circle, ro);
  if (!r.converged())
    std::cout << "exp_time_vs_error: Michell n = " << circle.rows() << ", Lk = " << lk << ": " << to_string(r.status())
              << std::endl;
  return r.stable();
}

/// 2. Michell's instability: the critical link √3(1 + ν) of a twisted ring by bisection.
void michell(const Args& a, const std::vector<int>& ns, results::TimeVsErrorSummary& sum) {
  const double exact = std::sqrt(3.0) * (1.0 + RodMaterial().poisson);
  Csv csv(a.out + "/michell.csv", {"n", "critical_link", "exact", "relative_error", "seconds", "solves"});
  for (int n : ns) {
    const Points circle = covered_circle(n, 1, n / (2.0 * M_PI));  // unit edges
    double lo = 0.5 * exact, hi = 1.5 * exact;
    int solves = 2;
    const auto t0 = Clock::now();
    if (!twisted_circle_stable(circle, lo) || twisted_circle_stable(circle, hi)) {
      std::cout << "exp_time_vs_error: Michell n = " << n << ": no bracket (see above); skipped" << std::endl;
      continue;
    }
    for (; hi - lo > 1e-6 * exact; ++solves) {
      const double mid = 0.5 * (lo + hi);
      (twisted_circle_stable(circle, mid) ? lo : hi) = mid;
    }
    const double secs = seconds_since(t0), lc = 0.5 * (lo + hi);
    csv.row({std::to_string(n), Csv::num(lc), Csv::num(exact), Csv::num(std::fabs(lc - exact) / exact),
             Csv::num(secs / solves), std::to_string(solves)});
    sum.michell.push_back({n, lc, std::fabs(lc - exact) / exact});
    std::cout << "exp_time_vs_error: Michell n = " << n << ": Lk_c = " << lc << " (exact " << exact << ")"
              << std::endl;
  }
  csv.commit();
}

/// 3a. A knot's equilibrium resampled to n = 100..800 and relaxed again:
/// energy against n, with the Richardson reference of the last three.
void resolution_sweep(const std::string& name, const RelaxResult& base, Csv& csv) {
  const std::vector<int> kn = {100, 200, 400, 800};
  std::vector<RelaxResult> runs;
  std::vector<double> E, T;
  for (int n : kn) {
    RelaxOptions ro;
    ro.rest_lengths = VecX::Constant(n, 400.0 / n);
    const auto t0 = Clock::now();
    runs.push_back(relax(resample_arclength(base.positions, n), ro));
    T.push_back(seconds_since(t0));
    E.push_back(runs.back().energy.total);
  }
  const size_t m = E.size();
  const double d1 = E[m - 2] - E[m - 3], d2 = E[m - 1] - E[m - 2];
  const double p = std::log(std::fabs(d1 / d2)) / std::log(2.0);
  const double ref = E[m - 1] + d2 / (std::pow(2.0, p) - 1.0);
  for (size_t q = 0; q < m; ++q)
    csv.row({name, std::to_string(kn[q]), Csv::num(E[q]), Csv::num(ref), Csv::num(std::fabs(E[q] - ref) / ref),
             Csv::num(T[q]), std::to_string(runs[q].report.iterations), to_string(runs[q].status()), Csv::num(p)});
  std::cout << "exp_time_vs_error: " << name << " observed order " << p << ", reference energy " << ref << std::endl;
}

/// 3b. The lattice sample relaxed at gradient tolerances 1e-4 .. 1e-10
/// against the result at 1e-12.
void tolerance_sweep(const std::string& name, const Points& sample, Csv& csv) {
  const auto solve = [&](double tol) {
    RelaxOptions ro;
    ro.tolerance = tol;
    const auto t0 = Clock::now();
    RelaxResult r = relax(sample, ro);
    return std::make_pair(r, seconds_since(t0));
  };
  const double reference = solve(1e-12).first.energy.total;
  for (double tol : {1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10}) {
    const auto [r, secs] = solve(tol);
    const double er = std::fabs(r.energy.total - reference) / reference;
    csv.row({name, Csv::num(tol), Csv::num(r.energy.total), Csv::num(reference), Csv::num(er), Csv::num(secs),
             std::to_string(r.report.iterations), to_string(r.status())});
  }
}

/// 3. Knots: the resolution and tolerance sweeps of one lattice sample each.
void knots(const Args& a) {
  Csv kc(a.out + "/knots.csv", {"knot", "n", "energy", "reference", "relative_error", "seconds", "iterations",
                                "status", "observed_order"});
  Csv tc(a.out + "/tolerance.csv",
         {"knot", "tolerance", "energy", "reference", "relative_error", "seconds", "iterations", "status"});
  for (const std::string name : {"4_1", "8_19", "12a_1019"}) {
    SampleOptions so;
    so.vertices = 400;
    so.seed = 7;
    const Points sample = to_points(sample_knot(KnotTable::global().at(name), so).samples.front());
    const RelaxResult base = relax(sample);
    require(base.stable(), name + ": the n = 400 sample did not converge");
    resolution_sweep(name, base, kc);
    tolerance_sweep(name, sample, tc);
  }
  kc.commit();
  tc.commit();
}

}  // namespace

int main(int argc, char** argv) {
  return run_experiment(argc, argv, "exp_time_vs_error", "Run time against error.", [](const Args& a) {
    const std::vector<int> ns = a.scale == Scale::CI ? std::vector<int>{50, 100, 200, 400, 800}
                                                     : std::vector<int>{50, 100, 200, 400, 800, 1600, 3200};
    announce(a, "exp_time_vs_error", "circles, Michell's instability, knots at n = 100..800, tolerance sweep",
             a.scale == Scale::CI ? 120.0 : 900.0);
    results::TimeVsErrorSummary sum;
    sum.scale = a.scale_name;
    circles(a, ns);
    michell(a, ns, sum);
    knots(a);
    write_summary(a, sum);
  });
}
