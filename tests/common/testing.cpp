#include "testing.hpp"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>

#include <Eigen/Geometry>

#include "ek/core/config.hpp"

namespace ek::fixtures {

std::string peer_dir() {
  const char* env = std::getenv("EK_PEER_DATA");
  if (env && env[0]) return env;
  return config::kPeerDataDir;
}

std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

Points random_lattice_walk(int n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> step(0, 5);
  Points walk(n, 3);
  Vec3 x = Vec3::Zero();
  for (Eigen::Index i = 0; i < walk.rows(); ++i) {
    const int s = step(rng);
    x(s % 3) += s < 3 ? 1.0 : -1.0;
    walk.row(i) = x.transpose();
  }
  return walk;
}

Points random_fourier_curve(int n, int modes, std::uint64_t seed, double amplitude) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> N(0.0, 1.0);
  Eigen::MatrixXd a(modes, 3), b(modes, 3);
  for (int k = 0; k < modes; ++k)
    for (int c = 0; c < 3; ++c) {
      a(k, c) = amplitude * N(rng) / (k + 1);
      b(k, c) = amplitude * N(rng) / (k + 1);
    }
  Points P(n, 3);
  for (int i = 0; i < n; ++i) {
    const double s = 2.0 * M_PI * i / n;
    Vec3 p = Vec3::Zero();
    for (int k = 0; k < modes; ++k)
      p += (a.row(k) * std::cos((k + 1) * s) + b.row(k) * std::sin((k + 1) * s)).transpose();
    P.row(i) = p.transpose();
  }
  return P;
}

Points circle(int n, double R) {
  Points P(n, 3);
  for (int i = 0; i < n; ++i) {
    const double s = 2.0 * M_PI * i / n;
    P.row(i) << R * std::cos(s), R * std::sin(s), 0.0;
  }
  return P;
}

Points circle(int n, const Vec3& c, double r, const Vec3& u, const Vec3& v) {
  Points P(n, 3);
  for (int i = 0; i < n; ++i) {
    const double t = 2.0 * M_PI * i / n;
    P.row(i) = (c + r * (std::cos(t) * u + std::sin(t) * v)).transpose();
  }
  return P;
}

Points unit_ring(int n, double z0) {
  Points P = circle(n, 0.5 / std::sin(M_PI / n));
  P.col(2).setConstant(z0);
  return P;
}

Points ellipse(int n, double a, double b) {
  Points P(n, 3);
  for (int i = 0; i < n; ++i) {
    const double t = 2 * M_PI * i / n;
    P.row(i) << a * std::cos(t), b * std::sin(t), 0.0;
  }
  return P;
}

Points torus_knot(int n, int p, int q, double R, double r) {
  Points P(n, 3);
  for (int i = 0; i < n; ++i) {
    const double s = 2.0 * M_PI * i / n;
    const double rr = R + r * std::cos(q * s);
    P.row(i) << rr * std::cos(p * s), rr * std::sin(p * s), r * std::sin(q * s);
  }
  return P;
}

Points rigid_copy(const Points& P, const Mat3& R, const Vec3& t, int shift) {
  const auto n = P.rows();
  Points Q(n, 3);
  for (Eigen::Index i = 0; i < n; ++i)
    Q.row(i) = (R * P.row(((i + shift) % n + n) % n).transpose() + t).transpose();
  return Q;
}

Points mirror_x(const Points& P) {
  Points Q = P;
  Q.col(0) *= -1.0;
  return Q;
}

Mat3 random_rotation(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> N(0.0, 1.0);
  Eigen::Quaterniond q(N(rng), N(rng), N(rng), N(rng));
  q.normalize();
  return q.toRotationMatrix();
}

VecX fd_gradient(const std::function<double(const VecX&)>& f, const VecX& x, double h) {
  VecX g(x.size());
  VecX y = x;
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    const double xi = y(i);
    y(i) = xi + h;
    const double fp = f(y);
    y(i) = xi - h;
    const double fm = f(y);
    y(i) = xi;
    g(i) = (fp - fm) / (2.0 * h);
  }
  return g;
}

}  // namespace ek::fixtures
