#include "ek/analysis/similarity.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>

#include "ek/core/errors.hpp"
#include "ek/geometry/resample.hpp"

namespace ek {

namespace {

/// The FFTW planner (plan creation and destruction) is not thread-safe.
std::mutex& planner_mutex() {
  static std::mutex m;
  return m;
}

/// How a correlation array is to be read: computed values, or a constant
/// (1: both profiles zero, 0: exactly one zero).
enum class Corr { Computed, One, Zero };

Corr zero_rule(bool zero_a, bool zero_b) {
  if (zero_a && zero_b) return Corr::One;
  if (zero_a || zero_b) return Corr::Zero;
  return Corr::Computed;
}

double constant_of(Corr c) { return c == Corr::One ? 1.0 : 0.0; }

double pos(double x) { return x > 0.0 ? x : 0.0; }

/// Best (score, shift, correlations) over the shifts for one family
/// (correlation or convolution) and the identity / mirror variants.
struct Best {
  double score = -1.0;
  double ck = 0.0, ct = 0.0;
  int index = 0;  ///< index into the correlation / convolution array
  bool mirrored = false;
};

/// Scans ck[s], ct[s] (scaled by `scale`, or constants) and updates best.
void scan(int n, const double* ck, const double* ct, double scale, Corr rk, Corr rt, bool mirror, Best& best) {
  for (int s = 0; s < n; ++s) {
    const double k = rk == Corr::Computed ? ck[s] * scale : constant_of(rk);
    const double t = rt == Corr::Computed ? ct[s] * scale : constant_of(rt);
    const double kp = pos(k);
    const double v = kp + pos(t);
    if (v > best.score) {
      best = {v, k, t, s, false};
    }
    if (mirror && rt == Corr::Computed) {
      const double vm = kp + pos(-t);
      if (vm > best.score) best = {vm, k, -t, s, true};
    }
  }
}

double finish_score(double sum) {
  const double s = 0.5 * sum;
  if (s > 1.0 - kUnitySnap) return 1.0;
  return std::max(0.0, s);
}

/// Combines the candidates of the correlation family (identity / mirror) and,
/// when allowed, the convolution family (reversal) into a result.
SimilarityResult make_result(int n, const Best& corr, const Best* conv) {
  SimilarityResult r;
  const Best* best = &corr;
  bool rev = false;
  if (conv && conv->score > corr.score) {
    best = conv;
    rev = true;
  }
  r.similarity = finish_score(best->score);
  r.curvature_correlation = best->ck;
  r.torsion_correlation = best->ct;
  r.mirrored = best->mirrored;
  r.reversed = rev;
  r.samples = n;
  // correlation index s: vertex i of A matches vertex i + s of B;
  // convolution index c: Σ_i A_i B_{c-i}; B reversed (B'_j = B_{n-1-j}) matches at s = n-1-c.
  r.best_shift = rev ? ((n - 1 - best->index) % n + n) % n : best->index;
  return r;
}

}  // namespace

void SimilarityOptions::validate() const {
  require(samples == 0 || samples >= 3, "SimilarityOptions: samples must be 0 (automatic) or >= 3");
  require(zero_tolerance >= 0.0 && zero_tolerance < 1.0, "SimilarityOptions: zero_tolerance must be in [0, 1)");
}

struct SimilarityEngine::Impl {
  int n = 0;
  int nc = 0;  // n/2 + 1 complex coefficients
  SimilarityOptions options;
  double* rbuf_k = nullptr;
  double* rbuf_t = nullptr;
  fftw_complex* cbuf_k = nullptr;
  fftw_complex* cbuf_t = nullptr;
  fftw_plan forward = nullptr;   // r2c rbuf_k -> cbuf_k
  fftw_plan backward = nullptr;  // c2r cbuf_k -> rbuf_k (also run on the _t buffers)

  Impl(int size, const SimilarityOptions& opt) : n(size), nc(size / 2 + 1), options(opt) {
    const auto nr = static_cast<size_t>(n), ncs = static_cast<size_t>(nc);
    rbuf_k = fftw_alloc_real(nr);
    rbuf_t = fftw_alloc_real(nr);
    cbuf_k = fftw_alloc_complex(ncs);
    cbuf_t = fftw_alloc_complex(ncs);
    if (!rbuf_k || !rbuf_t || !cbuf_k || !cbuf_t) {
      release();
      throw std::bad_alloc();
    }
    std::lock_guard<std::mutex> lock(planner_mutex());
    forward = fftw_plan_dft_r2c_1d(n, rbuf_k, cbuf_k, FFTW_ESTIMATE);
    backward = fftw_plan_dft_c2r_1d(n, cbuf_k, rbuf_k, FFTW_ESTIMATE);
  }
  ~Impl() { release(); }
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;

