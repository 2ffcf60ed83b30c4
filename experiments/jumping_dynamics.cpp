// exp_jumping_dynamics: does a jumping knot really jump? Beyond the paper,
// which predicts the jump by a static relaxation and says why that is not
// enough ("our simulation neither accounts for dynamics nor friction, we have
// to validate this prediction with physical models", Section 8, jumping
// knots). For knots that jump in exp_jumping_knots, the flat coil it relaxed
// under the slab (with its link Lk_B = Wr_target and the coil's rest lengths)
// is released at t = 0 and followed in time (ek/mechanics/dynamics.hpp:
// backward Euler, the wire's inertia, air drag γ, Coulomb friction μ between
// touching wires) until it comes to rest or the duration runs out. Per knot
// and μ: the outcome (jumped: its end is 3D; flat: at rest and planar;
// between: at rest, neither; moving: neither 3D nor at rest at the end),
// the time to rest, the largest speed, and how its end compares with the
// static release and the 3D target; then the friction bracket: the largest
// μ at which it jumps below the smallest at which it rests flat, halved
// `bisection` times. The outcome need not be monotone in μ: friction
// changes the path, and a coil whose contacts open as it rises is not held.
//   ci:      12a_1019 (Fig. 13) at μ = 0 and 4
//   default: 12a_1019 and the first 5 other jumping knots of exp_jumping_knots'
//            table, μ ∈ {0, 0.5, 1, 2, 4}, 2 halvings; the step check (μ = 0 at h/2)
//   paper:   12a_1019 and the first 20 others, as default
// Writes dynamics.csv, trajectories/<knot>_<run>.csv, frames/<knot>/NNNNN.obj
// (12a_1019 at μ = 0), curves/<knot>_<run>_end.obj, summary.json (docs/results.md).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <mutex>
#include <sstream>

#include "ek/analysis/attributes.hpp"
#include "ek/analysis/similarity.hpp"
#include "ek/core/parallel.hpp"
#include "ek/geometry/curve_io.hpp"
#include "ek/geometry/polyline.hpp"
#include "ek/mechanics/dynamics.hpp"
#include "experiment.hpp"
#include "jumping_dynamics_summary.hpp"
#include "thresholds.hpp"

using namespace ek;
using namespace ek::exp;
using namespace ek::results;

