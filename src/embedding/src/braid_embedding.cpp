#include <algorithm>
#include <cmath>
#include <vector>

#include "common.hpp"
#include "ek/core/errors.hpp"
#include "ek/knots/alexander.hpp"

namespace ek {

Embedding embed_braid(const BraidWord& word, const EmbeddingOptions& o) {
  validate(o);
  require_input(word.length() > 0 && word.strands >= 1, "braid embedding: empty braid word");
  require_input(closure_components(word) == 1, "braid embedding: the closure is not a knot");
  const int s = word.strands, L = word.length();
  const double R = 1.0;
  const double slot = 2.0 * M_PI * R / L;
  const double delta = o.strand_spacing > 0.0 ? o.strand_spacing : std::min(0.5 * slot, 0.6 * R / s);
  require_input(delta * (s - 1) < 1.8 * R, "braid embedding: strand spacing too large for the coil radius");
  const double h = o.crossing_height * delta;
  auto offset = [&](double position) { return (position - 0.5 * (s + 1)) * delta; };
  require_input(std::isfinite(o.braid_tilt), "braid embedding: tilt must be finite");
  // a turned cross-section must stay off the axis (r > 0)
  require_input(o.braid_tilt == 0.0 || std::hypot(0.5 * (s - 1) * delta, h) < R,
                "braid embedding: strand spacing and crossing height too large for a tilted coil");
  const double ct = std::cos(o.braid_tilt), st = std::sin(o.braid_tilt);
  auto smoothstep = [](double u) { return u * u * (3.0 - 2.0 * u); };
  const int K = o.samples_per_letter;
  std::vector<Vec3> pts;
  pts.reserve(static_cast<size_t>(s * L * K));
  int pos = 1;
  for (int turn = 0; turn < s; ++turn) {
    for (int j = 0; j < L; ++j) {
      const int letter = word.letters[static_cast<size_t>(j)];
      const int i = std::abs(letter);
      const bool involved = (pos == i || pos == i + 1);
      const int target = involved ? (pos == i ? i + 1 : i) : pos;
      // σ_i: the strand from position i passes over; σ_i^{-1}: from i+1.
      const bool over = involved && ((letter > 0) == (pos == i));
      for (int k = 0; k < K; ++k) {
        const double u = static_cast<double>(k) / K;
        const double phi = 2.0 * M_PI * (j + u) / L;
        const double w = involved ? smoothstep(u) : 0.0;
        // coil: (radial, height) = (position offset a, over/under lift b),
        // turned by the tilt about the core circle
        const double a = offset(pos + (target - pos) * w);
        const double b = involved ? (over ? h : -h) * std::sin(M_PI * u) : 0.0;
        const double r = R + a * ct - b * st, z = a * st + b * ct;
        pts.emplace_back(r * std::cos(phi), r * std::sin(phi), z);
      }
      pos = target;
    }
    if (pos == 1) break;
  }
  require(pos == 1, "braid embedding: strand did not close");
  Points dense(static_cast<Eigen::Index>(pts.size()), 3);
  for (size_t k = 0; k < pts.size(); ++k) dense.row(static_cast<Eigen::Index>(k)) = pts[k].transpose();
  const AlexanderPolynomial expected = alexander(word);
  return finish_embedding(dense, o, "braid", &expected);
}

}  // namespace ek
