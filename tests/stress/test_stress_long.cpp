// Long stress runs for `make stress`: the volume of lattice samples over knots
// up to 12 crossings: 10,000 by default (at least 10,000 in `make stress`;
// about 2 h on two cores at ~1.2 s per relaxation);
// EK_STRESS_VOLUME=N for a shorter or longer run. Two jobs. Counts are printed,
// with a progress line every 500 runs. EK_STRESS_LOG=FILE writes one CSV row per
// run (index, knot, seed, status, iterations, seconds, energy, gradient norm,
// Alexander preserved) to FILE.partial and renames it to FILE at the end, so an
// interrupted run never replaces an earlier complete log. An interrupted run
// resumes: the rows of an existing FILE.partial are counted and only the
// missing indices are run (run k is fixed by k: knot k·7919 modulo the number
// of knots, seed k + 1; delete FILE.partial to start over after changing the
// code). A log with runs beyond EK_STRESS_VOLUME is refused and left as it is.
// EK_STRESS_METHOD=M relaxes by the named method M of with_method() (default:
// "default"); a volume is run by one method from start to end.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <mutex>
#include <sstream>
#include <string>
#include <vector>
#include <thread>

#include "ek/core/atomic_file.hpp"
#include "ek/lattice/sampling.hpp"
#include "stress_common.hpp"

using namespace ek;

TEST(StressLong, VolumeOfLatticeSamples) {
  const char* env = std::getenv("EK_STRESS_VOLUME");
  int volume = 10000;
  if (env) {  // the whole value must be a positive integer ("10,000" or "1e4" are refused)
    char* end = nullptr;
    const long v = std::strtol(env, &end, 10);
    volume = (end != env && *end == '\0' && v > 0 && v <= 10000000) ? static_cast<int>(v) : 0;
  }
  ASSERT_GT(volume, 0) << "EK_STRESS_VOLUME must be a positive integer, got '" << (env ? env : "") << "'";
  const char* method_env = std::getenv("EK_STRESS_METHOD");
  const std::string method = method_env ? method_env : "default";
  RelaxOptions options;
  try {
    options = with_method(options, method);
  } catch (const std::exception& e) {
    FAIL() << "EK_STRESS_METHOD: " << e.what();
  }
  std::cout << "[ stress   ] method " << method << std::endl;
  const auto knots = KnotTable::global().up_to_crossings(12);
  stress::Tally tally;
  std::mutex mutex;
  const char* log_env = std::getenv("EK_STRESS_LOG");
  const std::string log_path = log_env ? log_env : "";
  const std::string header = "index,knot,seed,status,iterations,seconds,energy,gradient_norm,alexander_preserved";
  std::vector<char> done(static_cast<size_t>(volume), 0);
  std::ofstream log;
  if (!log_path.empty()) {
    const std::string partial = log_path + ".partial";
    // resume: keep the complete rows of an interrupted run (a row cut by the
    // interruption is dropped and run again), rewritten before appending
    std::vector<std::string> kept;
    if (std::ifstream in(partial); in) {
      std::string line;
      std::getline(in, line);
      ASSERT_EQ(line, header) << partial << " is not a stress log; move it away to start over";
      while (std::getline(in, line) && !in.eof()) {  // the last line counts only if it ends with '\n'
        std::vector<std::string> f;
        std::stringstream ss(line);
        for (std::string x; std::getline(ss, x, ',');) f.push_back(x);
        if (f.size() != 9) continue;
        const int k = std::atoi(f[0].c_str());
        ASSERT_LT(k, volume) << partial << " has runs beyond the volume " << volume
                             << "; rerun with that log's volume or move it away";
        if (k < 0 || done[static_cast<size_t>(k)]) continue;
        done[static_cast<size_t>(k)] = 1;
        tally.add_logged(f[3], std::isfinite(std::strtod(f[6].c_str(), nullptr)) &&
                                   std::isfinite(std::strtod(f[7].c_str(), nullptr)),
                         f[8] == "1", f[1]);
        kept.push_back(line);
      }
      std::cout << "[ stress   ] resuming " << partial << ": " << kept.size() << " runs already done" << std::endl;
    }
    {  // the kept rows replace the old log atomically: an interruption here loses nothing
      AtomicFile out(partial);
      out.stream() << header << "\n";
      for (const auto& line : kept) out.stream() << line << "\n";
      out.commit();
    }
    log.open(partial, std::ios::app);
    ASSERT_TRUE(log) << "cannot write the stress log " << partial;
  }
  const auto start = std::chrono::steady_clock::now();
  std::atomic<int> next{0};
  auto worker = [&]() {
    for (;;) {
      const int k = next.fetch_add(1);
      if (k >= volume) return;
      if (done[static_cast<size_t>(k)]) continue;
      // knots spread over the table, one sample each (seed = index)
      const KnotRecord& knot = *knots[static_cast<size_t>(k) * 7919 % knots.size()];
      SampleOptions so;
      so.vertices = 400;
      so.seed = static_cast<std::uint64_t>(k) + 1;
      RelaxResult r;
      try {
        const Points P = to_points(sample_knot(knot, so).samples.front());
        r = relax(P, options);
      } catch (const std::exception& e) {
        std::lock_guard<std::mutex> lock(mutex);
        ADD_FAILURE() << knot.name << ": " << e.what();
        continue;
      }
      std::lock_guard<std::mutex> lock(mutex);
      tally.add(r, knot.name);
      if (log) {
        char row[512];
        std::snprintf(row, sizeof row, "%d,%s,%llu,%s,%d,%.4f,%.10g,%.3e,%d\n", k, knot.name.c_str(),
                      static_cast<unsigned long long>(so.seed), to_string(r.status()).c_str(), r.report.iterations,
                      r.report.seconds, r.energy.total, r.report.gradient_norm, r.alexander_preserved ? 1 : 0);
        log << row << std::flush;
      }
      if (tally.runs % 500 == 0) {
        const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        tally.print("progress " + std::to_string(tally.runs) + "/" + std::to_string(volume) + " after " +
                    std::to_string(static_cast<int>(s)) + " s");
      }
    }
  };
  std::thread t1(worker), t2(worker);
  t1.join();
  t2.join();
  tally.print("volume " + std::to_string(volume));
  if (log) {
    log.close();
    ASSERT_EQ(std::rename((log_path + ".partial").c_str(), log_path.c_str()), 0)
        << "cannot rename the stress log to " << log_path;
  }
  EXPECT_EQ(tally.topology_changes, 0);
  EXPECT_EQ(tally.runs, volume);
}
