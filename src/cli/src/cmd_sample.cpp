// knots sample NAME|FILE --count K [-n N] [--seed S] -o DIR [--decorrelation STEPS] [--format obj|txt]
//               [--overwrite] [--json]
//
// Writes DIR/<name>-0000.<ext> ... (K files). NAME is a knot of the table or
// a link of the link table; FILE (.obj or .txt) is a closed curve or a link,
// used as it is when it already is on the lattice and rounded onto the
// lattice otherwise; the outputs are then named after the file's stem. A
// link's samples are link files. Existing output files are an
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
#include "ek/geometry/link.hpp"
#include "ek/knots/link_table.hpp"
#include "ek/lattice/link_sampling.hpp"
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

/// The command line of `knots sample`.
struct SampleArgs {
  std::string input, dir, format = "obj";
  int count = 1;
  long long seed = 1;
  bool json = false, overwrite = false;
  SampleOptions opt;
};

/// Parses and checks the command line; false when it asked for help.
bool parse_sample_args(int argc, char** argv, SampleArgs& a) {
  SampleOptions& opt = a.opt;
  ArgParser args("sample",
                 "NAME|FILE --count K [-n N] [--seed S] -o DIR [--decorrelation STEPS] [--format obj|txt] "
                 "[--overwrite] [--json]");
  args.positional("NAME|FILE", &a.input,
                  "knot name as in the table, a link of the link table, or a curve or link file (.obj or .txt) to "
                  "start from");
  args.option("--count", &a.count, "number of samples K (default 1), one continuing BFACF walk");
  args.option("-n,--vertices", &opt.vertices,
              "vertices of every sample, even (default 400); a link's, in all, shared by its components in "
              "proportion to their lengths");
  args.option("--seed", &a.seed, "seed of the walk's random numbers, >= 0 (default 1)");
  args.option("-o,--output", &a.dir, "output folder (created if missing); files <name>-0000.<ext>, ...");
  args.option("--decorrelation", &opt.decorrelation_moves,
              "extra attempted BFACF moves at the peak length between samples (default 0)");
  args.option("--grow-fugacity", &opt.grow_fugacity, "fugacity of the growth phase, > 0.2135 (default 0.4)");
  args.option("--shrink-fugacity", &opt.shrink_fugacity, "fugacity of the shrink phase, < 0.2135 (default 0.1)");
  args.option("--growth-factor", &opt.growth_factor, "the growth phase ends at this multiple of n (default 10)");
  args.option("--format", &a.format, "obj (default) or txt");
  args.flag("--overwrite", &a.overwrite, "replace existing output files (otherwise they are an error)");
  args.flag("--json", &a.json, "print a JSON summary");
  if (!args.parse(argc, argv)) return false;
  if (a.dir.empty()) throw InputError("missing -o DIR");
  if (a.format != "obj" && a.format != "txt") throw InputError("--format: expected obj or txt, got '" + a.format + "'");
  if (a.count < 1) throw InputError("--count: need at least 1 sample, got " + std::to_string(a.count));
  if (a.count > 9999) throw InputError("--count: at most 9999 samples per run, got " + std::to_string(a.count));
  if (a.seed < 0) throw InputError("--seed: must be >= 0");
  opt.count = a.count;
  opt.seed = static_cast<std::uint64_t>(a.seed);
  return true;
}

/// What the walk starts from: a table knot or a curve file (read here, so
/// that a bad input fails before anything is written).
struct SampleSource {
  bool from_file = false;
  std::string name;  // names the outputs
  const KnotRecord* knot = nullptr;
  const LinkRecord* link_record = nullptr;  // a link of the link table
  Points curve;
  Link link;  // a link file of several components

  bool is_link() const { return link_record || link.size() > 1; }
};

SampleSource open_source(const std::string& input) {
  SampleSource src;
  src.from_file = ends_with(input, ".obj") || ends_with(input, ".txt");
  if (src.from_file) {
    src.name = std::filesystem::path(input).stem().string();
    if (src.name.empty()) throw InputError("cannot name the outputs after '" + input + "'");
    src.link = read_link(input);
    if (src.link.size() == 1) src.curve = src.link[0];
  } else if ((src.link_record = find_link(input))) {
    src.name = src.link_record->name;
  } else {
    src.knot = &KnotTable::global().at(input);
    src.name = src.knot->name;
  }
  return src;
}

