#include "ek/rod/elastic_rod.hpp"

#include <cmath>
#include <string>

#include "ek/core/errors.hpp"
#include "ek/geometry/writhe.hpp"
#include "ek/rod/kernels.hpp"

namespace ek {

namespace {

VecX input_edge_lengths(const Points& P) {
  const int n = static_cast<int>(P.rows());
  VecX l(n);
  for (int j = 0; j < n; ++j) l(j) = (P.row((j + 1) % n) - P.row(j)).norm();
  return l;
}

/// A unit vector perpendicular to the unit vector t.
Vec3 perpendicular(const Vec3& t) {
  Eigen::Index k;
  t.cwiseAbs().minCoeff(&k);
  return t.cross(Vec3::Unit(k)).normalized();
}

/// d made exactly perpendicular to the unit t and normalised.
Vec3 orthonormalize(const Vec3& d, const Vec3& t) { return (d - t * t.dot(d)).normalized(); }

}  // namespace

ElasticRod::ElasticRod(const Points& positions, RodMaterial material, TwistModel model)
    : n_(static_cast<int>(positions.rows())), material_(material), model_(model) {
  require(n_ >= 3, "ElasticRod: a closed rod needs at least 3 vertices, got " + std::to_string(n_));
  init(positions, input_edge_lengths(positions));
}

ElasticRod::ElasticRod(const Points& positions, const VecX& rest_edge_lengths, RodMaterial material,
                       TwistModel model)
    : n_(static_cast<int>(positions.rows())), material_(material), model_(model) {
  init(positions, rest_edge_lengths);
}

void ElasticRod::init(const Points& positions, const VecX& rest) {
  require(n_ >= 3, "ElasticRod: a closed rod needs at least 3 vertices, got " + std::to_string(n_));
  require(rest.size() == n_, "ElasticRod: expected " + std::to_string(n_) + " rest edge lengths, got " +
                                 std::to_string(rest.size()));
  require(positions.allFinite(), "ElasticRod: positions must be finite");
  for (int j = 0; j < n_; ++j)
    require(std::isfinite(rest(j)) && rest(j) > 0.0,
            "ElasticRod: rest length of edge " + std::to_string(j) + " must be positive and finite");
  material_.validate();
  x_ = positions;
  theta_ = VecX::Zero(n_);
  rest_len_ = rest;
  rest_vor_.resize(n_);
  for (int i = 0; i < n_; ++i) rest_vor_(i) = 0.5 * (rest_len_((i + n_ - 1) % n_) + rest_len_(i));

  // Edges (without reference twists: there is no source frame yet).
  e_.resize(3, n_);
  t_.resize(3, n_);
  len_.resize(n_);
  for (int j = 0; j < n_; ++j) {
    e_.col(j) = (x_.row((j + 1) % n_) - x_.row(j)).transpose();
    len_(j) = e_.col(j).norm();
    require(len_(j) > 0.0, "ElasticRod: edge " + std::to_string(j) + " has zero length");
    t_.col(j) = e_.col(j) / len_(j);
  }
  // Space-parallel transport of a director along the curve from edge 0.
  src_t_ = t_;
  src_d_.resize(3, n_);
  src_d_.col(0) = perpendicular(t_.col(0));
  for (int j = 1; j < n_; ++j)
    src_d_.col(j) = orthonormalize(rod::parallel_transport(t_.col(j - 1), t_.col(j), src_d_.col(j - 1)), t_.col(j));
  src_m_ = VecX::Zero(n_);
  src_m_(0) = rod::signed_angle(rod::parallel_transport(t_.col(n_ - 1), t_.col(0), src_d_.col(n_ - 1)),
                                src_d_.col(0), t_.col(0));
  Theta_ = -src_m_.sum();
  update_geometry();
}

int ElasticRod::num_dofs() const {
  switch (model_) {
    case TwistModel::TwistFree:
      return 3 * n_;
    case TwistModel::FreeTheta:
      return 4 * n_ + 1;
    case TwistModel::FixedLink:
      return 4 * n_;
  }
  return 3 * n_;
}

VecX ElasticRod::dofs() const {
  VecX d(num_dofs());
  d.head(3 * n_) = as_vector(x_);
  if (has_theta()) d.segment(3 * n_, n_) = theta_;
  if (model_ == TwistModel::FreeTheta) d(Theta_index()) = Theta_;
  return d;
}

void ElasticRod::set_dofs(const VecX& d) {
  require(d.size() == num_dofs(), "ElasticRod::set_dofs: expected " + std::to_string(num_dofs()) +
                                      " dofs, got " + std::to_string(d.size()));
  as_vector(x_) = d.head(3 * n_);
  if (has_theta()) theta_ = d.segment(3 * n_, n_);
  if (model_ == TwistModel::FreeTheta) Theta_ = d(Theta_index());
  update_geometry();
}

void ElasticRod::update_geometry() {
  for (int j = 0; j < n_; ++j) {
    const int k = j + 1 == n_ ? 0 : j + 1;
    e_.col(j) = (x_.row(k) - x_.row(j)).transpose();
    len_(j) = e_.col(j).norm();
    t_.col(j) = e_.col(j) / len_(j);
  }
  if (has_theta()) {
    m_.resize(n_);
    for (int i = 0; i < n_; ++i) m_(i) = compute_reference_twist(i);
  }
}

double ElasticRod::compute_reference_twist(int i) const {
  const int a = i == 0 ? n_ - 1 : i - 1;
  return src_m_(i) + rod::reference_twist_change(src_t_.col(a), src_t_.col(i), e_.col(a), e_.col(i));
}

// ---------------------------------------------------------------------------
// Energy, gradient, Hessian

ElasticRod::Terms ElasticRod::selected_terms(EnergyTerm term) const {
  const bool all = term == EnergyTerm::All;
  return {all || term == EnergyTerm::Stretch, all || term == EnergyTerm::Bend,
          (all || term == EnergyTerm::Twist) && has_theta()};
}

double ElasticRod::energy(EnergyTerm term) const {
  const auto [stretch, bend, twist] = selected_terms(term);
  const double EA = material_.stretching_stiffness();
  const double EI = material_.bending_stiffness();
  const double GJ = material_.twisting_stiffness();
  double E = 0.0;
  for (int i = 0; i < n_; ++i) {
    const int a = i == 0 ? n_ - 1 : i - 1;
    if (stretch) E += rod::stretch_energy(e_.col(i), rest_len_(i), EA);
    if (bend) E += 0.5 * EI / rest_vor_(i) * rod::kb_squared(e_.col(a), e_.col(i));
    if (twist) {
      const double tau = twist_angle(i);
      E += 0.5 * GJ / rest_vor_(i) * tau * tau;
    }
  }
  return E;
}

VecX ElasticRod::gradient(EnergyTerm term) const {
  const auto [stretch, bend, twist] = selected_terms(term);
  const double EA = material_.stretching_stiffness();
  const double EI = material_.bending_stiffness();
  const double GJ = material_.twisting_stiffness();
  VecX g = VecX::Zero(num_dofs());
  for (int i = 0; i < n_; ++i) {
    const int a = i == 0 ? n_ - 1 : i - 1;
    const int c = i + 1 == n_ ? 0 : i + 1;
    if (stretch) {
      const Vec3 gs = rod::stretch_gradient(e_.col(i), rest_len_(i), EA);
      g.segment<3>(3 * i) -= gs;
      g.segment<3>(3 * c) += gs;
    }
    rod::Vec6 ge = rod::Vec6::Zero();
    if (bend) ge = (0.5 * EI / rest_vor_(i)) * rod::kb_squared_gradient(e_.col(a), e_.col(i));
    if (twist) {
      const double k = GJ / rest_vor_(i);
      const double kt = k * twist_angle(i);
      ge += kt * rod::reference_twist_change_gradient(src_t_.col(a), src_t_.col(i), e_.col(a), e_.col(i));
      g(theta_index(i)) += kt;
      g(theta_index(a)) -= kt;
      if (i == 0 && model_ == TwistModel::FreeTheta) g(Theta_index()) += kt;
    }
    if (bend || twist) {
      g.segment<3>(3 * a) -= ge.head<3>();
      g.segment<3>(3 * i) += ge.head<3>() - ge.tail<3>();
      g.segment<3>(3 * c) += ge.tail<3>();
    }
  }
  return g;
}

void ElasticRod::add_hessian(SparseAssembler& A, EnergyTerm term) const { add_hessian(A, term, HessianKind::Exact); }

void ElasticRod::add_hessian(SparseAssembler& A, EnergyTerm term, HessianKind kind) const {
  const bool project_stretch = kind == HessianKind::Projected;
  const auto [stretch, bend, twist] = selected_terms(term);
  const double EA = material_.stretching_stiffness();
  const double EI = material_.bending_stiffness();
  const double GJ = material_.twisting_stiffness();

  // Every term is a function of the edge vectors, so the position Hessian is
  // Dᵀ K D with e = D x and K block-tridiagonal (cyclic) in the edges:
  // Kd[j] = ∂²E/∂e_j², Ko[j] = ∂²E/∂e_j∂e_{j+1}. Each Kd[j] adds to the
  // vertex pairs (j, j), (j+1, j+1) with + and (j, j+1) with -, each Ko[j]
  // to (j, j+1), (j+1, j+2) with +, (j+1, j+1) with - (twice, with its
  // transpose) and (j, j+2) with -. Each global entry is then added once.
  using Blocks = std::vector<Mat3, Eigen::aligned_allocator<Mat3>>;
  Blocks Kd(static_cast<size_t>(n_)), Ko(static_cast<size_t>(n_));
  // Twist coupling: k ∂τ/∂x (9 per vertex, over x_{i-1}, x_i, x_{i+1}) and k = GJ / l̄_i^V.
  Eigen::Matrix<double, 9, Eigen::Dynamic> coupling;
  VecX kt;
  if (has_theta()) {
    coupling.setZero(9, n_);
    kt.setZero(n_);
  }
  for (int j = 0; j < n_; ++j) {
    if (stretch)
      Kd[static_cast<size_t>(j)] = project_stretch ? rod::stretch_hessian_projected(e_.col(j), rest_len_(j), EA)
                                                   : rod::stretch_hessian(e_.col(j), rest_len_(j), EA);
    else
      Kd[static_cast<size_t>(j)].setZero();
    Ko[static_cast<size_t>(j)].setZero();
  }
  for (int i = 0; i < n_; ++i) {
    const int a = i == 0 ? n_ - 1 : i - 1;
    Mat3& Kaa = Kd[static_cast<size_t>(a)];
    Mat3& Kbb = Kd[static_cast<size_t>(i)];
    Mat3& Kab = Ko[static_cast<size_t>(a)];
    if (bend) rod::add_kb_squared_hessian_blocks(e_.col(a), e_.col(i), 0.5 * EI / rest_vor_(i), Kaa, Kab, Kbb);
    if (twist) {
      const double k = GJ / rest_vor_(i);
      const double tau = twist_angle(i);
      rod::Vec6 gme;
      rod::Mat6 Hme;
      rod::reference_twist_change_derivatives(src_t_.col(a), src_t_.col(i), e_.col(a), e_.col(i), gme, Hme);
      rod::Mat6 He = (k * tau) * Hme;
      He.noalias() += k * gme * gme.transpose();
      Kaa += He.topLeftCorner<3, 3>();
      Kab += He.topRightCorner<3, 3>();
      Kbb += He.bottomRightCorner<3, 3>();
      coupling.col(i) = k * rod::to_vertices(gme);
      kt(i) = k;
    }
  }
  for (int v = 0; v < n_; ++v) {
    const int p = v == 0 ? n_ - 1 : v - 1;
    const int v1 = v + 1 == n_ ? 0 : v + 1;
    const int v2 = v1 + 1 == n_ ? 0 : v1 + 1;
    const Mat3& Kov = Ko[static_cast<size_t>(v)];
    const Mat3& Kop = Ko[static_cast<size_t>(p)];
    const Mat3 D = Kd[static_cast<size_t>(v)] + Kd[static_cast<size_t>(p)] - Kop - Kop.transpose();
    const Mat3 U1 = Kop - Kd[static_cast<size_t>(v)] + Kov;
    for (int r = 0; r < 3; ++r)
      for (int c = r; c < 3; ++c) A.add(3 * v + r, 3 * v + c, D(r, c));
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) A.add(3 * v + r, 3 * v1 + c, U1(r, c));
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) A.add(3 * v + r, 3 * v2 + c, -Kov(r, c));
  }
  if (!has_theta()) return;
  // τ_i = θ_i - θ_{i-1} + m_i (+ Θ at i = 0): ∂τ/∂θ_i = 1, ∂τ/∂θ_{i-1} = -1, ∂τ/∂Θ = 1.
  for (int i = 0; i < n_; ++i) {
    const int a = i == 0 ? n_ - 1 : i - 1;
    const int vert[3] = {a, i, i + 1 == n_ ? 0 : i + 1};
    const int ti = theta_index(i), ta = theta_index(a);
    const bool with_Theta = i == 0 && model_ == TwistModel::FreeTheta;
    for (int q = 0; q < 3; ++q)
      for (int r = 0; r < 3; ++r) {
        const int row = 3 * vert[q] + r;
        const double w = coupling(3 * q + r, i);
        A.add(row, ti, w);
        A.add(row, ta, -w);
        if (with_Theta) A.add(row, Theta_index(), w);
      }
    const double k = kt(i);
    A.add(ti, ti, k);
    A.add(ta, ta, k);
    A.add(ta, ti, -k);
    if (with_Theta) {
      A.add(Theta_index(), Theta_index(), k);
      A.add(ti, Theta_index(), k);
      A.add(ta, Theta_index(), -k);
    }
  }
}

