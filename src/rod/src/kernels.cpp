#include "ek/rod/kernels.hpp"

#include <cmath>

namespace ek::rod {

namespace {

Mat3 cross_matrix(const Vec3& a) {
  Mat3 A;
  A << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
  return A;
}

/// Chain rule through t = e/|e|: gradient with respect to e from the gradient
/// g with respect to t.
Vec3 unit_gradient(const Vec3& t, double len, const Vec3& g) { return (g - t * t.dot(g)) / len; }

/// Σ_k g_k ∂²t_k/∂e² = [3 (g·t) t tᵀ - t gᵀ - g tᵀ - (g·t) I] / |e|².
Mat3 unit_curvature_term(const Vec3& t, double len, const Vec3& g) {
  const double gt = g.dot(t);
  Mat3 C = 3.0 * gt * t * t.transpose() - t * g.transpose() - g * t.transpose();
  C.diagonal().array() -= gt;
  return C / (len * len);
}

}  // namespace

// ---------------------------------------------------------------------------
// Stretching

double stretch_energy(const Vec3& e, double rest_length, double EA) {
  const double d = e.norm() - rest_length;
  return 0.5 * EA * d * d / rest_length;
}

Vec3 stretch_gradient(const Vec3& e, double rest_length, double EA) {
  const double len = e.norm();
  return (EA / rest_length) * (len - rest_length) / len * e;
}

Mat3 stretch_hessian(const Vec3& e, double rest_length, double EA) {
  const double len = e.norm();
  const Vec3 t = e / len;
  const double k = EA / rest_length;
  const double s = 1.0 - rest_length / len;
  Mat3 H = (k * (1.0 - s)) * (t * t.transpose());
  H.diagonal().array() += k * s;
  return H;
}

Mat3 stretch_hessian_projected(const Vec3& e, double rest_length, double EA) {
  const double len = e.norm();
  if (len >= rest_length) return stretch_hessian(e, rest_length, EA);
  const Vec3 t = e / len;
  return (EA / rest_length) * (t * t.transpose());
}

// ---------------------------------------------------------------------------
// Bending

Vec3 curvature_binormal(const Vec3& a, const Vec3& b) {
  return 2.0 * a.cross(b) / (a.norm() * b.norm() + a.dot(b));
}

// |κb|² = f(p, q) = 4 (p - q)/(p + q) with p = |a||b|, q = a·b.

double kb_squared(const Vec3& a, const Vec3& b) {
  const double p = a.norm() * b.norm(), q = a.dot(b);
  return 4.0 * (p - q) / (p + q);
}

Vec6 kb_squared_gradient(const Vec3& a, const Vec3& b) {
  const double la = a.norm(), lb = b.norm();
  const double p = la * lb, q = a.dot(b), s = p + q;
  const double fp = 8.0 * q / (s * s), fq = -8.0 * p / (s * s);
  Vec6 g;
  g.head<3>() = fp * (lb / la) * a + fq * b;
  g.tail<3>() = fp * (la / lb) * b + fq * a;
  return g;
}

// Each 3 by 3 block of the Hessian is c_I I + c_aa a aᵀ + c_ab a bᵀ + c_ba b aᵀ + c_bb b bᵀ:
//   H_aa = (f_pp lb²/la² - f_p lb/la³) a aᵀ + f_qq b bᵀ + f_pq lb/la (a bᵀ + b aᵀ) + f_p lb/la I
//   H_bb = (f_pp la²/lb² - f_p la/lb³) b bᵀ + f_qq a aᵀ + f_pq la/lb (a bᵀ + b aᵀ) + f_p la/lb I
//   H_ab = (f_pp + f_p/(la lb)) a bᵀ + f_qq b aᵀ + f_pq (lb/la a aᵀ + la/lb b bᵀ) + f_q I
// from H = f_pp ∇p∇pᵀ + f_qq ∇q∇qᵀ + f_pq (∇p∇qᵀ + ∇q∇pᵀ) + f_p ∇²p + f_q ∇²q with
// ∇p = (lb/la a, la/lb b), ∇q = (b, a), ∇²p = [[lb/la (I - ââᵀ), â b̂ᵀ], [b̂ âᵀ, la/lb (I - b̂b̂ᵀ)]],
// ∇²q = [[0, I], [I, 0]].

namespace {

/// H += c_I I + c_aa a aᵀ + c_ab a bᵀ + c_ba b aᵀ + c_bb b bᵀ.
inline __attribute__((always_inline)) void add_dyadic_block(const Vec3& a, const Vec3& b, double cI, double caa,
                                                            double cab, double cba, double cbb, Mat3& H) {
  const Vec3 u = caa * a + cba * b;  // coefficient vector multiplying aᵀ
  const Vec3 v = cab * a + cbb * b;  // coefficient vector multiplying bᵀ
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) H(r, c) += u(r) * a(c) + v(r) * b(c);
  H(0, 0) += cI;
  H(1, 1) += cI;
  H(2, 2) += cI;
}

}  // namespace

