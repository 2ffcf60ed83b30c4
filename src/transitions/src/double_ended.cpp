#include "ek/transitions/double_ended.hpp"

#include <Eigen/SVD>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "ek/core/errors.hpp"
#include "saddle_checks.hpp"

namespace ek {
namespace {

using Clock = std::chrono::steady_clock;

/// The rigid motion of c that best matches a vertex by vertex (Kabsch, det = +1).
Points kabsch(const Points& a, const Points& c) {
  const Eigen::RowVector3d ca = a.colwise().mean();
  const Eigen::RowVector3d cc = c.colwise().mean();
  const Mat3 H = (c.rowwise() - cc).transpose() * (a.rowwise() - ca);
  const Eigen::JacobiSVD<Mat3> svd(H, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Mat3 D = Mat3::Identity();
  D(2, 2) = (svd.matrixV() * svd.matrixU().transpose()).determinant() < 0.0 ? -1.0 : 1.0;
  const Mat3 R = svd.matrixV() * D * svd.matrixU().transpose();
  return ((c.rowwise() - cc) * R.transpose()).rowwise() + ca;
}

/// c re-indexed cyclically: row i = c_{(i+s) mod n}.
Points shifted(const Points& c, Eigen::Index s) {
  const Eigen::Index n = c.rows();
  Points out(n, 3);
  for (Eigen::Index i = 0; i < n; ++i) out.row(i) = c.row((i + s) % n);
  return out;
}

/// Σ_i |a_i − R c_{(i+s)} − t|² after the best rigid motion for this
/// correspondence (Kabsch's residual: |A|² + |C|² − 2 Σσ, centred, with the
/// sign of the last singular value flipped for a reflection).
double rigid_residual(const Points& a, const Points& c, Eigen::Index s) {
  const Eigen::Index n = a.rows();
  const Eigen::RowVector3d ca = a.colwise().mean();
  const Eigen::RowVector3d cc = c.colwise().mean();
  Mat3 H = Mat3::Zero();
  double norms = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::RowVector3d p = a.row(i) - ca;
    const Eigen::RowVector3d q = c.row((i + s) % n) - cc;
    H += q.transpose() * p;
    norms += p.squaredNorm() + q.squaredNorm();
  }
  const Eigen::JacobiSVD<Mat3> svd(H);
  Vec3 sigma = svd.singularValues();
  if (H.determinant() < 0.0) sigma(2) = -sigma(2);
  return norms - 2.0 * sigma.sum();
}

/// E + (k/2)|P(x) − x_B|² over the model's dofs (step 2 of the file comment);
/// the CCD and accept() of the model. No rigid modes (the pull breaks them).
class SteeredObjective final : public Objective {
 public:
  SteeredObjective(Objective& model, const VecX& target, double stiffness)
      : f_(model), target_(target), k_(stiffness), x_(model.dofs()) {}
  int num_dofs() const override { return f_.num_dofs(); }
  VecX dofs() const override { return f_.dofs(); }
  void set_dofs(const VecX& x) override {
    f_.set_dofs(x);
    x_ = x;
  }
  double pull() const { return 0.5 * k_ * (x_.head(target_.size()) - target_).squaredNorm(); }
  double energy() override { return f_.energy() + pull(); }
  VecX gradient() override {
    VecX g = f_.gradient();
    g.head(target_.size()) += k_ * (x_.head(target_.size()) - target_);
    return g;
  }
  void assemble_hessian(SparseAssembler& A, HessianKind kind) override {
    f_.assemble_hessian(H_, kind);
    const auto& M = H_.matrix();
    A.begin(static_cast<int>(M.rows()));
    A.segment(0, H_.pattern_version());
    for (int c = 0; c < M.outerSize(); ++c)
      for (Eigen::SparseMatrix<double, Eigen::ColMajor, int>::InnerIterator it(M, c); it; ++it)
        A.add(static_cast<int>(it.row()), static_cast<int>(it.col()), it.value());
    A.segment(1, 0);
    for (int i = 0; i < target_.size(); ++i) A.add(i, i, k_);
    A.end();
  }
  double max_step(const VecX& x, const VecX& dx) override { return f_.max_step(x, dx); }
  void accept() override { f_.accept(); }
  std::vector<EnergyPart> energy_parts() override {
    std::vector<EnergyPart> p = f_.energy_parts();
    p.push_back({"steering", pull()});
    return p;
  }
  int active_pairs() const override { return f_.active_pairs(); }