Eigen::SparseMatrix<double> ElasticRod::hessian(EnergyTerm term) const {
  SparseAssembler A;
  A.begin(num_dofs());
  A.segment(0, hessian_structure());
  add_hessian(A, term);
  A.end();
  Eigen::SparseMatrix<double> full = A.matrix().selfadjointView<Eigen::Upper>();
  return full;
}

std::uint64_t ElasticRod::hessian_structure() const {
  // "ROD" tag, model and size: the pattern depends on nothing else.
  return (std::uint64_t{0x524F44} << 40) ^ (static_cast<std::uint64_t>(model_) << 32) ^
         static_cast<std::uint64_t>(n_);
}

// ---------------------------------------------------------------------------
// Frames, state

void ElasticRod::update_reference_frames() {
  // Branch reference for the new twists: the continuous holonomy values (the
  // cache m_ in the models with θ). The twist-free model does not use the
  // twists, so there the old source values serve (exact while no reference
  // twist changes by more than π in one step, Panetta's rule).
  const VecX holonomy = has_theta() ? m_ : src_m_;
  for (int j = 0; j < n_; ++j)
    src_d_.col(j) = orthonormalize(rod::parallel_transport(src_t_.col(j), t_.col(j), src_d_.col(j)), t_.col(j));
  src_t_ = t_;
  // Re-derive the twists from the transported directors (no drift between
  // directors and twists), on the 2π branch of the continuous holonomy value.
  for (int i = 0; i < n_; ++i) {
    const int a = i == 0 ? n_ - 1 : i - 1;
    const double direct = rod::signed_angle(rod::parallel_transport(t_.col(a), t_.col(i), src_d_.col(a)),
                                            src_d_.col(i), t_.col(i));
    src_m_(i) = direct + 2.0 * M_PI * std::round((holonomy(i) - direct) / (2.0 * M_PI));
  }
  if (has_theta()) m_ = src_m_;
}

