#include "ek/analysis/link_states.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "ek/core/errors.hpp"
#include "ek/geometry/resample.hpp"

namespace ek {
namespace {

/// Quantiles of a component's point distances divided by `scale`.
Eigen::VectorXd distance_quantiles(const Points& resampled, double scale, int quantiles) {
  const Eigen::Index q = resampled.rows();
  std::vector<double> d;
  d.reserve(static_cast<size_t>(q * (q - 1) / 2));
  for (Eigen::Index i = 0; i < q; ++i)
    for (Eigen::Index j = i + 1; j < q; ++j) d.push_back((resampled.row(i) - resampled.row(j)).norm() / scale);
  std::sort(d.begin(), d.end());
  Eigen::VectorXd out(quantiles);
  const double last = static_cast<double>(d.size() - 1);
  for (int k = 0; k < quantiles; ++k) {
    // linear interpolation of the empirical quantile function at (k + ½)/K
    const double x = (k + 0.5) / quantiles * last;
    const auto lo = static_cast<size_t>(std::floor(x));
    const size_t hi = std::min(lo + 1, d.size() - 1);
    out[k] = d[lo] + (x - static_cast<double>(lo)) * (d[hi] - d[lo]);
  }
  return out;
}

}  // namespace

void LinkShapeOptions::validate() const {
  require_input(samples >= 4, "link shape: samples must be at least 4");
  require_input(quantiles >= 1, "link shape: quantiles must be at least 1");
}

LinkShape link_shape(const Link& link, const LinkShapeOptions& options) {
  options.validate();
  require_input(!link.empty(), "link shape: a link needs at least one component");
  for (const Points& c : link) require_input(c.rows() >= 3, "link shape: every component needs at least 3 vertices");
  const double scale = mean_component_length(link);
  require_input(std::isfinite(scale) && scale > 0.0, "link shape: components need a positive finite length");
  LinkShape out;
  for (const Points& c : link)
    out.components.push_back(distance_quantiles(resample_arclength(c, options.samples), scale, options.quantiles));
  return out;
}

LinkStateDistance link_state_distance(const LinkShape& a, const LinkShape& b) {
  const size_t m = a.components.size();
  require_input(m == b.components.size(), "link states: the links have different numbers of components");
  require_input(m >= 1 && m <= 8, "link states: between 1 and 8 components are compared (m! pairings)");
  for (size_t c = 0; c < m; ++c)
    require_input(a.components[c].size() == b.components[c].size() &&
                      a.components[c].size() == a.components.front().size(),
                  "link states: the descriptors have different quantile counts");
  Eigen::MatrixXd pair(m, m);  // RMS difference of component i of A and j of B
  for (size_t i = 0; i < m; ++i)
    for (size_t j = 0; j < m; ++j)
      pair(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) =
          std::sqrt((a.components[i] - b.components[j]).squaredNorm() / static_cast<double>(a.components[i].size()));
  std::vector<int> perm(m);
  std::iota(perm.begin(), perm.end(), 0);
  LinkStateDistance best;
  best.distance = std::numeric_limits<double>::infinity();
  do {
    double worst = 0.0;
    for (size_t i = 0; i < m; ++i) worst = std::max(worst, pair(static_cast<Eigen::Index>(i), perm[i]));
    if (worst < best.distance) {
      best.distance = worst;
      best.pairing = perm;
    }
  } while (std::next_permutation(perm.begin(), perm.end()));
  return best;
}

Eigen::MatrixXd link_state_similarity_matrix(const std::vector<LinkShape>& shapes) {
  const auto m = static_cast<Eigen::Index>(shapes.size());
  Eigen::MatrixXd s = Eigen::MatrixXd::Identity(m, m);
  for (Eigen::Index i = 0; i < m; ++i)
    for (Eigen::Index j = i + 1; j < m; ++j)
      s(i, j) = s(j, i) = 1.0 - link_state_distance(shapes[static_cast<size_t>(i)], shapes[static_cast<size_t>(j)]).distance;
  return s;
}

}  // namespace ek
