// knots similarity A B [--reverse] [--mirror] [--samples N] [--json]
#include <algorithm>
#include <iostream>

#include "args.hpp"
#include "commands.hpp"
#include "ek/analysis/json.hpp"
#include "ek/analysis/link_similarity.hpp"
#include "ek/geometry/link.hpp"
#include "ek/core/errors.hpp"
#include "ek/geometry/curve_io.hpp"
#include "output.hpp"

namespace ek::cli {
namespace {

/// Two links: the best pairing of their components (link_similarity.hpp).
int print_links(const std::string& file_a, const std::string& file_b, const LinkSimilarityResult& r, bool json) {
  if (json) {
    Json j;
    j["file_a"] = file_a;
    j["file_b"] = file_b;
    j["components"] = r.pairing.size();
    j["similarity"] = number(r.similarity);
    j["pairing"] = r.pairing;
    Json each = Json::array();
    for (const SimilarityResult& c : r.components) each.push_back(number(c.similarity));
    j["component_similarity"] = each;
    j["mirrored"] = r.mirrored;
    j["placement"] = number(r.placement);
    print_json(j);
    return 0;
  }
  std::cout << "similarity:            " << fmt(r.similarity) << " (mean over the best pairing of components"
            << (r.mirrored ? ", B mirrored" : "") << ")\n";
  for (size_t i = 0; i < r.pairing.size(); ++i)
    std::cout << "component " << i + 1 << " of A ~ " << r.pairing[i] + 1 << " of B: " << fmt(r.components[i].similarity)
              << "\n";
  std::cout << "placement:             " << fmt(r.placement)
            << " (largest difference of centroid distances over the mean component length)\n";
  return 0;
}

}  // namespace

int cmd_similarity(int argc, char** argv) {
  std::string file_a, file_b;
  bool reverse = false, mirror = false, json = false;
  std::optional<int> samples;
  ArgParser args("similarity", "A B [--reverse] [--mirror] [--samples N] [--json]");
  args.positional("A", &file_a, "first closed curve or link, .obj or .txt");
  args.positional("B", &file_b, "second closed curve or link (as many components as A), .obj or .txt");
  args.flag("--reverse", &reverse, "also compare with B's orientation reversed (convolutions)");
  args.flag("--mirror", &mirror, "also compare with B's mirror image (torsion sign flipped)");
  args.option("--samples", &samples,
              "common vertex count n (default: the smaller vertex count; curves with another count are "
              "resampled at equal arc length)");
  args.flag("--json", &json, "print one JSON object");
  if (!args.parse(argc, argv)) return 0;
  require_input(!samples || *samples >= 4, "--samples must be at least 4");

  const Link LA = read_link(file_a), LB = read_link(file_b);
  SimilarityOptions opt;
  opt.reversal = reverse;
  opt.mirror = mirror;
  opt.samples = samples.value_or(0);
  if (LA.size() > 1 || LB.size() > 1) return print_links(file_a, file_b, compare_links(LA, LB, opt), json);
  const Points& A = LA[0];
  const Points& B = LB[0];
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