void add_kb_squared_hessian_blocks(const Vec3& a, const Vec3& b, double scale, Mat3& Haa, Mat3& Hab, Mat3& Hbb) {
  const double la2 = a.squaredNorm(), lb2 = b.squaredNorm();
  const double la = std::sqrt(la2), lb = std::sqrt(lb2);
  const double p = la * lb, q = a.dot(b), s = p + q;
  const double is = 1.0 / s, is2 = is * is, is3 = is2 * is;
  const double fp = 8.0 * q * is2 * scale, fq = -8.0 * p * is2 * scale;
  const double fpp = -16.0 * q * is3 * scale, fqq = 16.0 * p * is3 * scale, fpq = 8.0 * (p - q) * is3 * scale;
  const double ra = lb / la, rb = la / lb;
  add_dyadic_block(a, b, fp * ra, fpp * ra * ra - fp * ra / la2, fpq * ra, fpq * ra, fqq, Haa);
  add_dyadic_block(a, b, fp * rb, fqq, fpq * rb, fpq * rb, fpp * rb * rb - fp * rb / lb2, Hbb);
  add_dyadic_block(a, b, fq, fpq * ra, fpp + fp / p, fqq, fpq * rb, Hab);
}

Mat6 kb_squared_hessian(const Vec3& a, const Vec3& b) {
  Mat3 Haa = Mat3::Zero(), Hab = Mat3::Zero(), Hbb = Mat3::Zero();
  add_kb_squared_hessian_blocks(a, b, 1.0, Haa, Hab, Hbb);
  Mat6 H;
  H << Haa, Hab, Hab.transpose(), Hbb;
  return H;
}

// ---------------------------------------------------------------------------
// Spherical geometry

Vec3 parallel_transport(const Vec3& a, const Vec3& b, const Vec3& v) {
  return v - (b.dot(v) / (1.0 + a.dot(b))) * (a + b);
}

double signed_angle(const Vec3& u, const Vec3& v, const Vec3& axis) {
  return std::atan2(u.cross(v).dot(axis), u.dot(v));
}

double solid_angle(const Vec3& a, const Vec3& b, const Vec3& c) {
  return 2.0 * std::atan2(a.dot(b.cross(c)), 1.0 + a.dot(b) + b.dot(c) + c.dot(a));
}

// Ω = 2 atan2(N, D), N = a·(b×c), D = 1 + a·b + b·c + c·a, as a function of (b, c):
//   ∇N = (c×a, a×b), ∇D = (a+c, a+b), ∇²N = [[0, -[a]×], [[a]×, 0]], ∇²D = [[0, I], [I, 0]];
//   ∇atan2 = (D∇N - N∇D)/ρ, ρ = N² + D²,
//   ∇²atan2 = (D∇²N - N∇²D)/ρ - 2/ρ² [DN (∇N∇Nᵀ - ∇D∇Dᵀ) + (D² - N²)/2 (∇N∇Dᵀ + ∇D∇Nᵀ)]
// (the antisymmetric parts of the two terms of the quotient rule cancel).

namespace {

/// Ω and its derivatives with respect to (b, c) in one pass.
void solid_angle_derivatives(const Vec3& a, const Vec3& b, const Vec3& c, Vec6& G, Mat6& H) {
  const double N = a.dot(b.cross(c)), D = 1.0 + a.dot(b) + b.dot(c) + c.dot(a);
  const double rho = N * N + D * D;
  Vec6 gN, gD;
  gN << c.cross(a), a.cross(b);
  gD << a + c, a + b;
  G = (2.0 / rho) * (D * gN - N * gD);
  const double s = -4.0 / (rho * rho);
  H.noalias() = (s * D * N) * (gN * gN.transpose() - gD * gD.transpose());
  H.noalias() += (0.5 * s * (D * D - N * N)) * (gN * gD.transpose() + gD * gN.transpose());
  const Mat3 A = (2.0 * D / rho) * cross_matrix(a);
  H.topRightCorner<3, 3>() -= A;
  H.bottomLeftCorner<3, 3>() += A;
  H.topRightCorner<3, 3>().diagonal().array() -= 2.0 * N / rho;
  H.bottomLeftCorner<3, 3>().diagonal().array() -= 2.0 * N / rho;
}

/// Ω and its derivatives with respect to c only (∇²N_cc = ∇²D_cc = 0).
void solid_angle_c_derivatives(const Vec3& a, const Vec3& b, const Vec3& c, Vec3& G, Mat3& H) {
  const double N = a.dot(b.cross(c)), D = 1.0 + a.dot(b) + b.dot(c) + c.dot(a);
  const double rho = N * N + D * D;
  const Vec3 gN = a.cross(b), gD = a + b;
  G = (2.0 / rho) * (D * gN - N * gD);
  const double s = -4.0 / (rho * rho);
  H.noalias() = (s * D * N) * (gN * gN.transpose() - gD * gD.transpose());
  H.noalias() += (0.5 * s * (D * D - N * N)) * (gN * gD.transpose() + gD * gN.transpose());
}

}  // namespace