namespace {

constexpr double kTimeStep = 1.0;      ///< [time] h: the coil's slowest modes have periods near 100
constexpr double kDuration = 6000.0;   ///< [time] the frictionless 12a_1019 rests after about 2,600
constexpr double kDamping = 0.005;     ///< [1/time] γ: air drag, a decay time 1/γ of 200
constexpr double kRestSpeed = 1e-4;    ///< [length/time] at rest below it for 10 steps
/// [length/time] ε_v: slower contacts feel viscous friction. 1e-3 let held
/// coils creep about 1e-3 per time unit, 6 edge lengths over a run; speeds
/// in a jump are 0.01 to 0.2.
constexpr double kFrictionVelocity = 1e-5;
constexpr int kTrajectoryEvery = 20;   ///< [steps] frames of the trajectories and of frames/
constexpr const char* kFigureKnot = "12a_1019";

/// A jumping knot of exp_jumping_knots: its coil, flat state, link and the
/// states of the static release.
struct Coil {
  std::string knot;
  double link = 0.0;  ///< [turns] Lk_B = Wr_target
  VecX rest;          ///< the coil's edge lengths
  Points flat, released, target;
};

std::vector<Coil> read_coils(const Args& a, int others) {
  const std::string dir = a.results + "/jumping_knots";
  const std::vector<CsvRow> rows = read_csv_rows(dir + "/jumping.csv", "exp_jumping_dynamics", {"knot", "writhe_target", "jumps"});
  std::vector<Coil> out;
  for (const CsvRow& r : rows) {
    const bool figure = r.at("knot") == kFigureKnot;
    if (r.at("jumps") != "true" || (!figure && others <= 0)) continue;
    others -= figure ? 0 : 1;
    const std::string base = dir + "/curves/" + r.at("knot");
    out.push_back({r.at("knot"), std::stod(r.at("writhe_target")), edge_lengths(read_curve(base + "_coil.obj")),
                   read_curve(base + "_flat.obj"), read_curve(base + "_final.obj"), read_curve(base + "_target.obj")});
  }
  require_input(std::any_of(out.begin(), out.end(), [](const Coil& c) { return c.knot == kFigureKnot; }),
                "exp_jumping_dynamics: jumping_knots/jumping.csv has no jumping 12a_1019");
  return out;
}

/// One release of a coil at friction μ and step h.
struct Release {
  const Coil* coil = nullptr;
  double mu = 0.0, h = kTimeStep;
  DynamicsResult r;
  double seconds = 0.0;
  /// "jumped" (its end is 3D, at rest or still moving), "flat" (at rest and
  /// planar), "between" (at rest, neither) or "moving" (not 3D and not yet at
  /// rest when the duration ran out: undecided).
  std::string outcome() const {
    const double td = threedim(r.positions);
    if (td >= kJumpThreedim) return "jumped";
    if (r.status != DynamicsStatus::Rest) return "moving";
    return td < kPlanarThreedim ? "flat" : "between";
  }
};

Release release(const Coil& c, double mu, double h) {
  DynamicsOptions o;
  o.model.link = c.link;
  o.time_step = h;
  o.duration = kDuration;
  o.damping = kDamping;
  o.friction = mu;
  o.friction_velocity = kFrictionVelocity;
  o.rest_speed = kRestSpeed;
  o.frame_every = std::max(1, static_cast<int>(kTrajectoryEvery * kTimeStep / h));
  Release out{&c, mu, h, {}, 0.0};
  const auto t0 = std::chrono::steady_clock::now();
  out.r = simulate(c.flat, c.rest, o);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::ostringstream line;  // one write per line: workers print concurrently
  line << "exp_jumping_dynamics: " << c.knot << " mu " << mu << " h " << h << ": " << out.outcome() << " ("
       << out.r.status << " at t = " << out.r.time << ", 3D-ness " << threedim(out.r.positions) << ", "
       << out.seconds << " s)\n";
  std::cout << line.str() << std::flush;
  return out;
}

std::string run_name(const Release& x) {
  std::ostringstream s;
  s << "mu" << x.mu << (x.h == kTimeStep ? "" : "_h" + Csv::num(x.h, 4));
  return s.str();
}

/// trajectories/<knot>_<run>.csv and curves/<knot>_<run>_end.obj; the
/// figure knot's frictionless run also keeps every frame in frames/<knot>/.
void write_run(const Args& a, const Release& x, Csv& table) {
  const std::string name = x.coil->knot + "_" + run_name(x);
  Csv t(a.out + "/trajectories/" + name + ".csv", {"time", "kinetic", "elastic", "threedim", "max_speed", "contacts"});
  for (const DynamicsFrame& f : x.r.frames)
    t.row({Csv::num(f.time), Csv::num(f.kinetic), Csv::num(f.elastic), Csv::num(threedim(f.positions)),
           Csv::num(f.max_speed), std::to_string(f.contacts)});
  t.commit();
  write_curve(a.out + "/curves/" + name + "_end.obj", x.r.positions);
  if (x.coil->knot == kFigureKnot && x.mu == 0.0 && x.h == kTimeStep) {
    std::filesystem::create_directories(a.out + "/frames/" + x.coil->knot);
    for (size_t k = 0; k < x.r.frames.size(); ++k) {
      char file[32];
      std::snprintf(file, sizeof file, "%05zu.obj", k);
      write_curve(a.out + "/frames/" + x.coil->knot + "/" + file, x.r.frames[k].positions);
    }
  }
  const double link_error = std::abs(x.r.link - x.coil->link);
  table.row({x.coil->knot, Csv::num(x.mu), Csv::num(x.h), to_string(x.r.status), x.outcome(), Csv::num(threedim(x.r.positions)),
             x.r.rest_time ? Csv::num(*x.r.rest_time) : "", Csv::num(x.r.max_speed), Csv::num(x.r.max_kinetic),
             Csv::num(x.r.frames.front().elastic), Csv::num(x.r.frames.back().elastic),
             Csv::num(similarity(x.r.positions, x.coil->released)), Csv::num(similarity(x.r.positions, x.coil->target)),
             Csv::num(link_error), Csv::flag(x.r.alexander_preserved), std::to_string(x.r.steps),
             std::to_string(x.r.newton_iterations), Csv::num(x.seconds, 4), "trajectories/" + name + ".csv",
             "curves/" + name + "_end.obj"});
}

/// The bracket from a knot's releases: the largest μ that jumped below the
/// smallest at which it rests flat.
FrictionBracket bracket_of(const Coil& c, const std::vector<Release>& runs) {
  FrictionBracket b;
  b.knot = c.knot;
  for (const Release& x : runs)
    if (x.coil == &c && x.h == kTimeStep && x.outcome() == "flat" && (!b.mu_flat || x.mu < *b.mu_flat)) b.mu_flat = x.mu;
  for (const Release& x : runs)
    if (x.coil == &c && x.h == kTimeStep && x.outcome() == "jumped" && (!b.mu_flat || x.mu < *b.mu_flat) &&
        (!b.mu_jumps || x.mu > *b.mu_jumps))
      b.mu_jumps = x.mu;
  return b;
}

}  // namespace

