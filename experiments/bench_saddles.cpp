// exp_bench_saddles: macro benchmark of the saddle searches (docs/performance.md).
// Fixed BFACF lattice samples (seed 20230806, n = 400 unit edges) of the
// knots given (default 3_1, 4_1, 5_2), each relaxed to a stable state by the
// default method; from each state find_knot_saddles() with K modes (default
// 4, both directions). Reports per search its status and wall time, and the
// time per verified saddle (all searches' time over the verified ones) and the
// verified share. Then the double-ended searches: D relaxed samples of 4_1
// (the same seed and n; the first D stable ones of distinct energy among 4·D
// samples; default D = 3), and for each pair of them
// connect_states() (connect.hpp) with a budget of B searches (default 4) on
// a graph of the D states: the time per double-ended search
// (transition_search(), each attempt), the share of searches verified (one
// saddle joining their two states) and the share of pairs connected. Run
// pinned to one core by make bench.
//
//   exp_bench_saddles [--knots A,B,...] [--count C] [--modes K] [--n N]
//                     [--double-ended D] [--budget B] [--out DIR]
//
// Writes DIR/saddles_runs.csv (one row per search), DIR/saddles.csv (one
// summary row), DIR/double_ended_runs.csv (one row per double-ended search)
// and DIR/double_ended.csv (one summary row); prints them. D = 0 skips the
// double-ended part.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "ek/analysis/similarity.hpp"
#include "ek/core/errors.hpp"
#include "ek/knots/table.hpp"
#include "ek/lattice/lattice_polygon.hpp"
#include "ek/lattice/sampling.hpp"
#include "ek/solver/relax.hpp"
#include "ek/transitions/connect.hpp"
#include "ek/transitions/saddles.hpp"

namespace {

struct Config {
  std::vector<std::string> knots = {"3_1", "4_1", "5_2"};
  int count = 1, modes = 4, n = 400;
  int double_ended = 3, budget = 4;
  std::string out = "results/bench";
};

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, ',')) out.push_back(item);
  return out;
}

bool parse_numbers(int argc, char** argv, Config& c);

bool parse(int argc, char** argv, Config& c) {
  try {
    return parse_numbers(argc, argv, c);
  } catch (const std::exception&) {
    std::fprintf(stderr, "exp_bench_saddles: error: --count, --modes, --n, --double-ended and --budget take integers\n");
    return false;
  }
}

bool parse_numbers(int argc, char** argv, Config& c) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool value = i + 1 < argc;
    if (a == "--knots" && value) c.knots = split(argv[++i]);
    else if (a == "--count" && value) c.count = std::stoi(argv[++i]);
    else if (a == "--modes" && value) c.modes = std::stoi(argv[++i]);
    else if (a == "--n" && value) c.n = std::stoi(argv[++i]);
    else if (a == "--double-ended" && value) c.double_ended = std::stoi(argv[++i]);
    else if (a == "--budget" && value) c.budget = std::stoi(argv[++i]);
    else if (a == "--out" && value) c.out = argv[++i];
    else {
      std::fprintf(stderr, "exp_bench_saddles: error: unknown or incomplete argument '%s'\n", a.c_str());
      return false;
    }
  }
  if (c.count >= 1 && c.modes >= 1 && c.n >= 24 && c.n % 2 == 0 && c.double_ended >= 0 && c.budget >= 1) return true;
  std::fprintf(stderr,
               "exp_bench_saddles: error: need --count >= 1, --modes >= 1, an even --n >= 24, --double-ended >= 0 "
               "and --budget >= 1\n");
  return false;
}

}  // namespace

int run(const Config& c);
void run_double_ended(const Config& c);

int main(int argc, char** argv) {
  Config c;
  if (!parse(argc, argv, c)) return 2;
  try {
    return run(c);
  } catch (const ek::InputError& e) {
    std::fprintf(stderr, "exp_bench_saddles: error: %s\n", e.what());
    return 2;
  }
}