Vec6 solid_angle_gradient(const Vec3& a, const Vec3& b, const Vec3& c) {
  Vec6 G;
  Mat6 H;
  solid_angle_derivatives(a, b, c, G, H);
  return G;
}

Mat6 solid_angle_hessian(const Vec3& a, const Vec3& b, const Vec3& c) {
  Vec6 G;
  Mat6 H;
  solid_angle_derivatives(a, b, c, G, H);
  return H;
}

// ---------------------------------------------------------------------------
// Reference twist

double reference_twist_change(const Vec3& sa, const Vec3& sb, const Vec3& a, const Vec3& b) {
  const Vec3 ta = a.normalized(), tb = b.normalized();
  return -(solid_angle(sa, ta, tb) + solid_angle(sb, sa, tb));
}

Vec6 reference_twist_change_gradient(const Vec3& sa, const Vec3& sb, const Vec3& a, const Vec3& b) {
  const double la = a.norm(), lb = b.norm();
  const Vec3 ta = a / la, tb = b / lb;
  // Only gradients are needed: ∇Ω from the closed form (D∇N - N∇D) 2/ρ.
  auto grad = [](const Vec3& p, const Vec3& q, const Vec3& r, Vec3& gq, Vec3& gr) {
    const double N = p.dot(q.cross(r)), D = 1.0 + p.dot(q) + q.dot(r) + r.dot(p);
    const double w = 2.0 / (N * N + D * D);
    gq = w * (D * r.cross(p) - N * (p + r));
    gr = w * (D * p.cross(q) - N * (p + q));
  };
  Vec3 g1a, g1b, g2b, unused;
  grad(sa, ta, tb, g1a, g1b);
  grad(sb, sa, tb, unused, g2b);
  Vec6 g;
  g.head<3>() = -unit_gradient(ta, la, g1a);
  g.tail<3>() = -unit_gradient(tb, lb, Vec3(g1b + g2b));
  return g;
}

void reference_twist_change_derivatives(const Vec3& sa, const Vec3& sb, const Vec3& a, const Vec3& b, Vec6& g,
                                        Mat6& H) {
  const double la = a.norm(), lb = b.norm();
  const Vec3 ta = a / la, tb = b / lb;
  Vec6 G;
  Mat6 Ht;
  solid_angle_derivatives(sa, ta, tb, G, Ht);
  Vec3 G2;
  Mat3 H2;
  solid_angle_c_derivatives(sb, sa, tb, G2, H2);
  G.tail<3>() += G2;
  Ht.bottomRightCorner<3, 3>() += H2;
  g.head<3>() = -unit_gradient(ta, la, G.head<3>());
  g.tail<3>() = -unit_gradient(tb, lb, G.tail<3>());
  const Mat3 Pa = (Mat3::Identity() - ta * ta.transpose()) / la;
  const Mat3 Pb = (Mat3::Identity() - tb * tb.transpose()) / lb;
  H.topLeftCorner<3, 3>().noalias() = -(Pa * Ht.topLeftCorner<3, 3>() * Pa);
  H.topLeftCorner<3, 3>() -= unit_curvature_term(ta, la, G.head<3>());
  H.bottomRightCorner<3, 3>().noalias() = -(Pb * Ht.bottomRightCorner<3, 3>() * Pb);
  H.bottomRightCorner<3, 3>() -= unit_curvature_term(tb, lb, G.tail<3>());
  H.topRightCorner<3, 3>().noalias() = -(Pa * Ht.topRightCorner<3, 3>() * Pb);
  H.bottomLeftCorner<3, 3>() = H.topRightCorner<3, 3>().transpose();
}

Mat6 reference_twist_change_hessian(const Vec3& sa, const Vec3& sb, const Vec3& a, const Vec3& b) {
  Vec6 g;
  Mat6 H;
  reference_twist_change_derivatives(sa, sb, a, b, g, H);
  return H;
}

// ---------------------------------------------------------------------------
// Edge to vertex coordinates

Vec9 to_vertices(const Vec6& g) {
  Vec9 out;
  out.segment<3>(0) = -g.head<3>();
  out.segment<3>(3) = g.head<3>() - g.tail<3>();
  out.segment<3>(6) = g.tail<3>();
  return out;
}

Mat9 to_vertices(const Mat6& H) {
  const Mat3 Haa = H.topLeftCorner<3, 3>(), Hab = H.topRightCorner<3, 3>();
  const Mat3 Hba = H.bottomLeftCorner<3, 3>(), Hbb = H.bottomRightCorner<3, 3>();
  Mat9 out;
  out.block<3, 3>(0, 0) = Haa;
  out.block<3, 3>(0, 3) = Hab - Haa;
  out.block<3, 3>(0, 6) = -Hab;
  out.block<3, 3>(3, 0) = Hba - Haa;
  out.block<3, 3>(3, 3) = Haa - Hab - Hba + Hbb;
  out.block<3, 3>(3, 6) = Hab - Hbb;
  out.block<3, 3>(6, 0) = -Hba;
  out.block<3, 3>(6, 3) = Hba - Hbb;
  out.block<3, 3>(6, 6) = Hbb;
  return out;
}

}  // namespace ek::rod
