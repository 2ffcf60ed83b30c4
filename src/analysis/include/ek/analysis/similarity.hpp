#pragma once
/// \file
/// Curvature-torsion similarity of closed curves (paper Section 7.1) with
/// FFT cross-correlations.
///
/// Definition. For signatures (K1, T1) and (K2, T2) of length n (see
/// signature.hpp; curves are first brought to a common vertex count n, below)
/// the normalised cyclic cross-correlation is
///
/// ~~~{.unparsed}
///   (A ⋆ B)[s] = Σ_i A_i B_{(i+s) mod n} / (‖A‖ ‖B‖),   s = 0 .. n-1,
/// ~~~
///
/// and the score of one symmetry is
///
/// ~~~{.unparsed}
///   S = max_s ( [(K1 ⋆ K2)[s]]₊ + [(T1 ⋆ T2)[s]]₊ ) / 2 ∈ [0, 1],  [x]₊ = max(x, 0).
/// ~~~
///
/// The paper writes the bracket without the factor 1/2 and states that it lies
/// in [0, 1]; the sum of two correlations reaches 2, so we divide by 2: S = 1
/// exactly when both profiles agree up to a positive factor at one shift.
///
/// Symmetries. With `reversal`, the second curve is also compared with its
/// orientation reversed (vertex i -> n-1-i), whose signatures are the reversed
/// sequences: the correlations become convolutions Σ_i A_i B_{(s-i) mod n}.
/// With `mirror`, the mirror image of the second curve is also compared: T2
/// changes sign, so (T1 ⋆ T2) becomes -(T1 ⋆ T2). The similarity is the
/// maximum over the allowed symmetries (identity; reversed; mirrored;
/// reversed and mirrored when both are allowed). It is invariant under
/// rigid motions and cyclic re-indexing of either curve, symmetric in its
/// arguments (up to rounding, ~1e-15), and exactly 1 for a curve and itself.
///
/// Zero profiles. A profile whose RMS is at most `zero_tolerance` times the
/// curve's mean squared curvature, RMS(T) <= tol · mean(K²) (both sides are
/// [1/length²], so the test is scale-free), counts as zero. A planar curve
/// without inflections has T = 0 exactly, also after any rigid motion (see the
/// rounding rule in signature.hpp); the tolerance absorbs what rounding leaves
/// in nearly planar data. (A planar curve with inflections has T ≠ 0 by the
/// paper's definition: θ = π on each inflection edge.) The correlation of a
/// zero profile is defined as 1 for every shift when both profiles are zero
/// (they agree) and 0 when exactly one is (nothing in common; the term then
/// contributes nothing).
/// Two planar curves without inflections thus score (1 + max_s [(K1 ⋆ K2)[s]]₊)/2, a planar
/// and a 3D curve at most 1/2. K counts as zero only when all κ_i = 0, which
/// no closed polygon has (its total turning is at least 2π); the same rule
/// applies to it.
///
/// Rounding. The FFT result agrees with the direct O(n²) evaluation
/// (similarity_direct) to ~1e-15; a final score within kUnitySnap of 1 is
/// reported as exactly 1.
///
/// Common vertex count. SimilarityEngine works at a fixed n: a curve with
/// another vertex count (or every curve, with `resample`) is resampled at
/// equal arc length to n vertices (ek::resample_arclength: linear
/// interpolation, starting at vertex 0); otherwise a curve with n vertices is
/// used as it is (the data set's curves all have n nearly equal edges). The
/// one-shot functions take the smallest vertex count as the common n unless
/// `samples` is given. Resampling should go from finer to coarser curves, and
/// by a good factor: the resampled vertices lie on the input's chords, which
/// perturbs each turning angle by about (h_in/h_out)²/4 of itself (h the edge
/// lengths), and upsampling a polygon puts nodes on its straight edges
/// (κ = 0 between corners), a different signature.
///
/// Cost: per curve one signature and two real FFTs (cached in a
/// SignatureSpectrum); per pair two inverse real FFTs (four with reversal)
/// and O(n) products and maxima.
#include <complex>
#include <memory>
#include <vector>

#include "ek/analysis/signature.hpp"
#include "ek/geometry/types.hpp"

namespace ek {

/// Scores within this distance of 1 are reported as exactly 1 (the FFT's rounding is ~1e-15).
inline constexpr double kUnitySnap = 1e-12;

/// Options of the similarity measure.
struct SimilarityOptions {
  bool reversal = false;  ///< also compare with the second curve's orientation reversed (convolutions)
  bool mirror = false;    ///< also compare with the second curve's mirror image (torsion sign flipped)
  /// [1] common vertex count n for the one-shot functions; 0: the smallest
  /// vertex count of the curves (curves with more vertices are resampled).
  int samples = 0;
  /// resample every curve at equal arc length to the common count, also those that already have it
  bool resample = false;
  /// [1] a profile with RMS <= zero_tolerance · mean(K²) counts as zero (see above).
  double zero_tolerance = 1e-9;