  void release() {
    {
      std::lock_guard<std::mutex> lock(planner_mutex());
      if (forward) fftw_destroy_plan(forward);
      if (backward) fftw_destroy_plan(backward);
    }
    forward = backward = nullptr;
    fftw_free(rbuf_k);
    fftw_free(rbuf_t);
    fftw_free(cbuf_k);
    fftw_free(cbuf_t);
    rbuf_k = rbuf_t = nullptr;
    cbuf_k = cbuf_t = nullptr;
  }

  /// r2c transform of v/‖v‖ into out (n/2+1 coefficients).
  void transform(const VecX& v, double norm, std::vector<std::complex<double>>& out) {
    for (int i = 0; i < n; ++i) rbuf_k[i] = v(i) / norm;
    fftw_execute_dft_r2c(forward, rbuf_k, cbuf_k);
    out.resize(static_cast<size_t>(nc));
    for (int k = 0; k < nc; ++k) out[static_cast<size_t>(k)] = {cbuf_k[k][0], cbuf_k[k][1]};
  }

  /// out = IFFT(conj(a)·b) (correlation) or IFFT(a·b) (convolution), unnormalised.
  void inverse(const std::vector<std::complex<double>>& a, const std::vector<std::complex<double>>& b,
               bool convolution, fftw_complex* cbuf, double* rbuf) {
    const double sgn = convolution ? 1.0 : -1.0;  // conj(a) flips the sign of a's imaginary part
    for (int k = 0; k < nc; ++k) {
      const double ar = a[static_cast<size_t>(k)].real(), ai = sgn * a[static_cast<size_t>(k)].imag();
      const double br = b[static_cast<size_t>(k)].real(), bi = b[static_cast<size_t>(k)].imag();
      cbuf[k][0] = ar * br - ai * bi;
      cbuf[k][1] = ar * bi + ai * br;
    }
    fftw_execute_dft_c2r(backward, cbuf, rbuf);
  }

