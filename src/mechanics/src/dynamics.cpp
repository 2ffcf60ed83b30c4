#include "ek/mechanics/dynamics.hpp"

#include <algorithm>
#include <cmath>
#include <ostream>
#include <sstream>

#include "ek/contact/barrier.hpp"
#include "ek/core/errors.hpp"
#include "ek/core/hash.hpp"
#include "ek/geometry/segment_distance.hpp"
#include "ek/knots/alexander.hpp"
#include "ek/optim/newton.hpp"
#include "ek/rod/elastic_rod.hpp"
#include "ek/solver/rod_terms.hpp"

namespace ek {

VecX lumped_masses(const VecX& rest, double density, double radius) {
  const Eigen::Index n = rest.size();
  require(n >= 3 && density > 0.0 && radius > 0.0, "lumped_masses: n >= 3, density and radius > 0");
  const double area = M_PI * radius * radius;
  VecX m(n);
  for (Eigen::Index i = 0; i < n; ++i) m(i) = density * area * 0.5 * (rest((i + n - 1) % n) + rest(i));
  return m;
}

// ---------------------------------------------------------------- inertia

InertiaTerm::InertiaTerm(VecX masses, double time_step, double damping, const Vec3& gravity)
    : m_(std::move(masses)), h_(time_step), gamma_(damping), g_(gravity) {
  require(m_.size() >= 3 && m_.minCoeff() > 0.0, "InertiaTerm: positive masses");
  require(h_ > 0.0 && gamma_ >= 0.0, "InertiaTerm: h > 0, damping >= 0");
  x_ = start_ = target_ = VecX::Zero(3 * m_.size());
}

void InertiaTerm::start_step(const Points& x, const Points& v) {
  require(x.rows() == m_.size() && v.rows() == m_.size(), "InertiaTerm::start_step: n by 3 positions and velocities");
  start_ = as_vector(x);
  target_ = start_ + h_ * as_vector(v);
  for (Eigen::Index i = 0; i < m_.size(); ++i) target_.segment<3>(3 * i) += h_ * h_ * g_;
  x_ = start_;
}

void InertiaTerm::set_dofs(const VecX& x) { x_ = x.head(start_.size()); }

double InertiaTerm::energy() const {
  double e = 0.0;
  for (Eigen::Index i = 0; i < m_.size(); ++i) {
    const auto xi = x_.segment<3>(3 * i);
    e += m_(i) * ((xi - target_.segment<3>(3 * i)).squaredNorm() / (2 * h_ * h_) +
                  gamma_ * (xi - start_.segment<3>(3 * i)).squaredNorm() / (2 * h_));
  }
  return e;
}

void InertiaTerm::add_gradient(Eigen::Ref<VecX> g) const {
  for (Eigen::Index i = 0; i < m_.size(); ++i) {
    const auto xi = x_.segment<3>(3 * i);
    g.segment<3>(3 * i) += m_(i) * ((xi - target_.segment<3>(3 * i)) / (h_ * h_) +
                                    gamma_ * (xi - start_.segment<3>(3 * i)) / h_);
  }
}

void InertiaTerm::add_hessian(SparseAssembler& A, HessianKind) const {
  for (Eigen::Index i = 0; i < m_.size(); ++i) {
    const double d = m_(i) * (1.0 / (h_ * h_) + gamma_ / h_);
    for (int c = 0; c < 3; ++c) A.add(static_cast<int>(3 * i + c), static_cast<int>(3 * i + c), d);
  }
}

// ---------------------------------------------------------------- friction

std::vector<FrictionContact> self_friction_contacts(const ContactPotential& contact, const Points& x) {
  const double dhat = contact.options().dhat, omega = contact.options().stiffness;
  std::vector<FrictionContact> out;
  for (const ContactPair& p : contact.active_pairs()) {
    const Vec3 a0 = x.row(p.a0), a1 = x.row(p.a1), b0 = x.row(p.b0), b1 = x.row(p.b1);
    double s = 0.0, t = 0.0;
    const double d = std::sqrt(segment_segment_distance_squared(a0, a1, b0, b1, &s, &t));
    if (!(d > 0.0) || d >= dhat) continue;
    FrictionContact c;
    c.vertices = {p.a0, p.a1, p.b0, p.b1};
    c.weights = {1.0 - s, s, -(1.0 - t), -t};
    c.normal = ((1.0 - s) * a0 + s * a1 - (1.0 - t) * b0 - t * b1) / d;
    c.normal_force = omega * std::abs(barrier_first_derivative(d, dhat));
    out.push_back(c);
  }
  return out;
}

std::vector<FrictionContact> envelope_friction_contacts(const PlanaritySlab& slab, const Points& x) {
  const SlabOptions& o = slab.options();
  const double h = o.half_thickness, dhat = o.activation * h;
  std::vector<FrictionContact> out;
  for (Eigen::Index i = 0; i < x.rows(); ++i) {
    for (const double side : {1.0, -1.0}) {  // the plate z = +h, then z = −h
      const double d = h - side * x(i, 2);
      if (!(d > 0.0) || d >= dhat) continue;
      FrictionContact c;
      c.vertices = {static_cast<int>(i), -1, -1, -1};
      c.weights = {1.0, 0.0, 0.0, 0.0};
      c.normal = Vec3(0.0, 0.0, -side);
      c.normal_force = o.stiffness * std::abs(barrier_first_derivative(d, dhat));
      out.push_back(c);
    }
  }
  return out;
}

double friction_f0(double y, double eps) {
  if (y >= eps) return y;
  return y * y / eps - y * y * y / (3.0 * eps * eps) + eps / 3.0;
}

double friction_f1(double y, double eps) {
  if (y >= eps) return 1.0;
  return 2.0 * y / eps - y * y / (eps * eps);
}

FrictionTerm::FrictionTerm(double mu, double eps, const Points& start, std::vector<FrictionContact> contacts)
    : mu_(mu), eps_(eps), start_(as_vector(start)), x_(as_vector(start)), contacts_(std::move(contacts)) {
  require(mu_ >= 0.0 && eps_ > 0.0, "FrictionTerm: mu >= 0, eps > 0");
}

void FrictionTerm::set_dofs(const VecX& x) { x_ = x.head(start_.size()); }

Vec3 FrictionTerm::tangential(const FrictionContact& c) const {
  Vec3 rel = Vec3::Zero();
  for (int j = 0; j < 4; ++j)
    if (c.vertices[j] >= 0) rel += c.weights[j] * (x_.segment<3>(3 * c.vertices[j]) - start_.segment<3>(3 * c.vertices[j]));
  return rel - c.normal * c.normal.dot(rel);
}

double FrictionTerm::energy() const {
  double e = 0.0;
  for (const FrictionContact& c : contacts_) e += mu_ * c.normal_force * friction_f0(tangential(c).norm(), eps_);
  return e;
}

void FrictionTerm::add_gradient(Eigen::Ref<VecX> g) const {
  for (const FrictionContact& c : contacts_) {
    const Vec3 u = tangential(c);
    const double y = u.norm();
    if (y == 0.0) continue;
    const Vec3 force = mu_ * c.normal_force * friction_f1(y, eps_) / y * u;  // ∇_u D_k
    for (int j = 0; j < 4; ++j)
      if (c.vertices[j] >= 0) g.segment<3>(3 * c.vertices[j]) += c.weights[j] * force;
  }
}

std::uint64_t FrictionTerm::hessian_structure() const {
  std::uint64_t h = splitmix64(0xF41C + contacts_.size());
  for (const FrictionContact& c : contacts_)
    for (const int v : c.vertices) h = splitmix64(h ^ static_cast<std::uint64_t>(v + 1));
  return h;
}

void FrictionTerm::add_hessian(SparseAssembler& A, HessianKind) const {
  for (const FrictionContact& c : contacts_) {
    const Vec3 u = tangential(c);
    const double y = u.norm(), scale = mu_ * c.normal_force;
    // K = ∂²(μλ f₀(|u|))/∂u² = μλ [φ I + (φ'/y) u uᵀ], φ = f₁(y)/y
    Mat3 K;
    if (y < eps_)
      K = scale * ((2.0 / eps_ - y / (eps_ * eps_)) * Mat3::Identity() - u * u.transpose() / (eps_ * eps_ * std::max(y, 1e-300)));
    else
      K = scale / y * (Mat3::Identity() - u * u.transpose() / (y * y));
    if (y == 0.0) K = scale * 2.0 / eps_ * Mat3::Identity();
    const Mat3 P = Mat3::Identity() - c.normal * c.normal.transpose();
    const Mat3 PKP = P * K * P;
    Eigen::Matrix<double, 12, 12> H = Eigen::Matrix<double, 12, 12>::Zero();
    std::array<int, 12> idx;
    for (int j = 0; j < 4; ++j) {
      for (int a = 0; a < 3; ++a) idx[3 * j + a] = c.vertices[j] >= 0 ? 3 * c.vertices[j] + a : -1;
      for (int l = 0; l < 4; ++l) H.block<3, 3>(3 * j, 3 * l) = c.weights[j] * c.weights[l] * PKP;
    }
    A.add_local(idx, H);
  }
}

// ---------------------------------------------------------------- options

void DynamicsOptions::validate() const {
  model.validate();
  require_input(!model.slab, "dynamics: the envelope replaces the relaxation's slab");
  require_input(std::isfinite(density) && density > 0.0, "dynamics: the density must be positive");
  require_input(std::isfinite(time_step) && time_step > 0.0, "dynamics: the time step must be positive");
  require_input(std::isfinite(duration) && duration > 0.0, "dynamics: the duration must be positive");
  require_input(gravity.allFinite(), "dynamics: the gravity must be finite");
  require_input(std::isfinite(damping) && damping >= 0.0, "dynamics: the damping must be >= 0");
  require_input(std::isfinite(friction) && friction >= 0.0, "dynamics: the friction coefficient must be >= 0");
  require_input(std::isfinite(friction_velocity) && friction_velocity > 0.0,
                "dynamics: the friction velocity must be positive");
  if (envelope) {
    envelope->validate();
    std::ostringstream t;
    t << 2.0 * model.material.radius;
    require_input(envelope->half_thickness >= model.material.radius,
                  "dynamics: the envelope's gap 2h must be at least the wire's thickness 2r = " + t.str());
  }
  require_input(std::isfinite(envelope_speed) && envelope_speed >= 0.0, "dynamics: the envelope speed must be >= 0");
  require_input(frame_every >= 1, "dynamics: frames every >= 1 steps");
  require_input(std::isfinite(rest_speed) && rest_speed >= 0.0, "dynamics: the rest speed must be >= 0");
  require_input(rest_steps >= 1, "dynamics: rest steps >= 1");
}

// ---------------------------------------------------------------- simulation

namespace {

/// The model of one run: the rod, its contact, the envelope and the solver.
struct Motion {
  const DynamicsOptions& o;
  ElasticRod rod;
  ContactPotential contact;
  std::optional<PlanaritySlab> envelope;
  InertiaTerm inertia;
  NewtonSolver solver;

