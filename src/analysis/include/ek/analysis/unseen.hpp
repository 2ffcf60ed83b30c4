#pragma once
/// \file
/// What a knot's sampling has not seen yet, estimated from how many samples
/// fell into each distinct state: a state is a "species", a sample an
/// "individual", and the estimators are those of species richness.
///
/// With n samples in D observed states, f1 of them seen once (singletons)
/// and f2 twice (doubletons), r = (n − 1)/n:
///
///  - Good–Turing (I. J. Good, Biometrika 40, 1953): the probability that
///    the next sample lands in an unseen state is about f1 / n.
///  - Chao and Jost (Ecology 93, 2012, eq. 4b), the same probability
///    (one minus the sample coverage) with the doubletons' correction:
///    f1/n · (n − 1) f1 / ((n − 1) f1 + 2 f2)  (0 when f1 = 0).
///  - Chao1 (A. Chao, Scand. J. Statist. 11, 1984), the number of states:
///    D + r f1² / (2 f2) when f2 > 0, its bias-corrected form
///    D + r f1 (f1 − 1) / 2 when f2 = 0; a lower bound in expectation when
///    the states' probabilities differ (it is exact in expectation for equal
///    ones), so an estimate of the states *at least* present.
///  - Its interval (A. Chao, Biometrics 43, 1987): log-normal for the unseen
///    part t = Chao1 − D, [D + t/K, D + t K], K = exp(z √log(1 + var/t²)),
///    with Chao's variance; with no singleton, or one and no doubleton, Chao1
///    is D and the interval that of Chao (1987) for an almost complete
///    sample, D/(1 − P) ± z √var/(1 − P) with P = Σ f_i e^(−i) / D, at least D.
///    The variances are those of Chao's SpadeR (Chao1 and Chao1-bc).
///  - Good–Turing for one kind of state (Good 1953, for the species of a
///    subgroup chosen by an attribute of the species, e.g. low energy): the
///    probability that the next sample lands in an unseen state of the kind
///    is about f1(kind) / n, the kind's singletons over all samples (in
///    expectation exactly Σ_{i in kind} p_i (1 − p_i)^n, the kind's unseen
///    mass after n samples, with f1 counted after n + 1 samples).
#include <vector>

namespace ek {

/// The confidence level of estimate_unseen()'s interval.
struct UnseenOptions {
  double confidence = 0.95;  ///< [1] two-sided level of the interval, in (0, 1)
};

/// What estimate_unseen() returns: the counts it starts from and the estimates
/// of the unseen states (see the file's description).
struct UnseenEstimate {
  int samples = 0;                     ///< [1] n: samples that reached a state
  int observed = 0;                    ///< [1] D: states seen
  int singletons = 0;                  ///< [1] f1
  int doubletons = 0;                  ///< [1] f2
  double good_turing = 0.0;            ///< [1] f1 / n: the next sample's chance of a new state
  double new_state_probability = 0.0;  ///< [1] Chao–Jost 1 − coverage: the same, corrected
  double states = 0.0;                 ///< [1] Chao1: states estimated in all (≥ D)
  double lower = 0.0;                  ///< [1] its interval at options.confidence (≥ D)
  double upper = 0.0;                  ///< [1]
};

/// The estimates from `counts`, the samples in each observed state (entries
/// of 0 are ignored). No samples: everything 0. Throws InputError for a
/// negative count or a confidence outside (0, 1).
UnseenEstimate estimate_unseen(const std::vector<int>& counts, const UnseenOptions& options = {});

/// Good–Turing for one kind of state: f1(kind) / n, with n the samples of
/// every state (`counts` as above) and f1(kind) the states seen once whose
/// `of_kind` entry is true (of_kind[i] describes counts[i]). No samples: 0.
/// Throws InputError for a negative count or unequal lengths.
double new_state_probability_of_kind(const std::vector<int>& counts, const std::vector<bool>& of_kind);

/// The chance that `batch` further samples find at least one state not yet
/// seen, each with chance p: 1 − (1 − p)^batch (p in [0, 1], batch ≥ 0).
double new_state_probability_in_batch(double p, int batch);

}  // namespace ek
