#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "common.hpp"
#include "ek/core/errors.hpp"
#include "ek/geometry/link.hpp"
#include "ek/geometry/polyline.hpp"
#include "ek/geometry/resample.hpp"
#include "ek/knots/alexander.hpp"

namespace ek {

namespace {

/// One dense sample of the closed braid's strand walk.
struct StrandSample {
  double phi = 0.0;       ///< [rad] angle about the axis
  double position = 0.0;  ///< [1] strand position, 1..s, continuous across a letter
  double lift = 0.0;      ///< [1] +sin πu for the over strand of a letter, -sin πu under, 0 elsewhere
};

/// Follows the strand from position `start` through the word until it
/// returns there (s turns for a knot, from position 1): K samples per letter
/// slot, the two strands of a letter exchanging positions along `step` (a
/// smooth step [0,1] -> [0,1]). σ_i (letter +i): the strand coming from
/// position i passes over.
std::vector<StrandSample> strand_walk(const BraidWord& word, int K, const std::function<double(double)>& step,
                                      int start = 1) {
  const int s = word.strands, L = word.length();
  std::vector<StrandSample> out;
  out.reserve(static_cast<size_t>(s * L * K));
  int pos = start;
  for (int turn = 0; turn < s; ++turn) {
    for (int j = 0; j < L; ++j) {
      const int letter = word.letters[static_cast<size_t>(j)];
      const int i = std::abs(letter);
      const bool involved = (pos == i || pos == i + 1);
      const int target = involved ? (pos == i ? i + 1 : i) : pos;
      const bool over = involved && ((letter > 0) == (pos == i));
      for (int k = 0; k < K; ++k) {
        const double u = static_cast<double>(k) / K;
        const double w = involved ? step(u) : 0.0;
        const double lift = involved ? (over ? 1.0 : -1.0) * std::sin(M_PI * u) : 0.0;
        out.push_back({2.0 * M_PI * (j + u) / L, pos + (target - pos) * w, lift});
      }
      pos = target;
    }
    if (pos == start) break;
  }
  require(pos == start, "braid embedding: strand did not close");
  return out;
}

/// The first position of each cycle of the braid's permutation, in order
/// (one per component of the closure).
std::vector<int> cycle_starts(const BraidWord& word) {
  std::vector<int> starts;
  for (const std::vector<int>& cycle : closure_cycles(word)) starts.push_back(cycle.front());
  return starts;
}

Points to_points(const std::vector<Vec3>& pts) {
  Points dense(static_cast<Eigen::Index>(pts.size()), 3);
  for (size_t k = 0; k < pts.size(); ++k) dense.row(static_cast<Eigen::Index>(k)) = pts[k].transpose();
  return dense;
}

/// The coil (radial position offset a, lift b), turned by the tilt about the core circle r = 1.
Points coil_layout(const BraidWord& word, const EmbeddingOptions& o, int start = 1) {
  const int s = word.strands, L = word.length();
  const double R = 1.0, slot = 2.0 * M_PI * R / L;
  const double delta = o.strand_spacing.value_or(std::min(0.5 * slot, 0.6 * R / s));
  require_input(delta * (s - 1) < 1.8 * R, "braid embedding: strand spacing too large for the coil radius");
  const double h = o.crossing_height * delta;
  require_input(std::isfinite(o.braid_tilt), "braid embedding: tilt must be finite");
  // a turned cross-section must stay off the axis (r > 0)
  require_input(o.braid_tilt == 0.0 || std::hypot(0.5 * (s - 1) * delta, h) < R,
                "braid embedding: strand spacing and crossing height too large for a tilted coil");
  const double ct = std::cos(o.braid_tilt), st = std::sin(o.braid_tilt);
  const auto smoothstep = [](double u) { return u * u * (3.0 - 2.0 * u); };
  std::vector<Vec3> pts;
  for (const StrandSample& q : strand_walk(word, o.samples_per_letter, smoothstep, start)) {
    const double a = (q.position - 0.5 * (s + 1)) * delta, b = h * q.lift;
    const double r = R + a * ct - b * st, z = a * st + b * ct;
    pts.emplace_back(r * std::cos(q.phi), r * std::sin(q.phi), z);
  }
  return to_points(pts);
}

/// The cylinder r = 1: heights (position - (s+1)/2)·δ, radial offsets -h·lift
/// (h in the dense curve's units).
Points cylinder_points(const BraidWord& word, const EmbeddingOptions& o, double h, int start = 1) {
  const int s = word.strands, L = word.length();
  const double R = 1.0;
  const double delta = o.strand_spacing.value_or(2.0 * M_PI * R / L);
  const auto cosine_step = [](double u) { return 0.5 * (1.0 - std::cos(M_PI * u)); };
  std::vector<Vec3> pts;
  for (const StrandSample& q : strand_walk(word, o.samples_per_letter, cosine_step, start)) {
    const double r = R - h * q.lift, z = (q.position - 0.5 * (s + 1)) * delta;
    pts.emplace_back(r * std::cos(q.phi), r * std::sin(q.phi), z);
  }
  return to_points(pts);
}

/// The cylinder's crossing offset h in the dense curve's units: the offset
/// given in output edge lengths, at the scale of the resampling (the whole
/// closure's length over n, so that every component's edges share it).
double cylinder_offset(const BraidWord& word, const EmbeddingOptions& o) {
  require_input(o.cylinder_crossing_offset > 0.0 && std::isfinite(o.cylinder_crossing_offset),
                "braid embedding: the cylinder's crossing offset must be positive");
  require_input(o.braid_tilt == 0.0, "braid embedding: the tilt applies to the coil only");
  double length = 0.0;
  for (const int c : cycle_starts(word)) length += curve_length(cylinder_points(word, o, 0.0, c));
  const double h = o.cylinder_crossing_offset * length / o.vertices;
  require_input(h < 0.5, "braid embedding: the cylinder's crossing offset is too large for " +
                             std::to_string(o.vertices) + " vertices");
  return h;
}

/// The dense closed curve of each component, from its first position.
std::vector<Points> dense_components(const BraidWord& word, const EmbeddingOptions& o, const std::vector<int>& starts) {
  const double h = o.braid_style == BraidStyle::Cylinder ? cylinder_offset(word, o) : 0.0;
  std::vector<Points> out;
  for (const int c : starts)
    out.push_back(o.braid_style == BraidStyle::Coil ? coil_layout(word, o, c) : cylinder_points(word, o, h, c));
  return out;
}

/// Lk(i, j) from the braid word: half the sum of the signs of the letters
/// whose two strands belong to components i and j (σ_k: +1, σ_k⁻¹: −1),
/// the components numbered as closure_cycles() orders them.
Eigen::MatrixXi braid_linking_numbers(const BraidWord& word) {
  const std::vector<std::vector<int>> cycles = closure_cycles(word);
  const auto m = static_cast<Eigen::Index>(cycles.size());
  std::vector<int> at(static_cast<size_t>(word.strands) + 1, -1);  // the component at each position as the word is read
  for (size_t c = 0; c < cycles.size(); ++c)
    for (const int pos : cycles[c]) at[static_cast<size_t>(pos)] = static_cast<int>(c);
  Eigen::MatrixXi twice = Eigen::MatrixXi::Zero(m, m);
  for (const int letter : word.letters) {
    const auto i = static_cast<size_t>(std::abs(letter));
    const int a = at[i], b = at[i + 1];
    if (a != b) {
      twice(a, b) += letter > 0 ? 1 : -1;
      twice(b, a) += letter > 0 ? 1 : -1;
    }
    std::swap(at[i], at[i + 1]);
  }
  return twice / 2;
}

}  // namespace

std::string to_string(BraidStyle style) { return style == BraidStyle::Coil ? "coil" : "cylinder"; }

BraidStyle parse_braid_style(const std::string& text) {
  if (text == "coil") return BraidStyle::Coil;
  if (text == "cylinder") return BraidStyle::Cylinder;
  throw InputError("unknown braid style '" + text + "' (expected coil or cylinder)");
}

LinkEmbedding embed_braid_link(const BraidWord& word, const EmbeddingOptions& o) {
  validate(o);
  require_input(word.length() > 0 && word.strands >= 1, "braid embedding: empty braid word");
  const std::vector<int> starts = cycle_starts(word);
  LinkEmbedding e = finish_link_embedding(dense_components(word, o, starts), o, "braid embedding");
  e.linking_numbers = braid_linking_numbers(word);
  if (o.verify) {
    const Eigen::MatrixXi got = linking_matrix(e.components).array().round().cast<int>();
    if (got != e.linking_numbers)
      throw InputError("braid embedding with " + std::to_string(o.vertices) +
                       " vertices does not keep the braid's linking numbers; use more vertices");
  }
  return e;
}

Embedding embed_braid(const BraidWord& word, const EmbeddingOptions& o) {
  validate(o);
  require_input(word.length() > 0 && word.strands >= 1, "braid embedding: empty braid word");
  require_input(closure_components(word) == 1, "braid embedding: the closure is not a knot");
  const Points dense = dense_components(word, o, {1}).front();
  const AlexanderPolynomial expected = alexander(word);
  return finish_embedding(dense, o, EmbeddingMethod::Braid, &expected);
}

}  // namespace ek
