// knots sample NAME|FILE --count K [-n N] [--seed S] -o DIR [--decorrelation STEPS] [--format obj|txt]
//               [--overwrite] [--json]
//
// Writes DIR/<name>-0000.<ext> ... (K files). NAME is a knot of the table;
// FILE (.obj or .txt) is a closed curve, used as it is when it already is a
// self-avoiding lattice polygon and rounded onto the lattice otherwise; the
// outputs are then named after the file's stem. Existing output files are an
// error unless --overwrite is given; all samples are computed before the
// first file is written, and every file is written atomically, so a failed
// run leaves the folder as it was.
#include <filesystem>
#include <iostream>

#include "args.hpp"
#include "commands.hpp"
#include "ek/core/atomic_file.hpp"
#include "ek/core/errors.hpp"
#include "ek/geometry/curve_io.hpp"
#include "ek/knots/alexander.hpp"
#include "ek/lattice/sampling.hpp"
#include "output.hpp"

namespace ek::cli {

namespace {

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::string numbered(const std::string& dir, const std::string& stem, int k, const std::string& ext) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "-%04d.", k);
  return (std::filesystem::path(dir) / (stem + buf + ext)).string();
}

}  // namespace

int cmd_sample(int argc, char** argv) {
  std::string input, dir, format = "obj";
  int count = 1;
  long long seed = 1;
  bool json = false, overwrite = false;
  SampleOptions opt;
  ArgParser args("sample",
                 "NAME|FILE --count K [-n N] [--seed S] -o DIR [--decorrelation STEPS] [--format obj|txt] "
                 "[--overwrite] [--json]");
  args.positional("NAME|FILE", &input,
                  "knot name as in the table, or a closed curve file (.obj or .txt) to start from");
  args.option("--count", &count, "number of samples K (default 1), one continuing BFACF walk");
  args.option("-n,--vertices", &opt.vertices, "vertices of every sample, even (default 400)");
  args.option("--seed", &seed, "seed of the walk's random numbers, >= 0 (default 1)");
  args.option("-o,--output", &dir, "output folder (created if missing); files <name>-0000.<ext>, ...");
  args.option("--decorrelation", &opt.decorrelation_moves,
              "extra attempted BFACF moves at the peak length between samples (default 0)");
  args.option("--grow-fugacity", &opt.grow_fugacity, "fugacity of the growth phase, > 0.2135 (default 0.4)");
  args.option("--shrink-fugacity", &opt.shrink_fugacity, "fugacity of the shrink phase, < 0.2135 (default 0.1)");
  args.option("--growth-factor", &opt.growth_factor, "the growth phase ends at this multiple of n (default 10)");
  args.option("--format", &format, "obj (default) or txt");
  args.flag("--overwrite", &overwrite, "replace existing output files (otherwise they are an error)");
  args.flag("--json", &json, "print a JSON summary");
  if (!args.parse(argc, argv)) return 0;
  if (dir.empty()) throw InputError("missing -o DIR");
  if (format != "obj" && format != "txt") throw InputError("--format: expected obj or txt, got '" + format + "'");
  if (count < 1) throw InputError("--count: need at least 1 sample, got " + std::to_string(count));
  if (count > 9999) throw InputError("--count: at most 9999 samples per run, got " + std::to_string(count));
  if (seed < 0) throw InputError("--seed: must be >= 0");
  opt.count = count;
  opt.seed = static_cast<std::uint64_t>(seed);

  // The start: a table knot or a curve file.
  const bool from_file = ends_with(input, ".obj") || ends_with(input, ".txt");
  std::string name, start_method;
  LatticePoints start;
  AlexanderPolynomial expected;
  std::optional<double> scale;
  const KnotRecord* knot = nullptr;
  Points curve;
  if (from_file) {
    name = std::filesystem::path(input).stem().string();
    if (name.empty()) throw InputError("cannot name the outputs after '" + input + "'");
    curve = read_curve(input);
  } else {
    knot = &KnotTable::global().at(input);
    name = knot->name;
  }

  // Outputs: checked before the (possibly long) run.
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
    throw InputError("cannot create the output folder '" + dir + "'" + (ec ? ": " + ec.message() : ""));
  std::vector<std::string> files;
  for (int k = 0; k < count; ++k) {
    files.push_back(numbered(dir, name, k, format));
    if (!overwrite && std::filesystem::exists(files.back()))
      throw InputError("output file " + files.back() + " exists (use --overwrite to replace it)");
    check_writable(files.back());
  }

  if (from_file) {
    expected = alexander(curve);
    if (as_lattice_polygon(curve, &start)) {
      start_method = "lattice";
    } else {
      const RoundingResult r = round_to_lattice(curve, {}, expected);
      start = r.points;
      start_method = "rounded";
      scale = r.scale;
    }
  } else {
    const LatticeStart s = lattice_start(*knot);
    start = s.points;
    start_method = s.method;
    expected = s.alexander;
    if (s.method != "square") scale = s.rounding.scale;
  }
  const SampleBatch batch = sample_lattice_polygons(start, opt, expected, name);
  for (int k = 0; k < count; ++k)
    write_curve(files[static_cast<size_t>(k)], to_points(batch.samples[static_cast<size_t>(k)]));

  long long moves = 0;
  for (const SampleReport& r : batch.reports) moves += r.decorrelation.attempts + r.grow.attempts + r.shrink.attempts;
  if (json) {
    Json j;
    j["name"] = name;
    j["input"] = from_file ? Json(input) : Json(nullptr);
    j["start"] = start_method;
    j["start_vertices"] = start.rows();
    j["rounding_scale"] = scale ? number(*scale) : Json(nullptr);
    j["vertices"] = opt.vertices;
    j["count"] = count;
    j["seed"] = seed;
    j["decorrelation"] = opt.decorrelation_moves;
    j["alexander"] = expected.coefficients;
    j["attempted_moves"] = moves;
    j["files"] = files;
    print_json(j);
  } else {
    std::cout << "wrote " << count << " sample" << (count > 1 ? "s" : "") << " of " << name << " (" << opt.vertices
              << " vertices, Alexander " << expected.to_string() << ") from a " << start.rows() << "-vertex "
              << start_method << " lattice polygon: " << files.front();
    if (count > 1) std::cout << " ... " << files.back();
    std::cout << "\n";
  }
  return 0;
}

}  // namespace ek::cli