ElasticRod::State ElasticRod::save() const {
  State s;
  s.x = x_;
  s.theta = theta_;
  s.Theta = Theta_;
  s.source_tangents = src_t_;
  s.source_directors = src_d_;
  s.source_twist = src_m_;
  return s;
}

void ElasticRod::restore(const State& s) {
  require(s.x.rows() == n_ && s.theta.size() == n_ && s.source_tangents.cols() == n_ &&
              s.source_directors.cols() == n_ && s.source_twist.size() == n_,
          "ElasticRod::restore: state of a different rod");
  x_ = s.x;
  theta_ = s.theta;
  Theta_ = s.Theta;
  src_t_ = s.source_tangents;
  src_d_ = s.source_directors;
  src_m_ = s.source_twist;
  update_geometry();
}

void ElasticRod::relax_twist() {
  if (!has_theta()) return;
  const double total = Theta_ + m_.sum();
  const double L = rest_vor_.sum();
  for (int i = 1; i < n_; ++i) {
    const double tau = model_ == TwistModel::FreeTheta ? 0.0 : total * rest_vor_(i) / L;
    theta_(i) = theta_(i - 1) + tau - m_(i);
  }
  if (model_ == TwistModel::FreeTheta) Theta_ = -(theta_(0) - theta_(n_ - 1) + m_(0));
}