  void family(const SignatureSpectrum& a, const SignatureSpectrum& b, bool convolution, Best& best) {
    const Corr rk = zero_rule(a.curvature_is_zero(), b.curvature_is_zero());
    const Corr rt = zero_rule(a.torsion_is_zero(), b.torsion_is_zero());
    if (rk == Corr::Computed) inverse(a.curvature_spectrum(), b.curvature_spectrum(), convolution, cbuf_k, rbuf_k);
    if (rt == Corr::Computed) inverse(a.torsion_spectrum(), b.torsion_spectrum(), convolution, cbuf_t, rbuf_t);
    scan(n, rbuf_k, rbuf_t, 1.0 / n, rk, rt, options.mirror, best);
  }
};

SimilarityEngine::SimilarityEngine(int n, const SimilarityOptions& options) {
  require(n >= 3, "SimilarityEngine: the signature length n must be >= 3");
  options.validate();
  impl_ = std::make_unique<Impl>(n, options);
}

SimilarityEngine::~SimilarityEngine() = default;
SimilarityEngine::SimilarityEngine(SimilarityEngine&&) noexcept = default;
SimilarityEngine& SimilarityEngine::operator=(SimilarityEngine&&) noexcept = default;

int SimilarityEngine::size() const { return impl_->n; }
const SimilarityOptions& SimilarityEngine::options() const { return impl_->options; }

SignatureSpectrum SimilarityEngine::spectrum(const Points& P) {
  if (P.rows() == impl_->n && !impl_->options.resample) return spectrum(curve_signature(P));
  return spectrum(curve_signature(resample_arclength(P, impl_->n)));
}

SignatureSpectrum SimilarityEngine::spectrum(const CurveSignature& s) {
  const int n = impl_->n;
  require(s.size() == n && s.torsion.size() == n,
          "SimilarityEngine::spectrum: signature length " + std::to_string(s.size()) + " differs from the engine's " +
              std::to_string(n));
  require(s.curvature.allFinite() && s.torsion.allFinite(), "SimilarityEngine::spectrum: non-finite signature");
  SignatureSpectrum out;
  out.n_ = n;
  const double nk = s.curvature.norm(), nt = s.torsion.norm();
  out.k_zero_ = !(nk > 0.0);
  // RMS(T) <= tol · mean(K²)  <=>  ‖T‖/√n <= tol · ‖K‖²/n
  out.t_zero_ = out.k_zero_ || !(nt > impl_->options.zero_tolerance * nk * nk / std::sqrt(static_cast<double>(n)));
  const std::vector<std::complex<double>> zeros(static_cast<size_t>(impl_->nc));
  if (out.k_zero_)
    out.fk_ = zeros;
  else
    impl_->transform(s.curvature, nk, out.fk_);
  if (out.t_zero_)
    out.ft_ = zeros;
  else
    impl_->transform(s.torsion, nt, out.ft_);
  return out;
}

SimilarityResult SimilarityEngine::compare(const SignatureSpectrum& a, const SignatureSpectrum& b) {
  const int n = impl_->n;
  require(a.size() == n && b.size() == n, "SimilarityEngine::compare: spectra of another length than the engine's");
  Best corr;
  impl_->family(a, b, false, corr);
  if (!impl_->options.reversal) return make_result(n, corr, nullptr);
  Best conv;
  impl_->family(a, b, true, conv);
  return make_result(n, corr, &conv);
}

Eigen::MatrixXd SimilarityEngine::matrix(const std::vector<SignatureSpectrum>& spectra) {
  const auto N = static_cast<Eigen::Index>(spectra.size());
  Eigen::MatrixXd S(N, N);
  for (Eigen::Index i = 0; i < N; ++i) {
    S(i, i) = 1.0;
    for (Eigen::Index j = i + 1; j < N; ++j) {
      const double v = similarity(spectra[static_cast<size_t>(i)], spectra[static_cast<size_t>(j)]);
      S(i, j) = v;
      S(j, i) = v;
    }
  }
  return S;
}

Eigen::MatrixXd SimilarityEngine::cross_matrix(const std::vector<SignatureSpectrum>& a,
                                               const std::vector<SignatureSpectrum>& b) {
  Eigen::MatrixXd S(static_cast<Eigen::Index>(a.size()), static_cast<Eigen::Index>(b.size()));
  for (size_t i = 0; i < a.size(); ++i)
    for (size_t j = 0; j < b.size(); ++j)
      S(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = similarity(a[i], b[j]);
  return S;
}

namespace {

/// The common count: options.samples, or the smallest vertex count.
int common_count(const std::vector<const Points*>& curves, const SimilarityOptions& options) {
  options.validate();
  Eigen::Index m = std::numeric_limits<Eigen::Index>::max();
  for (const Points* c : curves) m = std::min(m, c->rows());
  require(m >= 3, "similarity: a closed curve needs at least 3 vertices");
  return options.samples > 0 ? options.samples : static_cast<int>(m);
}

}  // namespace

SimilarityResult compare_curves(const Points& a, const Points& b, const SimilarityOptions& options) {
  SimilarityEngine engine(common_count({&a, &b}, options), options);
  const SignatureSpectrum sa = engine.spectrum(a);
  const SignatureSpectrum sb = engine.spectrum(b);
  return engine.compare(sa, sb);
}

double similarity(const Points& a, const Points& b, const SimilarityOptions& options) {
  return compare_curves(a, b, options).similarity;
}

Eigen::MatrixXd similarity_matrix(const std::vector<Points>& curves, const SimilarityOptions& options) {
  if (curves.empty()) return Eigen::MatrixXd(0, 0);
  std::vector<const Points*> ptrs;
  for (const Points& c : curves) ptrs.push_back(&c);
  SimilarityEngine engine(common_count(ptrs, options), options);
  std::vector<SignatureSpectrum> spectra;
  spectra.reserve(curves.size());
  for (const Points& c : curves) spectra.push_back(engine.spectrum(c));
  return engine.matrix(spectra);
}

SimilarityResult similarity_direct(const CurveSignature& a, const CurveSignature& b, const SimilarityOptions& options) {
  options.validate();
  const int n = a.size();
  require(n >= 3 && b.size() == n && a.torsion.size() == n && b.torsion.size() == n,
          "similarity_direct: signatures of equal length >= 3 expected");
  auto zeros = [&](const CurveSignature& s, bool& kz, bool& tz) {
    const double nk = s.curvature.norm(), nt = s.torsion.norm();
    kz = !(nk > 0.0);
    tz = kz || !(nt > options.zero_tolerance * nk * nk / std::sqrt(static_cast<double>(n)));
  };
  bool akz, atz, bkz, btz;
  zeros(a, akz, atz);
  zeros(b, bkz, btz);
  const Corr rk = zero_rule(akz, bkz), rt = zero_rule(atz, btz);
  const double sk = rk == Corr::Computed ? 1.0 / (a.curvature.norm() * b.curvature.norm()) : 0.0;
  const double st = rt == Corr::Computed ? 1.0 / (a.torsion.norm() * b.torsion.norm()) : 0.0;
  std::vector<double> ck(static_cast<size_t>(n)), ct(static_cast<size_t>(n));
  auto fill = [&](bool convolution) {
    for (int s = 0; s < n; ++s) {
      double dk = 0.0, dt = 0.0;
      for (int i = 0; i < n; ++i) {
        const int j = convolution ? ((s - i) % n + n) % n : (i + s) % n;
        dk += a.curvature(i) * b.curvature(j);
        dt += a.torsion(i) * b.torsion(j);
      }
      ck[static_cast<size_t>(s)] = dk * sk;
      ct[static_cast<size_t>(s)] = dt * st;
    }
  };
  Best corr;
  fill(false);
  scan(n, ck.data(), ct.data(), 1.0, rk, rt, options.mirror, corr);
  if (!options.reversal) return make_result(n, corr, nullptr);
  Best conv;
  fill(true);
  scan(n, ck.data(), ct.data(), 1.0, rk, rt, options.mirror, conv);
  return make_result(n, corr, &conv);
}

}  // namespace ek
