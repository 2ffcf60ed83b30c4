#include "ek/solver/multilevel.hpp"

#include <utility>

#include "ek/contact/topology.hpp"
#include "ek/core/errors.hpp"

namespace ek {
namespace {

template <class M>
M shifted(const M& A, int k) {
  const Eigen::Index n = A.rows();
  require(k >= 0 && k < n, "shift_vertices: the shift must be in [0, n)");
  if (k == 0) return A;
  M B(A.rows(), A.cols());
  B.topRows(n - k) = A.bottomRows(n - k);
  B.bottomRows(k) = A.topRows(k);
  return B;
}

/// Where the odd vertex between a and b sits: a + w (b − a), w = l_a / (l_a + l_b).
Vec3 on_segment(const Points& P, int a, int b, double la, double lb) {
  const double w = la / (la + lb);
  return (P.row(a) + w * (P.row(b) - P.row(a))).transpose();
}

}  // namespace

CoarseCurve coarsen(const Points& fine, const VecX& rest, const ContactOptions& contact) {
  const int n = static_cast<int>(fine.rows());
  require(n >= 8 && n % 2 == 0, "coarsen: the curve needs an even number of vertices, at least 8");
  require(rest.size() == n && rest.minCoeff() > 0.0, "coarsen: rest lengths must be n positive numbers");
  CoarseCurve c;
  c.collapsed = fine;
  c.coarse.resize(n / 2, 3);
  c.coarse_rest.resize(n / 2);
  for (int k = 0; k < n / 2; ++k) {
    const int odd = 2 * k + 1, next = (2 * k + 2) % n;
    c.collapsed.row(odd) = on_segment(fine, 2 * k, next, rest(2 * k), rest(odd)).transpose();
    c.coarse.row(k) = fine.row(2 * k);
    c.coarse_rest(k) = rest(2 * k) + rest(odd);
  }
  c.certified = max_step(fine, c.collapsed - fine, CurveTopology::single(n), contact);
  return c;
}

Points refine(const Points& coarse, const VecX& fine_rest) {
  const int m = static_cast<int>(coarse.rows());
  require(fine_rest.size() == 2 * m, "refine: the fine rest lengths must be twice as many as the coarse vertices");
  Points P(2 * m, 3);
  for (int k = 0; k < m; ++k) {
    P.row(2 * k) = coarse.row(k);
    P.row(2 * k + 1) = on_segment(coarse, k, (k + 1) % m, fine_rest(2 * k), fine_rest(2 * k + 1)).transpose();
  }
  return P;
}

Points shift_vertices(const Points& A, int k) { return shifted(A, k); }
VecX shift_vertices(const VecX& A, int k) { return shifted(A, k); }

std::optional<ShiftedCoarsening> certified_coarsening(const Points& fine, const VecX& rest,
                                                      const ContactOptions& contact, bool either_parity) {
  for (int offset = 0; offset < (either_parity ? 2 : 1); ++offset) {
    CoarseCurve c = coarsen(shift_vertices(fine, offset), shift_vertices(rest, offset), contact);
    if (c.certified >= 1.0) return ShiftedCoarsening{std::move(c), offset};
  }
  return std::nullopt;
}

Points refine(const Points& coarse, const VecX& fine_rest, int offset) {
  const Points P = refine(coarse, shift_vertices(fine_rest, offset));
  return offset == 0 ? P : shift_vertices(P, static_cast<int>(P.rows()) - offset);
}

}  // namespace ek