  /// The envelope at time t: its plates moved apart by speed·t each, their
  /// barrier's reach (activation·H at t = 0) unchanged.
  void move_envelope(double t) {
    if (!o.envelope) return;
    SlabOptions s = *o.envelope;
    s.half_thickness += o.envelope_speed * t;
    s.activation *= o.envelope->half_thickness / s.half_thickness;
    envelope.emplace(s);
  }

  /// One backward Euler step from (x, v): the solver's report; the rod is left at the result.
  NewtonReport step(const Points& x, const Points& v, double t_next) {
    move_envelope(t_next);
    inertia.start_step(x, v);
    RodTerm rod_term(rod, o.model.max_tangent_rotation);
    ContactTerm contact_term(contact, x);  // builds the active set at x, which the friction reads
    std::vector<Potential*> terms{&inertia, &rod_term, &contact_term};
    std::optional<SlabTerm> slab_term;
    if (envelope) terms.push_back(&slab_term.emplace(*envelope, x));
    std::optional<FrictionTerm> friction;
    if (o.friction > 0.0) {
      std::vector<FrictionContact> contacts = self_friction_contacts(contact, x);
      if (envelope) {
        const std::vector<FrictionContact> plates = envelope_friction_contacts(*envelope, x);
        contacts.insert(contacts.end(), plates.begin(), plates.end());
      }
      terms.push_back(&friction.emplace(o.friction, o.friction_velocity * o.time_step, x, std::move(contacts)));
    }
    CompositeObjective phi({[this] { return rod.num_dofs(); }, [this] { return rod.dofs(); }, {}}, terms);

    return solver.minimize(phi);
  }

