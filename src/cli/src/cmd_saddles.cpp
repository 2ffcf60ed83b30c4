// knots saddles STATE [--modes K] [--link LK] [--rest-length L] [--max-iter N] [--displacement D]
//               [--images M] -o DIR [--overwrite] [--json]
//
// DIR is written as a whole: into a temporary folder beside it, renamed into
// place when every file is there. An existing DIR is an error before any
// search unless --overwrite is given; it is then replaced only after the new
// folder is complete.
#include <filesystem>
#include <iostream>
#include <unistd.h>

#include "args.hpp"
#include "commands.hpp"
#include "ek/analysis/similarity.hpp"
#include "ek/core/atomic_file.hpp"
#include "ek/core/errors.hpp"
#include "ek/core/stopwatch.hpp"
#include "ek/geometry/curve_io.hpp"
#include "ek/transitions/saddles.hpp"
#include "folder_output.hpp"
#include "output.hpp"
#include "saddle_json.hpp"

namespace ek::cli {
namespace {

namespace fs = std::filesystem;

struct SaddlesCommand {
  std::string file, out;
  double rest_length = 1.0;  // [length]
  bool json = false, overwrite = false;
  KnotSaddleOptions options;
};

bool parse_saddles(int argc, char** argv, SaddlesCommand& c) {
  KnotSaddleOptions& o = c.options;
  ArgParser args("saddles", "STATE [--modes K] [--link LK] [--rest-length L] [--max-iter N] [--displacement D] "
                            "[--images M] -o DIR [--overwrite] [--json]");
  args.positional("STATE", &c.file, "a stable equilibrium (.obj or .txt), e.g. from knots relax or knots export");
  args.option("-o,--output", &c.out, "folder for the summary, saddles, minima and paths (must not exist)");
  args.flag("--overwrite", &c.overwrite, "replace an existing output folder (after the run, when complete)");
  args.option("--modes", &o.modes, "softest non-rigid modes searched, each in both directions (default 4)");
  args.option("--link", &o.relax.link, "prescribed link Lk (the full model with Theta fixed); default: Theta free");
  args.option("--rest-length", &c.rest_length,
              "rest length of every edge (default 1: the data sets' lattice edges)");
  args.option("--max-iter", &o.search.max_iterations, "iterations per search (default 400)");
  args.option("--displacement", &o.displacement,
              "largest vertex displacement of the saddle along its negative mode before each descent (default 0.02)");
  args.option("--images", &o.max_images, "images kept per descent (default 24)");
  args.flag("--verbose", &o.search.verbose, "print each search iteration on stderr");
  args.flag("--json", &c.json, "print the summary as one JSON object");
  return args.parse(argc, argv);
}

Json summary_json(const SaddlesCommand& c, const SaddleStart& s, const std::vector<SaddleRecord>& records,
                  double seconds) {
  Json j = start_json(s);
  j["input"] = c.file;
  j["modes"] = c.options.modes;
  j["link"] = c.options.relax.link ? number(*c.options.relax.link) : Json(nullptr);
  j["saddles"] = saddles_json(records, s.energy, s.energy_scale);
  j["searches"] = searches_json(records, s.energy);
  j["output"] = c.out;
  j["seconds"] = number(seconds);
  return j;
}

/// The folder's files (folder_output.hpp: written as a whole).
void write_outputs(const SaddlesCommand& c, const SaddleStart& s, const std::vector<SaddleRecord>& records,
                   const Json& summary) {
  write_folder(c.out, [&](const fs::path& tmp) {
    write_curve((tmp / "start.obj").string(), s.positions);
    for (size_t k = 0; k < records.size(); ++k) {
      const SaddleRecord& r = records[k];
      if (!r.verified || r.duplicate_of >= 0) continue;
      const std::string id = std::to_string(k);
      write_curve((tmp / ("saddle_" + id + ".obj")).string(), r.saddle);
      write_curve((tmp / ("minimum_" + id + ".obj")).string(), r.minima[1].positions);
      std::vector<double> energies;
      int at = 0;
      const std::vector<Points> path = saddle_path(r, energies, at);
      write_path_obj((tmp / ("path_" + id + ".obj")).string(), path, energies);
    }
    write_summary_json(tmp, summary);
  });
}

void print_text(const SaddleStart& s, const std::vector<SaddleRecord>& records, double seconds) {
  std::cout << "start:   energy " << fmt(s.energy) << ", gradient " << fmt(s.gradient_norm, 3) << ", softest modes";
  for (Eigen::Index k = 0; k < s.mode_eigenvalues.size(); ++k) std::cout << " " << fmt(s.mode_eigenvalues(k), 4);
  std::cout << "\n";
  int verified = 0;
  for (size_t k = 0; k < records.size(); ++k) {
    const SaddleRecord& r = records[k];
    std::cout << "search " << k << " (mode " << r.mode << (r.direction > 0 ? " +" : " -")
              << "): " << to_string(r.status);
    if (r.verified) {
      ++verified;
      std::cout << ", energy " << fmt(r.energy) << ", barrier " << fmt(r.energy - s.energy, 6) << " / "
                << fmt(r.energy - r.minima[1].energy, 6) << ", lambda " << fmt(r.negative_eigenvalue, 4);
      if (r.duplicate_of >= 0) std::cout << " (same saddle as search " << r.duplicate_of << ")";
    }
    std::cout << " (" << r.iterations << " iterations, " << fmt(r.seconds, 3) << " s)\n";
  }
  std::cout << verified << " of " << records.size() << " searches ended in a verified saddle, " << fmt(seconds, 4)
            << " s\n";
}

}  // namespace

int cmd_saddles(int argc, char** argv) {
  SaddlesCommand c;
  if (!parse_saddles(argc, argv, c)) return 0;
  require_input(c.rest_length > 0.0 && std::isfinite(c.rest_length), "--rest-length must be positive");
  c.options.validate();
  check_output_folder(c.out, c.overwrite);
  const Stopwatch t0;
  const Points state = read_curve(c.file);
  const VecX rest = VecX::Constant(state.rows(), c.rest_length);
  const SaddleStart start = prepare_start(state, rest, c.options);
  SimilarityOptions so;
  so.reversal = true;
  const CurveSimilarity sim = [so](const Points& a, const Points& b) { return similarity(a, b, so); };
  const std::vector<SaddleRecord> records = find_knot_saddles(start, rest, c.options, sim);
  const double seconds = t0.seconds();
  const Json summary = summary_json(c, start, records, seconds);
  write_outputs(c, start, records, summary);
  if (c.json) print_json(summary);
  else print_text(start, records, seconds);
  return 0;
}

}  // namespace ek::cli