  /// Throws std::invalid_argument unless samples is 0 or >= 3 and 0 <= zero_tolerance < 1.
  void validate() const;
};

/// Outcome of one comparison.
struct SimilarityResult {
  double similarity = 0.0;             ///< [1] score in [0, 1] (maximum over the allowed symmetries)
  double curvature_correlation = 0.0;  ///< [1] (K1 ⋆ K2') at the best shift, in [-1, 1]
  double torsion_correlation = 0.0;    ///< [1] (T1 ⋆ T2') at the best shift, in [-1, 1]
  /// [1] best shift s: vertex i of the first curve matches vertex (i + s) mod n
  /// of the second curve after the symmetry below (both at the common n).
  int best_shift = 0;
  bool reversed = false;  ///< the best score uses the second curve's reversed orientation
  bool mirrored = false;  ///< the best score uses the second curve's mirror image
  int samples = 0;        ///< [1] the common vertex count n the curves were compared at
};

/// Fourier transforms of a signature, normalised, for repeated comparisons.
/// Immutable once built (by SimilarityEngine::spectrum), so one spectrum can be
/// shared by several engines and threads.
class SignatureSpectrum {
 public:
  SignatureSpectrum() = default;   ///< An empty spectrum (size 0); SimilarityEngine::spectrum() makes real ones.
  int size() const { return n_; }  ///< n, the signature length
  bool curvature_is_zero() const { return k_zero_; }  ///< whether K is zero (‖K‖ = 0)
  /// whether T counts as zero (RMS(T) <= zero_tolerance · mean(K²), or K zero)
  bool torsion_is_zero() const { return t_zero_; }
  /// r2c transforms (n/2 + 1 coefficients) of K/‖K‖ and T/‖T‖ (zero arrays for zero profiles).
  const std::vector<std::complex<double>>& curvature_spectrum() const { return fk_; }
  /// as curvature_spectrum(), of T/‖T‖
  const std::vector<std::complex<double>>& torsion_spectrum() const { return ft_; }

 private:
  friend class SimilarityEngine;
  int n_ = 0;
  bool k_zero_ = true, t_zero_ = true;
  std::vector<std::complex<double>> fk_, ft_;
};

/// Computes similarities at a fixed vertex count n with FFTW plans created
/// once (FFTW_ESTIMATE: deterministic results) and work buffers reused.
/// Not thread-safe: use one engine per thread (creating engines in several
/// threads at once is safe: the FFTW planner is guarded by a mutex).
class SimilarityEngine {
 public:
  /// n >= 3 signature length; options.samples is ignored (n is the common count).
  explicit SimilarityEngine(int n, const SimilarityOptions& options = {});
  ~SimilarityEngine();                                            ///< Destroys the FFTW plans and buffers.
  SimilarityEngine(const SimilarityEngine&) = delete;             ///< Not copyable.
  SimilarityEngine& operator=(const SimilarityEngine&) = delete;  ///< Not copyable.
  SimilarityEngine(SimilarityEngine&&) noexcept;                  ///< Moves the plans and buffers.
  SimilarityEngine& operator=(SimilarityEngine&&) noexcept;       ///< Moves the plans and buffers.

  int size() const;                          ///< n, the signature length compared
  const SimilarityOptions& options() const;  ///< the options as given

  /// Spectrum of a curve (resampled to n vertices when it has another count or options.resample is set).
  SignatureSpectrum spectrum(const Points& P);
  /// Spectrum of a signature of length n.
  SignatureSpectrum spectrum(const CurveSignature& s);

  /// Full comparison (score, correlations, best shift and symmetry).
  SimilarityResult compare(const SignatureSpectrum& a, const SignatureSpectrum& b);
  /// The score only.
  double similarity(const SignatureSpectrum& a, const SignatureSpectrum& b) { return compare(a, b).similarity; }

  /// N by N symmetric matrix of similarities, diagonal exactly 1 (each pair computed once).
  Eigen::MatrixXd matrix(const std::vector<SignatureSpectrum>& spectra);
  /// |a| by |b| matrix of similarities between two sets (e.g.\ a new batch against earlier curves).
  Eigen::MatrixXd cross_matrix(const std::vector<SignatureSpectrum>& a, const std::vector<SignatureSpectrum>& b);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// One-shot comparison of two curves (see the header comment for the common n).
SimilarityResult compare_curves(const Points& a, const Points& b, const SimilarityOptions& options = {});
/// One-shot similarity score of two curves.
double similarity(const Points& a, const Points& b, const SimilarityOptions& options = {});

/// Similarity matrix of N curves (N by N, symmetric, diagonal 1). The common n
/// is options.samples, or else the smallest vertex count.
Eigen::MatrixXd similarity_matrix(const std::vector<Points>& curves, const SimilarityOptions& options = {});

/// Reference evaluation of the same measure by direct O(n²) sums (no FFT),
/// for tests and validation. The signatures must have equal length.
SimilarityResult similarity_direct(const CurveSignature& a, const CurveSignature& b,
                                   const SimilarityOptions& options = {});

}  // namespace ek