/// The output files DIR/<name>-0000.<ext>, ...: the folder is created, and
/// the files checked before the (possibly long) run.
std::vector<std::string> output_files(const SampleArgs& a, const std::string& name) {
  std::error_code ec;
  std::filesystem::create_directories(a.dir, ec);
  if (ec || !std::filesystem::is_directory(a.dir))
    throw InputError("cannot create the output folder '" + a.dir + "'" + (ec ? ": " + ec.message() : ""));
  std::vector<std::string> files;
  for (int k = 0; k < a.count; ++k) {
    files.push_back(numbered(a.dir, name, k, a.format));
    if (!a.overwrite && std::filesystem::exists(files.back()))
      throw InputError("output file " + files.back() + " exists (use --overwrite to replace it)");
    check_writable(files.back());
  }
  return files;
}

void print_summary(const SampleArgs& a, const SampleSource& src, const LatticeStart& start, const SampleBatch& batch,
                   const std::vector<std::string>& files) {
  if (a.json) {
    Json j;
    j["name"] = src.name;
    j["input"] = src.from_file ? Json(a.input) : Json(nullptr);
    j["start"] = to_string(start.method);
    j["start_vertices"] = start.points.rows();
    const std::optional<double> scale = start.rounding_scale();
    j["rounding_scale"] = scale ? number(*scale) : Json(nullptr);
    j["vertices"] = a.opt.vertices;
    j["count"] = a.count;
    j["seed"] = a.seed;
    j["decorrelation"] = a.opt.decorrelation_moves;
    j["alexander"] = start.alexander.coefficients;
    j["attempted_moves"] = batch.attempted_moves();
    j["files"] = files;
    print_json(j);
  } else {
    std::cout << "wrote " << a.count << " sample" << (a.count > 1 ? "s" : "") << " of " << src.name << " ("
              << a.opt.vertices << " vertices, Alexander " << start.alexander.to_string() << ") from a "
              << start.points.rows() << "-vertex " << to_string(start.method) << " lattice polygon: " << files.front();
    if (a.count > 1) std::cout << " ... " << files.back();
    std::cout << "\n";
  }
}

/// A link: lattice_link_start() and sample_lattice_link(); the files are
/// link files (one closed loop per component).
int sample_link(const SampleArgs& a, const SampleSource& src, const std::vector<std::string>& files) {
  const LatticeLinkStart start =
      src.link_record ? lattice_link_start(*src.link_record) : lattice_link_start(src.link);
  const LinkSampleBatch batch = sample_lattice_link(start.components, a.opt, start.type, src.name);
  for (int k = 0; k < a.count; ++k) write_link(files[static_cast<size_t>(k)], to_link(batch.samples[static_cast<size_t>(k)]));
  int start_vertices = 0;
  for (const LatticePoints& L : start.components) start_vertices += static_cast<int>(L.rows());
  if (a.json) {
    Json j;
    j["name"] = src.name;
    j["input"] = src.from_file ? Json(a.input) : Json(nullptr);
    j["start"] = start.scale > 0.0 ? "rounded" : "lattice";
    j["start_vertices"] = start_vertices;
    j["rounding_scale"] = start.scale > 0.0 ? number(start.scale) : Json(nullptr);
    j["vertices"] = a.opt.vertices;
    j["components"] = start.components.size();
    j["component_vertices"] = batch.component_vertices;
    j["count"] = a.count;
    j["seed"] = a.seed;
    j["linking_numbers"] = integer_matrix_json(start.type.linking_numbers);
    j["conway"] = start.type.conway.coefficients;
    j["attempted_moves"] = batch.attempted_moves;
    j["files"] = files;
    print_json(j);
  } else {
    std::cout << "wrote " << a.count << " sample" << (a.count > 1 ? "s" : "") << " of " << src.name << " ("
              << start.components.size() << " components, " << start.type.to_string() << ") from a " << start_vertices
              << "-vertex lattice link: " << files.front();
    if (a.count > 1) std::cout << " ... " << files.back();
    std::cout << "\n";
  }
  return 0;
}

}  // namespace

int cmd_sample(int argc, char** argv) {
  SampleArgs a;
  if (!parse_sample_args(argc, argv, a)) return 0;
  const SampleSource src = open_source(a.input);
  const std::vector<std::string> files = output_files(a, src.name);
  if (src.is_link()) return sample_link(a, src, files);
  // a curve file is used as it is when it is a lattice polygon and rounded otherwise
  const LatticeStart start = src.from_file ? lattice_start(src.curve) : lattice_start(*src.knot);
  const SampleBatch batch = sample_lattice_polygons(start.points, a.opt, start.alexander, src.name);
  for (int k = 0; k < a.count; ++k)
    write_curve(files[static_cast<size_t>(k)], to_points(batch.samples[static_cast<size_t>(k)]));
  print_summary(a, src, start, batch, files);
  return 0;
}

}  // namespace ek::cli