  /// The frame of positions x, velocities v at time t.
  DynamicsFrame frame(double t, const Points& x, const Points& v, const VecX& m, int iterations) {
    DynamicsFrame f;
    f.time = t;
    f.positions = x;
    contact.update(x);
    f.contacts = static_cast<int>(contact.num_active());
    f.elastic = rod.energy() + contact.energy(x) + (envelope ? envelope->energy(x) : 0.0);
    for (Eigen::Index i = 0; i < x.rows(); ++i) {
      const double s = v.row(i).norm();
      f.kinetic += 0.5 * m(i) * s * s;
      f.gravity -= m(i) * o.gravity.dot(x.row(i).transpose());
      f.max_speed = std::max(f.max_speed, s);
    }
    f.newton_iterations = iterations;
    return f;
  }
};

}  // namespace

std::string to_string(DynamicsStatus status) {
  switch (status) {
    case DynamicsStatus::Rest: return "rest";
    case DynamicsStatus::Duration: return "duration";
    case DynamicsStatus::StepFailed: return "step-failed";
    case DynamicsStatus::TopologyChanged: return "topology-changed";
  }
  return "unknown";
}

std::ostream& operator<<(std::ostream& out, DynamicsStatus status) { return out << to_string(status); }

DynamicsResult simulate(const Points& start, const VecX& rest, const DynamicsOptions& o, const Points& velocity) {
  o.validate();
  const int n = static_cast<int>(start.rows());
  require_input(n >= 4 && start.allFinite(), "dynamics: a closed curve needs at least 4 finite vertices");
  require_input(rest.size() == n && rest.allFinite() && rest.minCoeff() > 0.0,
                "dynamics: rest lengths must be n positive numbers");
  require_input(velocity.size() == 0 || (velocity.rows() == n && velocity.allFinite()),
                "dynamics: the start velocities must be n finite rows");
  const ResolvedModel model = resolve_model(o.model, rest.mean());
  NewtonOptions no = newton_options(o.model, model, cached_lambda_min(n, rest.mean(), o.model.material, model.model));
  no.remove_rigid_motions = false;  // inertia is not invariant under rigid motions
  const VecX masses = lumped_masses(rest, o.density, o.model.material.radius);
  Motion m{o,
           model_rod(start, rest, o.model, model),
           ContactPotential(CurveTopology::single(n), contact_options(model)),
           std::nullopt,
           InertiaTerm(masses, o.time_step, o.damping, o.gravity),
           NewtonSolver(no)};
  m.contact.update(start);
  require_input(m.contact.min_distance() > 0.0, "dynamics: the start touches itself");
  m.move_envelope(0.0);
  require_input(!m.envelope || m.envelope->inside(start), "dynamics: the start is not strictly inside the envelope");
  const AlexanderPolynomial a0 = input_alexander(start, "dynamics: the start");

  DynamicsResult r;
  r.model = model.model;
  Points x = start, v = velocity.size() ? velocity : Points(Points::Zero(n, 3));
  r.frames.push_back(m.frame(0.0, x, v, masses, 0));
  r.max_speed = r.frames.back().max_speed;
  r.max_kinetic = r.frames.back().kinetic;
  r.status = DynamicsStatus::Duration;
  int slow_steps = 0;
  bool framed = true;
  while (r.time < o.duration * (1.0 - 1e-12)) {
    const double t = std::min(r.time + o.time_step, o.duration);
    const ElasticRod::State before = m.rod.save();
    const NewtonReport rep = m.step(x, v, r.time + o.time_step);
    r.newton_iterations += rep.iterations;
    if (rep.status != SolverStatus::ConvergedStable && rep.status != SolverStatus::ConvergedUnstable) {
      m.rod.restore(before);
      r.status = DynamicsStatus::StepFailed;
      r.failed_status = rep.status;
      break;
    }
    const Points next = m.rod.positions();
    v = (next - x) / o.time_step;
    x = next;
    r.time = t;
    ++r.steps;
    framed = r.steps % o.frame_every == 0;
    const DynamicsFrame f = m.frame(r.time, x, v, masses, rep.iterations);
    r.max_speed = std::max(r.max_speed, f.max_speed);
    r.max_kinetic = std::max(r.max_kinetic, f.kinetic);
    slow_steps = f.max_speed < o.rest_speed ? slow_steps + 1 : 0;
    if (framed) r.frames.push_back(f);
    if (o.rest_speed > 0.0 && slow_steps >= o.rest_steps) {
      r.status = DynamicsStatus::Rest;
      r.rest_time = r.time;
      break;
    }
  }
  if (!framed) r.frames.push_back(m.frame(r.time, x, v, masses, 0));
  r.positions = x;
  r.velocities = v;
  r.theta = m.rod.thetas();
  r.link = m.rod.model() == TwistModel::TwistFree ? 0.0 : m.rod.link();
  r.alexander_preserved = alexander(x) == a0;
  if (!r.alexander_preserved) r.status = DynamicsStatus::TopologyChanged;
  return r;
}

}  // namespace ek