// ---------------------------------------------------------------------------
// Twist, writhe, link

double ElasticRod::reference_twist(int i) const {
  require(i >= 0 && i < n_, "ElasticRod::reference_twist: vertex out of range");
  return has_theta() ? m_(i) : compute_reference_twist(i);
}

double ElasticRod::total_reference_twist() const {
  if (has_theta()) return m_.sum();
  double s = 0.0;
  for (int i = 0; i < n_; ++i) s += compute_reference_twist(i);
  return s;
}

double ElasticRod::twist_angle(int i) const {
  if (!has_theta()) return 0.0;
  const int a = i == 0 ? n_ - 1 : i - 1;
  return theta_(i) - theta_(a) + m_(i) + (i == 0 ? Theta_ : 0.0);
}

double ElasticRod::twist() const { return has_theta() ? (Theta_ + m_.sum()) / (2.0 * M_PI) : 0.0; }

double ElasticRod::writhe() const { return ek::writhe(x_); }

double ElasticRod::link() const { return twist() + writhe(); }

void ElasticRod::set_link(double Lk) {
  require(has_theta(), "ElasticRod::set_link: the twist-free model has no prescribed link (Lk = Wr)");
  require(std::isfinite(Lk), "ElasticRod::set_link: link must be finite");
  Theta_ = 2.0 * M_PI * (Lk - writhe()) - m_.sum();
}

double ElasticRod::theta_total() const { return has_theta() ? Theta_ : -total_reference_twist(); }

Vec3 ElasticRod::curvature_binormal(int i) const {
  require(i >= 0 && i < n_, "ElasticRod::curvature_binormal: vertex out of range");
  return rod::curvature_binormal(e_.col(i == 0 ? n_ - 1 : i - 1), e_.col(i));
}

Vec3 ElasticRod::reference_director(int j) const {
  require(j >= 0 && j < n_, "ElasticRod::reference_director: edge out of range");
  return orthonormalize(rod::parallel_transport(src_t_.col(j), t_.col(j), src_d_.col(j)), t_.col(j));
}

Vec3 ElasticRod::material_director(int j) const {
  const Vec3 d = reference_director(j);
  const Vec3 t = t_.col(j);
  return std::cos(theta_(j)) * d + std::sin(theta_(j)) * t.cross(d);
}

std::string to_string(TwistModel model) {
  switch (model) {
    case TwistModel::TwistFree: return "twist-free";
    case TwistModel::FreeTheta: return "free-theta";
    case TwistModel::FixedLink: return "fixed-link";
  }
  return "?";
}

}  // namespace ek
