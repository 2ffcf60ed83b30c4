// knots similarity A B [--reverse] [--mirror] [--samples N] [--json]
#include <algorithm>
#include <iostream>

#include "args.hpp"
#include "commands.hpp"
#include "ek/analysis/json.hpp"
#include "ek/core/errors.hpp"
#include "ek/geometry/curve_io.hpp"
#include "output.hpp"

namespace ek::cli {

int cmd_similarity(int argc, char** argv) {
  std::string file_a, file_b;
  bool reverse = false, mirror = false, json = false;
  std::optional<int> samples;
  ArgParser args("similarity", "A B [--reverse] [--mirror] [--samples N] [--json]");
  args.positional("A", &file_a, "first closed curve, .obj or .txt");
  args.positional("B", &file_b, "second closed curve, .obj or .txt");
  args.flag("--reverse", &reverse, "also compare with B's orientation reversed (convolutions)");
  args.flag("--mirror", &mirror, "also compare with B's mirror image (torsion sign flipped)");
  args.option("--samples", &samples,
              "common vertex count n (default: the smaller vertex count; curves with another count are "
              "resampled at equal arc length)");
  args.flag("--json", &json, "print one JSON object");
  if (!args.parse(argc, argv)) return 0;
  require_input(!samples || *samples >= 4, "--samples must be at least 4");

  const Points A = read_curve(file_a);
  const Points B = read_curve(file_b);
  SimilarityOptions opt;
  opt.reversal = reverse;
  opt.mirror = mirror;
  opt.samples = samples.value_or(0);
  const SimilarityResult r = compare_curves(A, B, opt);
  if (json) {
    Json j;
    j["file_a"] = file_a;
    j["file_b"] = file_b;
    j.update(similarity_json(r, opt));
    print_json(j);
    return 0;
  }
  std::cout << "similarity:            " << fmt(r.similarity) << "\n"
            << "curvature correlation: " << fmt(r.curvature_correlation) << "\n"
            << "torsion correlation:   " << fmt(r.torsion_correlation) << "\n"
            << "best shift:            " << r.best_shift << " (vertex i of A matches vertex i + " << r.best_shift
            << " of B" << (r.reversed ? " reversed" : "") << (r.mirrored ? " mirrored" : "") << ", at n = "
            << r.samples << ")\n";
  return 0;
}

}  // namespace ek::cli