int main(int argc, char** argv) {
  return run_experiment(argc, argv, "exp_jumping_dynamics", "Jumping knots released in time, with friction.", [](const Args& a) {
    const std::vector<Coil> coils = read_coils(a, by_scale(a, 0, 5, 20));
    const std::vector<double> grid = by_scale(a, std::vector<double>{0.0, 4.0}, std::vector<double>{0.0, 0.5, 1.0, 2.0, 4.0},
                                              std::vector<double>{0.0, 0.5, 1.0, 2.0, 4.0});
    const int halvings = by_scale(a, 0, 2, 2);
    const bool step_check = a.scale != Scale::CI;
    announce(a, "exp_jumping_dynamics",
             std::to_string(coils.size()) + " knots at " + std::to_string(grid.size()) + " friction coefficients, " +
                 std::to_string(halvings) + " halvings each",
             coils.size() * (grid.size() + halvings) * 8.0 / a.jobs);
    for (const char* d : {"/trajectories", "/curves"}) std::filesystem::create_directories(a.out + d);
    // the grid, every knot and μ at once
    std::vector<std::pair<const Coil*, double>> jobs;
    for (const Coil& c : coils)
      for (const double mu : grid) jobs.push_back({&c, mu});
    const Coil* figure = nullptr;
    for (const Coil& c : coils) figure = c.knot == kFigureKnot ? &c : figure;
    if (step_check) jobs.push_back({figure, -1.0});  // μ = 0 at h/2
    std::vector<Release> runs(jobs.size());
    parallel_for(jobs.size(), a.jobs, [&](size_t q) {
      runs[q] = jobs[q].second < 0 ? release(*jobs[q].first, 0.0, kTimeStep / 2) : release(*jobs[q].first, jobs[q].second, kTimeStep);
    });
    // each knot's bracket halved
    std::vector<std::vector<Release>> extra(coils.size());
    parallel_for(coils.size(), a.jobs, [&](size_t k) {
      FrictionBracket b = bracket_of(coils[k], runs);
      for (int s = 0; s < halvings && b.mu_jumps && b.mu_flat; ++s) {
        extra[k].push_back(release(coils[k], 0.5 * (*b.mu_jumps + *b.mu_flat), kTimeStep));
        const std::string o = extra[k].back().outcome();
        if (o != "jumped" && o != "flat") break;
        (o == "jumped" ? b.mu_jumps : b.mu_flat) = extra[k].back().mu;
      }
    });
    for (auto& e : extra) runs.insert(runs.end(), e.begin(), e.end());
    std::stable_sort(runs.begin(), runs.end(), [](const Release& x, const Release& y) {
      return x.coil != y.coil ? x.coil < y.coil : x.h != y.h ? x.h > y.h : x.mu < y.mu;
    });

    Csv table(a.out + "/dynamics.csv",
              {"knot", "mu", "time_step", "status", "outcome", "end_threedim", "rest_time", "max_speed", "max_kinetic",
               "start_energy", "end_energy", "similarity_static", "similarity_target", "link_error",
               "alexander_preserved", "steps", "newton_iterations", "seconds", "trajectory", "curve_end"});
    JumpingDynamicsSummary sum;
    for (const Release& x : runs) write_run(a, x, table);
    table.commit();
    sum.scale = a.scale_name;
    sum.time_step = kTimeStep;
    sum.duration = kDuration;
    sum.damping = kDamping;
    sum.density = DynamicsOptions().density;
    sum.friction_velocity = kFrictionVelocity;
    sum.rest_speed = kRestSpeed;
    sum.mu_grid = grid;
    sum.bisection_steps = halvings;
    sum.threedim_threshold = kJumpThreedim;
    sum.planar_threshold = kPlanarThreedim;
    sum.cut = kClusterCut;
    sum.figure_knot = kFigureKnot;
    for (const Coil& c : coils) {
      sum.knots.push_back(c.knot);
      sum.brackets.push_back(bracket_of(c, runs));
      for (const Release& x : runs)
        if (x.coil == &c && x.mu == 0.0 && x.h == kTimeStep && x.outcome() == "jumped") sum.jumping_without_friction.push_back(c.knot);
    }
    if (step_check) {
      const Release *full = nullptr, *half = nullptr;
      for (const Release& x : runs)
        if (x.coil == figure && x.mu == 0.0) (x.h == kTimeStep ? full : half) = &x;
      StepCheck s;
      s.knot = figure->knot;
      s.time_step = half->h;
      s.similarity = similarity(half->r.positions, full->r.positions);
      s.rest_time = half->r.rest_time.value_or(half->r.time);
      s.rest_time_full = full->r.rest_time.value_or(full->r.time);
      sum.step_check = s;
    }
    sum.runs = static_cast<int>(runs.size());
    sum.seconds = elapsed_seconds();
    sum.radius = RelaxOptions().material.radius;
    write_summary(a, sum);
  });
}
