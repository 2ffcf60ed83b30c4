#include "ek/transitions/double_ended.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "ek/core/errors.hpp"
#include "ek/core/stopwatch.hpp"
#include "ek/geometry/rigid.hpp"
#include "saddle_checks.hpp"

namespace ek {
namespace {


/// c re-indexed cyclically: row i = c_{(i+s) mod n}.
Points shifted(const Points& c, Eigen::Index s) {
  const Eigen::Index n = c.rows();
  Points out(n, 3);
  for (Eigen::Index i = 0; i < n; ++i) out.row(i) = c.row((i + s) % n);
  return out;
}

/// Σ_i |a_i − R c_{(i+s)} − t|² after the best rigid motion for this
/// correspondence (ek/geometry/rigid.hpp).
double shifted_residual(const Points& a, const Points& c, Eigen::Index s) {
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
  return rigid_residual(H, norms);
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

/// The state a minimum belongs to (the file comment's "States").
enum class InState { A, B, Neither };

/// The steered chain (step 2): every accepted iterate (dofs) and its E.
struct Chain {
  std::vector<VecX> images;
  std::vector<double> energies;
};

/// At most `count` images of c evenly spaced by path length (first and last kept).
Chain thinned(const Chain& c, int count) {
  const size_t m = c.images.size();
  if (static_cast<int>(m) <= count) return c;
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
  return out;
}

/// The chain's interior local maxima of E (E_i > E_{i−1}, E_i >= E_{i+1}) by decreasing energy.
std::vector<size_t> seed_order(const std::vector<double>& energies) {
  std::vector<size_t> idx;
  for (size_t i = 1; i + 1 < energies.size(); ++i)
    if (energies[i] > energies[i - 1] && energies[i] >= energies[i + 1]) idx.push_back(i);
  std::stable_sort(idx.begin(), idx.end(), [&](size_t p, size_t q) { return energies[p] > energies[q]; });
  return idx;
}

/// Steps 2 and 3 of the file comment between two polished states: the
/// model's system (at A's dofs to begin with), on which the chain is
/// steered and the basins are tested, the states, the options and the
/// result being filled.
class DoubleEndedSearch {
 public:
  DoubleEndedSearch(const SaddleStart& a, const SaddleStart& b, const VecX& rest, const TransitionSearchOptions& o,
                    const CurveSimilarity& similarity, TransitionSearch& result)
      : sys_(a.positions, rest, detail::direct(o.saddle)), a_(a), b_(b), rest_(rest), o_(o),
        similarity_(similarity), t_(result) {}

  /// The chain, then the seeds' searches; returns the search's status.
  SearchStatus run() {
    const Chain full = steer();
    keep_chain(thinned(full, o_.max_images));
    if (!t_.alexander_preserved) return SearchOutcome::TopologyChanged;
    if (!t_.reached) return SearchOutcome::NotReached;
    t_.path_barrier = *std::max_element(full.energies.begin(), full.energies.end()) - t_.energy_a;
    run_seeds(full);
    if (t_.seeds_tried == 0) return SearchOutcome::NoSeed;
    return t_.saddle.status;
  }

 private:
  /// The model's Newton options with another iteration cap.
  NewtonOptions newton(int max_iterations) const {
    NewtonOptions no = sys_.newton();
    no.max_iterations = max_iterations;
    return no;
  }

  /// The system's dofs set to x and accepted.
  void move_to(const VecX& x) {
    Objective& f = sys_.objective();
    f.set_dofs(x);
    f.accept();
  }

  /// Newton's method on E from dofs x, at most `max_iterations` iterations.
  Descent descend_from(const VecX& x, int max_iterations) {
    move_to(x);
    return descend(sys_.objective(), newton(max_iterations));
  }

  /// The state of minimum x (energy `energy`): A's or B's when its
  /// similarity to that one is >= reach and to the other not; when it is
  /// in both classes (A and B are that similar, e.g. a chiral curve and its
  /// mirror image, which the similarity cannot tell apart) only the minimum
  /// itself counts (same_minimum()). `to_a`, `to_b` receive the similarities.
  InState which_state(const Points& x, double energy, double* to_a = nullptr, double* to_b = nullptr) const {
    const double sa = similarity_(x, a_.positions), sb = similarity_(x, b_.positions);
    if (to_a) *to_a = sa;
    if (to_b) *to_b = sb;
    const bool in_a = sa >= o_.reach, in_b = sb >= o_.reach;
    if (in_a != in_b) return in_a ? InState::A : InState::B;
    if (!in_a) return InState::Neither;
    if (same_minimum(x, energy, a_.positions, a_.energy, o_)) return InState::A;
    if (same_minimum(x, energy, b_.positions, b_.energy, o_)) return InState::B;
    return InState::Neither;
  }

  /// The state of the minimum Newton's method on E reaches from dofs x
  /// (which_state()); Neither when it does not end converged-stable.
  InState basin(const VecX& x) {
    const Descent d = descend_from(x, o_.stage_iterations);
    if (d.report.status != SolverStatus::ConvergedStable) return InState::Neither;
    return which_state(sys_.positions(d.images.back()), d.energies.back());
  }

  /// Newton on E from the current dofs; true (and the images appended) when
  /// it ends converged-stable in B's state.
  bool release(Chain& chain) {
    const Descent d = descend(sys_.objective(), newton(o_.stage_iterations));
    if (d.report.status != SolverStatus::ConvergedStable) return false;
    if (which_state(sys_.positions(d.images.back()), d.energies.back()) != InState::B) return false;
    chain.images.insert(chain.images.end(), d.images.begin() + 1, d.images.end());
    chain.energies.insert(chain.energies.end(), d.energies.begin() + 1, d.energies.end());
    return true;
  }

  /// One steering stage (stiffness k towards `target`) from the current
  /// dofs: its iterates appended to the chain with E (the pull removed).
  void stage(Chain& chain, const VecX& target, double k, const NewtonOptions& no) {
    SteeredObjective s(sys_.objective(), target, k);
    const Descent d = descend(s, no);
    for (size_t i = 1; i < d.images.size(); ++i) {
      chain.images.push_back(d.images[i]);
      chain.energies.push_back(d.energies[i] - 0.5 * k * (d.images[i].head(target.size()) - target).squaredNorm());
    }
  }

  /// Step 2 from A (the system at A's dofs) towards B: every accepted
  /// iterate; fills the result's stage fields.
  Chain steer() {
    Objective& f = sys_.objective();
    const VecX target = as_vector(b_.positions);
    Chain chain{{f.dofs()}, {f.energy()}};
    double k = o_.initial_stiffness * a_.mode_eigenvalues(0);
    NewtonOptions no = newton(o_.stage_iterations);
    no.remove_rigid_motions = false;
    for (int j = 0; j < o_.max_stages; ++j, k *= o_.growth) {
      stage(chain, target, k, no);
      t_.stages = j + 1;
      t_.final_stiffness = k;
      const VecX x = chain.images.back();
      move_to(x);
      t_.reached_similarity = similarity_(sys_.positions(x), b_.positions);
      if (t_.reached_similarity < o_.reach) continue;
      if (release(chain)) {
        t_.reached = true;
        t_.reached_similarity = similarity_(sys_.positions(chain.images.back()), b_.positions);
        break;
      }
      move_to(x);
    }
    return chain;
  }

  /// The thinned chain's images and energies into the result, with the
  /// Alexander polynomial of every image checked against A's.
  void keep_chain(const Chain& chain) {
    for (size_t i = 0; i < chain.images.size(); ++i) {
      t_.chain.push_back(sys_.positions(chain.images[i]));
      t_.chain_energies.push_back(chain.energies[i]);
      if (detail::alexander_or_zero(t_.chain.back()) != a_.alexander) t_.alexander_preserved = false;
    }
  }

  /// `count` halvings of the step from `inside` (A's state) to `outside` (not).
  void bisect(int count, VecX& inside, VecX& outside) {
    for (int j = 0; j < count; ++j) {
      const VecX mid = 0.5 * (inside + outside);
      (basin(mid) == InState::A ? inside : outside) = mid;
    }
  }

  /// Edge tracking along the boundary of A's state (step 3): both points
  /// move by `tracking_steps` Newton iterations (each stays in its basin),
  /// the pair is checked (basins again, the straight step between them
  /// cleared by the CCD), then bisected again; it stops early when a check
  /// fails.
  void track_boundary(VecX& inside, VecX& outside) {
    Objective& f = sys_.objective();
    for (int r = 0; r < o_.tracking_rounds; ++r) {
      const VecX in = descend_from(inside, o_.tracking_steps).images.back();
      const VecX out = descend_from(outside, o_.tracking_steps).images.back();
      move_to(in);
      if (f.max_step(in, out - in) < 1.0) return;
      if (basin(in) != InState::A || basin(out) == InState::A) return;
      inside = in;
      outside = out;
      bisect(o_.tracking_bisections, inside, outside);
    }
  }

  /// A point of A's state's basin next to its boundary on the chain (step
  /// 3): a binary search over the iterates for consecutive ones, the first
  /// in A's basin and the second not, then `bisections` halvings of the
  /// straight step between them (a step the CCD cleared), then
  /// track_boundary(). `outside` receives the other end.
  VecX basin_boundary(const Chain& full, VecX& outside) {
    size_t lo = 0, hi = full.images.size() - 1;  // A, and the released end at B
    while (hi - lo > 1) {
      const size_t mid = (lo + hi) / 2;
      (basin(full.images[mid]) == InState::A ? lo : hi) = mid;
    }
    VecX inside = full.images[lo];
    outside = full.images[hi];
    bisect(o_.bisections, inside, outside);
    track_boundary(inside, outside);
    return inside;
  }

  /// Swaps r's two minima with their similarities to B and their states.
  static void swap_minima(SaddleRecord& r, std::array<double, 2>& to_b, std::array<InState, 2>& state) {
    std::swap(r.minima[0], r.minima[1]);
    std::swap(to_b[0], to_b[1]);
    std::swap(state[0], state[1]);
  }

  /// The A/B test of a checked saddle's minima (their start_similarity to A,
  /// to_b to B), minima[0] the one nearer A; `failed` the checks' verdict.
  SearchStatus classify(SaddleRecord& r, const std::optional<SearchStatus>& failed,
                        std::array<double, 2>& to_b) const {
    std::array<InState, 2> state{InState::Neither, InState::Neither};
    for (int m = 0; m < 2 && r.index == 1 && !r.minima[m].images.empty(); ++m) {
      SaddleMinimum& mm = r.minima[m];
      state[m] = which_state(mm.positions, mm.energy, &mm.start_similarity, &to_b[m]);
    }
    if (r.minima[1].start_similarity > r.minima[0].start_similarity) swap_minima(r, to_b, state);
    if (failed) return *failed;
    const bool joins = (state[0] == InState::A && state[1] == InState::B) ||
                       (state[0] == InState::B && state[1] == InState::A);
    if (!joins) return SearchOutcome::OtherMinima;
    if (state[0] != InState::A) swap_minima(r, to_b, state);  // the A-side descent first
    return SearchOutcome::Verified;
  }

  /// Step 3 from one seed: the search along `tangent`, the checks, and the
  /// A/B test of the minima (to_b: their similarities to B).
  SaddleRecord seed_search(const Points& seed, const VecX& tangent, std::array<double, 2>& to_b) const {
    const Stopwatch t0;
    RodModel sys(seed, rest_, detail::direct(o_.saddle));
    SaddleSearchOptions so = o_.saddle.search;
    so.max_iterations = o_.search_iterations;
    SaddleRecord r;
    const double max_rise = o_.saddle.max_rise_factor * std::abs(a_.energy);
    const SaddleSearchResult s = detail::search_into(sys, tangent, so, max_rise, r);
    if (s.status == SaddleStatus::Converged)
      r.status = classify(r, detail::descend_saddle(a_.alexander, rest_, o_.saddle, sys, s.x, r), to_b);
    r.verified = r.status.verified();
    r.seconds = t0.seconds();
    return r;
  }

  /// One seed's search and its bookkeeping; true when verified.
  bool try_seed(const Points& seed, const VecX& direction) {
    ++t_.seeds_tried;
    t_.minima_to_b = {0.0, 0.0};
    t_.saddle = seed_search(seed, direction, t_.minima_to_b);
    t_.seed_statuses.push_back(t_.saddle.status);
    if (t_.saddle.status == SearchOutcome::OtherMinima) t_.other_saddles.push_back(t_.saddle);
    return t_.saddle.verified;
  }

  /// Step 3's seeds in order: the basin boundary on the chain (when
  /// `bisections` > 0), then the chain's highest local maxima of E.
  void run_seeds(const Chain& full) {
    if (o_.bisections > 0) {
      VecX outside;
      const VecX inside = basin_boundary(full, outside);
      if (try_seed(sys_.positions(inside), outside - inside)) return;
    }
    for (const size_t i : seed_order(full.energies)) {
      if (t_.seeds_tried >= o_.seeds) return;
      const VecX tangent = full.images[i + 1] - full.images[i - 1];
      if (try_seed(sys_.positions(full.images[i]), tangent)) return;
    }
  }

  RodModel sys_;
  const SaddleStart& a_;
  const SaddleStart& b_;
  const VecX& rest_;
  const TransitionSearchOptions& o_;
  const CurveSimilarity& similarity_;
  TransitionSearch& t_;
};

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
      const double r = shifted_residual(a, *c, s);
      if (r < least) {
        least = r;
        best = shifted(*c, s);
      }
    }
  best = align_onto(best, a);
  distance = std::sqrt((a - best).rowwise().squaredNorm().mean());
  return best;
}

TransitionSearch transition_search(const Points& a, const Points& b, const VecX& rest,
                                   const TransitionSearchOptions& o, const CurveSimilarity& similarity) {
  o.validate();
  require(static_cast<bool>(similarity), "transition_search: a similarity function is needed");
  const Stopwatch t0;
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
  const auto done = [&](const SearchStatus& status) {
    t.status = status;
    t.verified = status.verified();
    t.seconds = t0.seconds();
    return t;
  };
  if (sa.alexander != sb.alexander) return done(SearchOutcome::DifferentKnot);
  t.similarity_ab = similarity(t.a, t.b);
  if (std::abs(t.energy_b - t.energy_a) <= o.energy_tolerance * std::abs(t.energy_a) &&
      t.alignment_distance <= o.same_distance)
    return done(SearchOutcome::SameState);
  return done(DoubleEndedSearch(sa, sb, rest, o, similarity, t).run());
}

}  // namespace ek
