// Microbenchmarks of the solver's factorisations: the Hessian of a relaxed
// trefoil (rod + contact, n = 400, the default material) factorised by
// CholeskySolver with a new symbolic analysis every time (the contact set
// changed) against a numeric factorisation that reuses it (the contact set
// unchanged: what the solver skips). First argument: the mode, 0 CHOLMOD
// simplicial, 1 CHOLMOD supernodal, 2 the 3 × 3 block factorisation.
#include <benchmark/benchmark.h>

#include <cmath>

#include "ek/contact/contact_potential.hpp"
#include "ek/core/sparse_assembler.hpp"
#include "ek/optim/cholesky.hpp"
#include "ek/rod/elastic_rod.hpp"
#include "ek/solver/relax.hpp"

using namespace ek;

namespace {

// The (2,3) torus knot with n = 400 edges of length ~1 (its edge lengths are
// the rest lengths), relaxed once.
struct Trefoil {
  Points start, relaxed;
};

const Trefoil& relaxed_trefoil() {
  static const Trefoil K = [] {
    const int n = 400;
    Points T(n, 3);
    for (int i = 0; i < n; ++i) {
      const double t = 2.0 * M_PI * i / n;
      T.row(i) << (2.0 + std::cos(3 * t)) * std::cos(2 * t), (2.0 + std::cos(3 * t)) * std::sin(2 * t),
          std::sin(3 * t);
    }
    double L = 0.0;
    for (int i = 0; i < n; ++i) L += (T.row((i + 1) % n) - T.row(i)).norm();
    T *= n / L;
    return Trefoil{T, relax(T).positions};
  }();
  return K;
}

// The relaxed trefoil as relax() models it: a twist-free rod with the start's
// edge lengths as rest lengths, the default material, and its contact
// options (d̂ = 2r, ω = 1e3).
ElasticRod trefoil_rod() {
  const Points& P = relaxed_trefoil().relaxed;
  const Points& S = relaxed_trefoil().start;
  VecX rest(S.rows());
  for (Eigen::Index i = 0; i < S.rows(); ++i) rest(i) = (S.row((i + 1) % S.rows()) - S.row(i)).norm();
  return ElasticRod(P, rest, RodMaterial{}, TwistModel::TwistFree);
}

ContactOptions trefoil_contact_options() {
  ContactOptions co;
  co.dhat = 2.0 * RodMaterial{}.radius;
  co.stiffness = 1e3;
  return co;
}

struct Hessian {
  SparseAssembler A;
  Hessian() {
    const Points& P = relaxed_trefoil().relaxed;
    const ElasticRod rod = trefoil_rod();
    ContactPotential contact(CurveTopology::single(static_cast<int>(P.rows())), trefoil_contact_options());
    contact.update(P);
    A.begin(rod.num_dofs());
    A.segment(0, rod.hessian_structure());
    rod.add_hessian(A);
    A.segment(1, contact.hessian_structure());
    contact.add_hessian(P, A);
    A.end();
  }
};

const Hessian& hessian() {
  static const Hessian h;
  return h;
}

CholeskyMode mode_of(std::int64_t k) {
  return k == 0 ? CholeskyMode::Simplicial : k == 1 ? CholeskyMode::Supernodal : CholeskyMode::Block;
}

void BM_FactorizeSymbolicAndNumeric(benchmark::State& state) {
  const auto& H = hessian().A.matrix();
  CholeskyOptions o;
  o.mode = mode_of(state.range(0));
  // second argument 1: the AMD ordering is kept and only the symbolic
  // analysis redone (what the solver does on a contact-set change); 0: AMD too
  o.reuse_ordering = state.range(1) != 0;
  CholeskySolver chol(o);
  std::uint64_t version = 0;
  for (auto _ : state) benchmark::DoNotOptimize(chol.factorize(H, 1e-6, ++version));
  state.counters["nnz_L"] = static_cast<double>(chol.factor_nonzeros());
}

void BM_FactorizeNumericOnly(benchmark::State& state) {
  const auto& H = hessian().A.matrix();
  CholeskyOptions o;
  o.mode = mode_of(state.range(0));
  CholeskySolver chol(o);
  if (!chol.factorize(H, 1e-6, 1)) state.SkipWithError("not positive definite");
  for (auto _ : state) benchmark::DoNotOptimize(chol.factorize(H, 1e-6, 1));
}

void BM_Solve(benchmark::State& state) {
  const auto& H = hessian().A.matrix();
  CholeskySolver chol(mode_of(state.range(0)));
  if (!chol.factorize(H, 1e-6, 1)) state.SkipWithError("not positive definite");
  const VecX b = VecX::Ones(H.rows());
  for (auto _ : state) benchmark::DoNotOptimize(chol.solve(b));
}

}  // namespace

// The assembler's pattern rebuild when the contact set changes (what the
// solver pays at every contact change before the symbolic analysis): the
// relaxed trefoil's rod Hessian replayed and its contact Hessian recorded
// under a new structure id, alternating between the contact set of the
// relaxed curve and that of the curve 1% larger (empty: the contacts of the
// equilibrium are less than 1% deep). Argument 0: the same contact set every
// pass (replayed: the cost of filling values alone), 1: alternating (a
// rebuild every pass).
void BM_AssemblerPatternRebuild(benchmark::State& state) {
  const bool alternate = state.range(0) != 0;
  const Points& P = relaxed_trefoil().relaxed;
  const ElasticRod rod = trefoil_rod();
  const Points Q = 1.01 * P;
  ContactPotential c0(CurveTopology::single(static_cast<int>(P.rows())), trefoil_contact_options()), c1 = c0;
  c0.update(P);
  c1.update(Q);
  SparseAssembler A;
  int pass = 0;
  for (auto _ : state) {
    const bool first = !alternate || (pass++ % 2) == 0;
    const ContactPotential& c = first ? c0 : c1;
    A.begin(rod.num_dofs());
    A.segment(0, rod.hessian_structure());
    rod.add_hessian(A);
    A.segment(1, c.hessian_structure());
    c.add_hessian(first ? P : Q, A);
    benchmark::DoNotOptimize(A.end());
  }
  state.counters["contacts"] = static_cast<double>(c0.num_active());
  state.counters["contacts_larger"] = static_cast<double>(c1.num_active());
}

BENCHMARK(BM_AssemblerPatternRebuild)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_FactorizeSymbolicAndNumeric)->ArgsProduct({{0, 1, 2}, {0, 1}})->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_FactorizeNumericOnly)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Solve)->Arg(0)->Arg(2)->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();
