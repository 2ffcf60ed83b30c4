#include "ek/analysis/link_similarity.hpp"

#include <algorithm>
#include <numeric>

#include "ek/core/errors.hpp"
#include "ek/geometry/polyline.hpp"

namespace ek {
namespace {

/// Distances between component centroids over the mean component length.
Eigen::MatrixXd relative_centroid_distances(const Link& link) {
  const Eigen::Index m = static_cast<Eigen::Index>(link.size());
  std::vector<Vec3> c;
  for (const Points& P : link) c.push_back(P.colwise().mean().transpose());
  const double length = mean_component_length(link);
  Eigen::MatrixXd D(m, m);
  for (Eigen::Index i = 0; i < m; ++i)
    for (Eigen::Index j = 0; j < m; ++j) D(i, j) = (c[static_cast<size_t>(i)] - c[static_cast<size_t>(j)]).norm() / length;
  return D;
}

struct Pairing {
  double score = -1.0;
  std::vector<int> pi;
};

/// The bijection maximising Σ_i S(i, π(i)) (exhaustive, m <= 8).
Pairing best_pairing(const std::vector<std::vector<SimilarityResult>>& S) {
  const int m = static_cast<int>(S.size());
  std::vector<int> pi(static_cast<size_t>(m));
  std::iota(pi.begin(), pi.end(), 0);
  Pairing best;
  do {
    double score = 0.0;
    for (int i = 0; i < m; ++i) score += S[static_cast<size_t>(i)][static_cast<size_t>(pi[static_cast<size_t>(i)])].similarity;
    if (score > best.score + 1e-15) best = {score, pi};
  } while (std::next_permutation(pi.begin(), pi.end()));
  return best;
}

}  // namespace

LinkSimilarityResult compare_links(const Link& a, const Link& b, const SimilarityOptions& options) {
  validate_link(a, "link similarity (A)");
  validate_link(b, "link similarity (B)");
  require_input(a.size() == b.size(), "link similarity: A has " + std::to_string(a.size()) + " components, B " +
                                          std::to_string(b.size()));
  require_input(a.size() <= 8, "link similarity: at most 8 components (the pairing tries all m! bijections)");
  SimilarityOptions per_pair = options;
  per_pair.mirror = false;  // the mirror image is taken for the whole link below
  LinkSimilarityResult out;
  for (const bool mirror : {false, true}) {
    if (mirror && !options.mirror) break;
    Link bb = b;
    if (mirror)
      for (Points& P : bb) P.col(2) *= -1.0;
    std::vector<std::vector<SimilarityResult>> S(a.size());
    for (size_t i = 0; i < a.size(); ++i)
      for (size_t j = 0; j < bb.size(); ++j) S[i].push_back(compare_curves(a[i], bb[j], per_pair));
    const Pairing p = best_pairing(S);
    const double score = p.score / static_cast<double>(a.size());
    if (score <= out.similarity && !out.pairing.empty()) continue;
    out.similarity = score;
    out.pairing = p.pi;
    out.mirrored = mirror;
    out.components.clear();
    for (size_t i = 0; i < a.size(); ++i) {
      out.components.push_back(S[i][static_cast<size_t>(p.pi[i])]);
      out.components.back().mirrored = mirror;
    }
  }
  const Eigen::MatrixXd DA = relative_centroid_distances(a), DB = relative_centroid_distances(b);
  out.placement = 0.0;
  for (Eigen::Index i = 0; i < DA.rows(); ++i)
    for (Eigen::Index j = 0; j < DA.cols(); ++j)
      out.placement = std::max(out.placement, std::abs(DA(i, j) - DB(out.pairing[static_cast<size_t>(i)],
                                                                        out.pairing[static_cast<size_t>(j)])));
  return out;
}

}  // namespace ek