 private:
  Objective& f_;
  VecX target_;
  double k_;
  VecX x_;
  SparseAssembler H_;
};

/// x (energy `energy`) is the minimum ref itself: energy within
/// energy_tolerance relative and aligned RMS vertex distance <= same_distance.
bool same_minimum(const Points& x, double energy, const Points& ref, double ref_energy,
                  const TransitionSearchOptions& o) {
  if (std::abs(energy - ref_energy) > o.energy_tolerance * std::abs(ref_energy)) return false;
  double distance = 0.0;
  align_vertices(ref, x, distance);
  return distance <= o.same_distance;
}

/// The state a minimum x belongs to (the file comment's "ends at"): 0 A,
/// 1 B, 2 neither. A state is the class of curves with similarity >= reach
/// to it; when x is in both classes (A and B are that similar, e.g. a chiral
/// curve and its mirror image, which the similarity cannot tell apart) only
/// the minimum itself counts (same_minimum()).
int which_state(const Points& x, double energy, const SaddleStart& a, const SaddleStart& b,
                const TransitionSearchOptions& o, const CurveSimilarity& similarity, double* to_a = nullptr,
                double* to_b = nullptr) {
  const double sa = similarity(x, a.positions), sb = similarity(x, b.positions);
  if (to_a) *to_a = sa;
  if (to_b) *to_b = sb;
  const bool in_a = sa >= o.reach, in_b = sb >= o.reach;
  if (in_a != in_b) return in_a ? 0 : 1;
  if (!in_a) return 2;
  if (same_minimum(x, energy, a.positions, a.energy, o)) return 0;
  if (same_minimum(x, energy, b.positions, b.energy, o)) return 1;
  return 2;
}

/// The steered chain (step 2): every accepted iterate (dofs) and its E.
struct Chain {
  std::vector<VecX> images;
  std::vector<double> energies;
};

/// Newton on E from the current dofs; true (and the images appended) when it
/// ends converged-stable at B.
bool release(KnotSystem& sys, const SaddleStart& a, const SaddleStart& b, const TransitionSearchOptions& o,
             const CurveSimilarity& similarity, Chain& chain) {
  Objective& f = sys.objective();
  NewtonOptions no = sys.newton();
  no.max_iterations = o.stage_iterations;
  const Descent d = descend(f, no);
  if (d.report.status != SolverStatus::ConvergedStable) return false;
  const Points end = sys.positions(d.images.back());
  if (which_state(end, d.energies.back(), a, b, o, similarity) != 1) return false;
  chain.images.insert(chain.images.end(), d.images.begin() + 1, d.images.end());
  chain.energies.insert(chain.energies.end(), d.energies.begin() + 1, d.energies.end());
  return true;
}

/// Step 2 from A (sys at A's dofs) towards B; fills the result's stage fields.
Chain steer(KnotSystem& sys, const SaddleStart& a, const SaddleStart& b, const TransitionSearchOptions& o,
            const CurveSimilarity& similarity, TransitionSearch& t) {
  Objective& f = sys.objective();
  const VecX target = as_vector(b.positions);
  Chain chain{{f.dofs()}, {f.energy()}};
  double k = o.initial_stiffness * a.mode_eigenvalues(0);
  NewtonOptions no = sys.newton();
  no.max_iterations = o.stage_iterations;
  no.remove_rigid_motions = false;
  for (int j = 0; j < o.max_stages; ++j, k *= o.growth) {
    SteeredObjective s(f, target, k);
    const Descent d = descend(s, no);
    for (size_t i = 1; i < d.images.size(); ++i) {
      chain.images.push_back(d.images[i]);
      chain.energies.push_back(d.energies[i] - 0.5 * k * (d.images[i].head(target.size()) - target).squaredNorm());
    }
    t.stages = j + 1;
    t.final_stiffness = k;
    const VecX x = chain.images.back();
    f.set_dofs(x);
    f.accept();
    t.reached_similarity = similarity(sys.positions(x), b.positions);
    if (t.reached_similarity < o.reach) continue;
    if (release(sys, a, b, o, similarity, chain)) {
      t.reached = true;
      t.reached_similarity = similarity(sys.positions(chain.images.back()), b.positions);
      break;
    }
    f.set_dofs(x);
    f.accept();
  }
  return chain;
}

/// At most `count` images evenly spaced by path length (first and last kept).
void thin(Chain& c, int count) {
  const size_t m = c.images.size();
  if (static_cast<int>(m) <= count) return;
  std::vector<double> s(m, 0.0);
  for (size_t k = 1; k < m; ++k) s[k] = s[k - 1] + (c.images[k] - c.images[k - 1]).norm();
  Chain out;
  size_t k = 0;
  for (int j = 0; j < count; ++j) {
    const double target = s.back() * j / (count - 1);
    while (k + 1 < m && s[k] < target) ++k;
    if (!out.images.empty() && out.images.back() == c.images[k]) continue;
    out.images.push_back(c.images[k]);
    out.energies.push_back(c.energies[k]);
  }
  c = std::move(out);
}

/// Step 3 from one chain image: the search along the chain's tangent, the
/// checks, and the A/B test of the minima.
SaddleRecord seed_search(const Points& seed, const VecX& tangent, const SaddleStart& a, const SaddleStart& b,
                         const VecX& rest, const TransitionSearchOptions& o, const CurveSimilarity& similarity,
                         std::array<double, 2>& to_b) {
  const auto t0 = Clock::now();
  const RelaxOptions model = detail::direct(o.saddle);
  KnotSystem sys(seed, rest, model);
  SaddleSearchOptions so = o.saddle.search;
  so.max_iterations = o.search_iterations;
  SaddleRecord r;
  const SaddleSearchResult s = detail::search_into(sys, tangent, so, o.saddle.max_rise_factor * std::abs(a.energy), r);
  if (s.status == SaddleStatus::Converged) {
    const std::string failed = detail::descend_saddle(a.alexander, rest, o.saddle, sys, s.x, r);
    bool at_a[2] = {false, false}, at_b[2] = {false, false};
    for (int m = 0; m < 2 && r.index == 1 && !r.minima[m].images.empty(); ++m) {
      SaddleMinimum& mm = r.minima[m];
      const int state = which_state(mm.positions, mm.energy, a, b, o, similarity, &mm.start_similarity, &to_b[m]);
      at_a[m] = state == 0;
      at_b[m] = state == 1;
    }
    if (r.minima[1].start_similarity > r.minima[0].start_similarity) {
      std::swap(r.minima[0], r.minima[1]);
      std::swap(to_b[0], to_b[1]);
      std::swap(at_a[0], at_a[1]);
      std::swap(at_b[0], at_b[1]);
    }
    if (!failed.empty()) r.status = failed;
    else if ((at_a[0] && at_b[1]) || (at_a[1] && at_b[0])) r.status = "verified";
    else r.status = "other-minima";
    if (r.status == "verified" && !at_a[0]) {  // the A-side descent first
      std::swap(r.minima[0], r.minima[1]);
      std::swap(to_b[0], to_b[1]);
    }
  }
  r.verified = r.status == "verified";
  r.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  return r;
}

/// The state of the minimum Newton's method on E reaches from dofs x
/// (which_state()), 2 when it does not end converged-stable.
int basin(KnotSystem& sys, const VecX& x, const SaddleStart& a, const SaddleStart& b,
          const TransitionSearchOptions& o, const CurveSimilarity& similarity) {
  Objective& f = sys.objective();
  f.set_dofs(x);
  f.accept();
  NewtonOptions no = sys.newton();
  no.max_iterations = o.stage_iterations;
  const Descent d = descend(f, no);
  if (d.report.status != SolverStatus::ConvergedStable) return 2;
  const Points end = sys.positions(d.images.back());
  return which_state(end, d.energies.back(), a, b, o, similarity);
}

/// `count` halvings of the step from `inside` (A's state) to `outside` (not).
void bisect(KnotSystem& sys, const SaddleStart& a, const SaddleStart& b, const TransitionSearchOptions& o,
            const CurveSimilarity& similarity, int count, VecX& inside, VecX& outside) {
  for (int j = 0; j < count; ++j) {
    const VecX mid = 0.5 * (inside + outside);
    (basin(sys, mid, a, b, o, similarity) == 0 ? inside : outside) = mid;
  }
}

/// `steps` Newton iterations on E from dofs x.
VecX newton_steps(KnotSystem& sys, const VecX& x, int steps) {
  Objective& f = sys.objective();
  f.set_dofs(x);
  f.accept();
  NewtonOptions no = sys.newton();
  no.max_iterations = steps;
  return descend(f, no).images.back();
}

/// Edge tracking along the boundary of A's state (step 3): both points move
/// by `tracking_steps` Newton iterations (each stays in its basin), the
/// pair is checked (basins again, the straight step between them cleared by
/// the CCD), then bisected again; it stops early when a check fails.
void track_boundary(KnotSystem& sys, const SaddleStart& a, const SaddleStart& b, const TransitionSearchOptions& o,
                    const CurveSimilarity& similarity, VecX& inside, VecX& outside) {
  Objective& f = sys.objective();
  for (int r = 0; r < o.tracking_rounds; ++r) {
    const VecX in = newton_steps(sys, inside, o.tracking_steps);
    const VecX out = newton_steps(sys, outside, o.tracking_steps);
    f.set_dofs(in);
    f.accept();
    if (f.max_step(in, out - in) < 1.0) return;
    if (basin(sys, in, a, b, o, similarity) != 0 || basin(sys, out, a, b, o, similarity) == 0) return;
    inside = in;
    outside = out;
    bisect(sys, a, b, o, similarity, o.tracking_bisections, inside, outside);
  }
}

/// A point of A's state's basin next to its boundary on the chain (step 3):
/// a binary search over the iterates for consecutive ones, the first in A's
/// basin and the second not, then `bisections` halvings of the straight step
/// between them (a step the CCD cleared), then track_boundary(). `outside`
/// receives the other end.
VecX basin_boundary(KnotSystem& sys, const Chain& full, const SaddleStart& a, const SaddleStart& b,
                    const TransitionSearchOptions& o, const CurveSimilarity& similarity, VecX& outside) {
  size_t lo = 0, hi = full.images.size() - 1;  // A, and the released end at B
  while (hi - lo > 1) {
    const size_t mid = (lo + hi) / 2;
    (basin(sys, full.images[mid], a, b, o, similarity) == 0 ? lo : hi) = mid;
  }
  VecX inside = full.images[lo];
  outside = full.images[hi];
  bisect(sys, a, b, o, similarity, o.bisections, inside, outside);
  track_boundary(sys, a, b, o, similarity, inside, outside);
  return inside;
}

/// The chain's interior local maxima of E (E_i > E_{i−1}, E_i >= E_{i+1}) by decreasing energy.
std::vector<size_t> seed_order(const std::vector<double>& energies) {
  std::vector<size_t> idx;
  for (size_t i = 1; i + 1 < energies.size(); ++i)
    if (energies[i] > energies[i - 1] && energies[i] >= energies[i + 1]) idx.push_back(i);
  std::stable_sort(idx.begin(), idx.end(), [&](size_t p, size_t q) { return energies[p] > energies[q]; });
  return idx;
}

/// One seed's search and its bookkeeping; true when verified.
bool try_seed(const Points& seed, const VecX& direction, const SaddleStart& a, const SaddleStart& b,
              const VecX& rest, const TransitionSearchOptions& o, const CurveSimilarity& similarity,
              TransitionSearch& t) {
  ++t.seeds_tried;
  t.minima_to_b = {0.0, 0.0};
  t.saddle = seed_search(seed, direction, a, b, rest, o, similarity, t.minima_to_b);
  t.seed_statuses.push_back(t.saddle.status);
  if (t.saddle.status == "other-minima") t.other_saddles.push_back(t.saddle);
  return t.saddle.verified;
}

/// Step 3's seeds in order: the basin boundary on the chain (when
/// `bisections` > 0), then the chain's highest local maxima of E.
void run_seeds(KnotSystem& sys, const Chain& full, const SaddleStart& a, const SaddleStart& b, const VecX& rest,
               const TransitionSearchOptions& o, const CurveSimilarity& similarity, TransitionSearch& t) {
  if (o.bisections > 0) {
    VecX outside;
    const VecX inside = basin_boundary(sys, full, a, b, o, similarity, outside);
    if (try_seed(sys.positions(inside), outside - inside, a, b, rest, o, similarity, t)) return;
  }
  for (const size_t i : seed_order(full.energies)) {
    if (t.seeds_tried >= o.seeds) return;
    const VecX tangent = full.images[i + 1] - full.images[i - 1];
    if (try_seed(sys.positions(full.images[i]), tangent, a, b, rest, o, similarity, t)) return;
  }
}

}  // namespace

void TransitionSearchOptions::validate() const {
  saddle.validate();
  require_input(initial_stiffness > 0.0 && std::isfinite(initial_stiffness),
                "transition: initial_stiffness must be positive");
  require_input(growth > 1.0 && std::isfinite(growth), "transition: growth must be > 1");
  require_input(max_stages >= 1, "transition: max_stages must be >= 1");
  require_input(stage_iterations >= 1, "transition: stage_iterations must be >= 1");
  require_input(reach > 0.0 && reach <= 1.0, "transition: reach must be in (0, 1]");
  require_input(energy_tolerance > 0.0 && energy_tolerance < 1.0, "transition: energy_tolerance must be in (0, 1)");
  require_input(max_images >= 3, "transition: max_images must be >= 3");
  require_input(same_distance > 0.0 && std::isfinite(same_distance), "transition: same_distance must be positive");
  require_input(seeds >= 1, "transition: seeds must be >= 1");
  require_input(bisections >= 0 && bisections <= 60, "transition: bisections must be in [0, 60]");
  require_input(search_iterations >= 1, "transition: search_iterations must be >= 1");
  require_input(tracking_rounds >= 0 && tracking_steps >= 1 && tracking_bisections >= 0 && tracking_bisections <= 60,
                "transition: tracking_rounds >= 0, tracking_steps >= 1 and tracking_bisections in [0, 60] are required");
}

Points align_vertices(const Points& a, const Points& b, double& distance) {
  require_input(a.rows() == b.rows() && a.rows() >= 3 && a.cols() == 3 && b.cols() == 3,
                "the two states must have the same number of vertices (" + std::to_string(a.rows()) + " and " +
                    std::to_string(b.rows()) + ")");
  const Points reversed = b.colwise().reverse();
  double least = std::numeric_limits<double>::infinity();
  Points best;
  for (const Points* c : {&b, &reversed})
    for (Eigen::Index s = 0; s < a.rows(); ++s) {
      const double r = rigid_residual(a, *c, s);
      if (r < least) {
        least = r;
        best = shifted(*c, s);
      }
    }
  best = kabsch(a, best);
  distance = std::sqrt((a - best).rowwise().squaredNorm().mean());
  return best;
}

TransitionSearch transition_search(const Points& a, const Points& b, const VecX& rest,
                                   const TransitionSearchOptions& o, const CurveSimilarity& similarity) {
  o.validate();
  require(static_cast<bool>(similarity), "transition_search: a similarity function is needed");
  const auto t0 = Clock::now();
  TransitionSearch t;
  KnotSaddleOptions so = o.saddle;
  so.modes = 1;
  const SaddleStart sa = prepare_start(a, rest, so);
  double distance = 0.0;
  const SaddleStart sb = prepare_start(align_vertices(sa.positions, b, distance), rest, so);
  t.a = sa.positions;
  t.b = sb.positions;
  t.energy_a = sa.energy;
  t.energy_b = sb.energy;
  t.energy_scale = sa.energy_scale;
  t.alignment_distance = std::sqrt((t.a - t.b).rowwise().squaredNorm().mean());
  const auto done = [&](const std::string& status) {
    t.status = status;
    t.verified = status == "verified";
    t.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    return t;
  };
  if (sa.alexander != sb.alexander) return done("different-knot");
  t.similarity_ab = similarity(t.a, t.b);
  if (std::abs(t.energy_b - t.energy_a) <= o.energy_tolerance * std::abs(t.energy_a) &&
      t.alignment_distance <= o.same_distance)
    return done("same-state");
  KnotSystem sys(t.a, rest, detail::direct(o.saddle));
  Chain chain = steer(sys, sa, sb, o, similarity, t);
  const Chain full = chain;
  thin(chain, o.max_images);
  for (size_t i = 0; i < chain.images.size(); ++i) {
    t.chain.push_back(sys.positions(chain.images[i]));
    t.chain_energies.push_back(chain.energies[i]);
    if (detail::alexander_or_zero(t.chain.back()) != sa.alexander) t.alexander_preserved = false;
  }
  if (!t.alexander_preserved) return done("topology-changed");
  if (!t.reached) return done("not-reached");
  t.path_barrier = *std::max_element(full.energies.begin(), full.energies.end()) - t.energy_a;
  run_seeds(sys, full, sa, sb, rest, o, similarity, t);
  if (t.seeds_tried == 0) return done("no-seed");
  return done(t.saddle.status);
}

}  // namespace ek
