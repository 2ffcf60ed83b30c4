#pragma once
// Shared test helpers: data locations, seeded random curves, finite differences.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <functional>
#include <random>
#include <string>

#include "ek/core/errors.hpp"
#include "ek/geometry/types.hpp"

namespace ek::fixtures {

/// An n by 3 matrix (Points, LatticePoints, ...) from a list of rows.
template <class Matrix>
Matrix rows3(std::initializer_list<std::array<typename Matrix::Scalar, 3>> rows) {
  Matrix M(static_cast<Eigen::Index>(rows.size()), 3);
  Eigen::Index i = 0;
  for (const auto& r : rows) M.row(i++) << r[0], r[1], r[2];
  return M;
}

/// Folder of the peer implementation's curves (../shared/data/peer).
std::string peer_dir();

/// The bytes of the file at `path` ("" when it cannot be read).
std::string read_bytes(const std::string& path);

/// Writes `bytes` as the whole file at `path` (created or truncated).
void write_bytes(const std::string& path, const std::string& bytes);

/// The value of type T stored at byte `offset` of `bytes` (native byte order).
template <class T>
T read_at(const std::string& bytes, size_t offset) {
  T x;
  std::memcpy(&x, bytes.data() + offset, sizeof(T));
  return x;
}

/// A random smooth closed curve: a sum of `modes` random Fourier modes,
/// sampled at n points (not necessarily simple).
Points random_fourier_curve(int n, int modes, std::uint64_t seed, double amplitude = 1.0);

/// A random walk of n unit steps along the axes of the cubic lattice from
/// the origin (open, not self-avoiding): many coplanar and collinear points.
Points random_lattice_walk(int n, std::uint64_t seed);

/// Circle of radius R in the xy-plane, n vertices, centred at the origin.
Points circle(int n, double R);

/// Circle of centre c and radius r in the plane of the unit vectors u, v,
/// n vertices, run from c + r·u towards c + r·v.
Points circle(int n, const Vec3& c, double r, const Vec3& u, const Vec3& v);

/// A ring of n unit edges (a regular n-gon) in the plane z = z0, centred on the z axis.
Points unit_ring(int n, double z0 = 0.0);

/// Ellipse (a cos t, b sin t, 0), t = 2πi/n, n vertices.
Points ellipse(int n, double a, double b);

/// Torus knot T(p, q) on a torus with radii R (core) and r (tube), n vertices.
Points torus_knot(int n, int p, int q, double R = 2.0, double r = 1.0);

/// Applies a rotation, translation and cyclic shift of the vertex order.
Points rigid_copy(const Points& P, const Mat3& R, const Vec3& t, int shift);

/// A random rotation matrix from a seed.
Mat3 random_rotation(std::uint64_t seed);

/// The mirror image in the plane x = 0 (x negated; chirality flips).
Points mirror_x(const Points& P);

/// Expects f() to throw InputError whose message contains `needle`.
template <class F>
void expect_input_error(F f, const std::string& needle) {
  try {
    f();
    ADD_FAILURE() << "expected InputError containing '" << needle << "'";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
  }
}

/// Central finite-difference derivative of f along the coordinates of x:
/// returns g with g_i ≈ (f(x + h e_i) - f(x - h e_i)) / 2h.
VecX fd_gradient(const std::function<double(const VecX&)>& f, const VecX& x, double h);

}  // namespace ek::fixtures