int run(const Config& c) {
  std::filesystem::create_directories(c.out);
  std::ofstream runs(c.out + "/saddles_runs.csv");
  runs << "knot,sample,mode,direction,status,verified,seconds,iterations,energy,barrier\n";
  int searches = 0, verified = 0;
  double seconds = 0.0;
  std::printf("saddle searches (n = %d, %d modes in both directions per state)\n", c.n, c.modes);
  for (const std::string& knot : c.knots) {
    ek::SampleOptions so;
    so.vertices = c.n;
    so.count = c.count;
    so.seed = 20230806;
    const ek::SampleBatch batch = ek::sample_knot(ek::KnotTable::global().at(knot), so);
    for (int s = 0; s < static_cast<int>(batch.samples.size()); ++s) {
      const ek::RelaxResult r = ek::relax(ek::to_points(batch.samples[s]));
      if (!r.stable()) continue;
      ek::KnotSaddleOptions o;
      o.modes = c.modes;
      const ek::VecX rest = ek::VecX::Ones(c.n);
      ek::SimilarityOptions sim;
      sim.reversal = true;
      const auto similarity = [sim](const ek::Points& a, const ek::Points& b) { return ek::similarity(a, b, sim); };
      const ek::SaddleStart start = ek::prepare_start(r.positions, rest, o);
      for (const ek::SaddleRecord& rec : ek::find_knot_saddles(start, rest, o, similarity)) {
        ++searches;
        verified += rec.verified;
        seconds += rec.seconds;
        runs << knot << "," << s << "," << rec.mode << "," << rec.direction << "," << ek::to_string(rec.status) << ","
             << (rec.verified ? "true" : "false") << "," << rec.seconds << "," << rec.iterations << ","
             << rec.energy << "," << (rec.verified ? rec.energy - start.energy : 0.0) << "\n";
        std::printf("  %-6s sample %d mode %d %+d: %-20s %7.2f s %4d iterations\n", knot.c_str(), s, rec.mode,
                    rec.direction, ek::to_string(rec.status).c_str(), rec.seconds, rec.iterations);
      }
    }
  }
  const double per_saddle = verified > 0 ? seconds / verified : 0.0;
  std::ofstream sum(c.out + "/saddles.csv");
  sum << "searches,verified,verified_share,seconds,seconds_per_search,seconds_per_verified_saddle\n"
      << searches << "," << verified << "," << (searches ? double(verified) / searches : 0.0) << "," << seconds << ","
      << (searches ? seconds / searches : 0.0) << "," << per_saddle << "\n";
  std::printf("%d of %d searches verified (%.0f%%), %.1f s per search, %.1f s per verified saddle\n", verified,
              searches, searches ? 100.0 * verified / searches : 0.0, searches ? seconds / searches : 0.0, per_saddle);
  if (c.double_ended > 0) run_double_ended(c);
  return 0;
}

void run_double_ended(const Config& c) {
  ek::SampleOptions so;
  so.vertices = c.n;
  so.count = 4 * c.double_ended;
  so.seed = 20230806;
  const ek::SampleBatch batch = ek::sample_knot(ek::KnotTable::global().at("4_1"), so);
  ek::TransitionGraph states;
  states.knot = "4_1";
  ek::KnotSaddleOptions o;
  const ek::VecX rest = ek::VecX::Ones(c.n);
  for (const auto& p : batch.samples) {  // the first D stable ones of distinct energy (1e-6 relative)
    if (static_cast<int>(states.states.size()) == c.double_ended) break;
    const ek::RelaxResult r = ek::relax(ek::to_points(p));
    if (!r.stable()) continue;
    const ek::SaddleStart start = ek::prepare_start(r.positions, rest, o);
    bool known = false;
    for (const ek::TransitionState& s : states.states) known |= std::abs(s.energy - start.energy) <= 1e-6 * start.energy;
    if (known) continue;
    states.states.push_back({-1, -1, start.energy, start.positions});
    states.energy_scale = start.energy_scale;
  }
  ek::SimilarityOptions sim;
  sim.reversal = true;
  const auto similarity = [sim](const ek::Points& a, const ek::Points& b) { return ek::similarity(a, b, sim); };
  ek::ConnectOptions co;
  co.max_searches = c.budget;
  std::ofstream runs(c.out + "/double_ended_runs.csv");
  runs << "a,b,u,v,status,verified,reached,seconds\n";
  int searches = 0, verified = 0, pairs = 0, connected = 0;
  double seconds = 0.0;
  std::printf("double-ended searches (4_1, n = %d, %zu stable samples, budget %d per pair)\n", c.n,
              states.states.size(), c.budget);
  const int m = static_cast<int>(states.states.size());
  for (int a = 0; a < m; ++a)
    for (int b = a + 1; b < m; ++b) {
      ek::TransitionGraph g = states;
      const ek::ConnectResult r = ek::connect_states(g, a, b, rest, co, similarity, 0.95);
      ++pairs;
      connected += r.connected;
      for (const ek::ConnectAttempt& t : r.attempt_list) {
        ++searches;
        verified += t.status.verified();
        seconds += t.seconds;
        runs << a << "," << b << "," << t.u << "," << t.v << "," << ek::to_string(t.status) << ","
             << (t.status.verified() ? "true" : "false") << "," << (t.reached ? "true" : "false") << ","
             << t.seconds << "\n";
      }
      const std::string status = ek::to_string(r.status);
      std::printf("  %d -> %d: %-10s %d searches %7.2f s%s\n", a, b, status.c_str(), r.attempts, r.seconds,
                  r.connected ? (", barrier " + std::to_string(r.barrier_forward_scaled) + " EI/L").c_str() : "");
    }
  std::ofstream sum(c.out + "/double_ended.csv");
  sum << "pairs,connected,connected_share,searches,verified,verified_share,seconds,seconds_per_search\n"
      << pairs << "," << connected << "," << (pairs ? double(connected) / pairs : 0.0) << "," << searches << ","
      << verified << "," << (searches ? double(verified) / searches : 0.0) << "," << seconds << ","
      << (searches ? seconds / searches : 0.0) << "\n";
  std::printf("%d of %d pairs connected; %d of %d double-ended searches verified, %.1f s per search\n", connected,
              pairs, verified, searches, searches ? seconds / searches : 0.0);
}
