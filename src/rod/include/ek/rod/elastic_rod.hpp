#pragma once
/// \file
/// Discrete elastic rod for closed curves: stretching, bending and twisting
/// with exact gradient and sparse Hessian, and the link Lk = Tw + Wr of the
/// framed curve (paper Section 6 and Appendix C; Bergou et al.\ 2008 and 2010).
///
/// Discretisation. Vertices x_0 .. x_{n-1} (n >= 3); edge j is
/// e_j = x_{j+1} - x_j (indices mod n), with rest length l̄_j (the input's edge
/// lengths unless given) and unit tangent t_j. Vertex i joins edge i-1 to edge i;
/// its rest Voronoi length is l̄_i^V = (l̄_{i-1} + l̄_i)/2. Vertex 0 is the
/// closing vertex (edge n-1 to edge 0).
///
/// ~~~{.unparsed}
///   E_stretch = Σ_j EA/2 (|e_j|/l̄_j - 1)² l̄_j
///   E_bend    = Σ_i EI/2 |(κb)_i|² / l̄_i^V,   (κb)_i = 2 e_{i-1}×e_i / (|e_{i-1}||e_i| + e_{i-1}·e_i)
///   E_twist   = Σ_i GJ/2 τ_i² / l̄_i^V,        τ_i = θ_i - θ_{i-1} + m_i + [i = 0] Θ
/// ~~~
///
/// Bending is the material-frame energy of Bergou et al. 2008 (eq. 5, per-edge
/// material curvatures ω_i^j, j ∈ {i-1, i}, averaged over the two edges):
/// for an isotropic cross-section and a straight rest shape |ω_i^j|² = |(κb)_i|²
/// for both edges, so it equals the form above exactly and does not depend on
/// the material angles θ. (The averaged-curvature variant of Bergou et al.
/// 2010 would add a factor cos²(τ_i/2), which agrees with it at relaxed twist.)
/// The coupling between positions and twist is through the reference twist m_i.
///
/// Frames. Each edge j carries a reference director d_j ⟂ t_j obtained by
/// time-parallel transport of a stored source director u_j from the source
/// tangent s_j: d_j = P(s_j → t_j) u_j; the material director is
/// d1_j = cos θ_j d_j + sin θ_j t_j × d_j. The reference twist m_i is the signed
/// angle about t_i from P(t_{i-1} → t_i) d_{i-1} to d_i. It is evaluated from the
/// source value by the exact holonomy formula m_i = m_i^src + Δm(s_{i-1}, s_i,
/// e_{i-1}, e_i) (kernels.hpp), continuous in time: it never jumps by 2π, and
/// its gradient and Hessian are exact also away from the source configuration.
/// update_reference_frames() makes the current frames the new source (call it
/// after each accepted step). At construction the frames are space-parallel
/// transported along the curve from edge 0 (m_i = 0 for i ≥ 1, m_0 is the
/// closing angle in (-π, π]), θ = 0 and Θ = -Σ m_i: the twist-free framing.
///
/// Twist, writhe, link (Appendix C, eq. 6): Tw = (Θ + Σ_i m_i)/(2π) (the θ
/// telescope away), Wr = ek::writhe(x), Lk = Tw + Wr. With Θ held fixed, Lk is
/// invariant under deformation without strand passage (Călugăreanu; the total
/// reference twist changes by exactly -2π ΔWr).
///
/// Degrees of freedom: [x (3n, vertex-major x0 y0 z0 x1 ...) | θ (n) | Θ],
/// the θ block in FreeTheta and FixedLink, Θ in FreeTheta only.
///
/// Zero modes of the Hessian at an equilibrium (with the source frames at the
/// current configuration): the three translations; the three rotations, which
/// in the models with θ are (ẋ_i = ω × x_i, θ̇_j = ω·t_j) because the reference
/// frames follow by parallel transport (no spin about the tangent) while the
/// material frames must rotate rigidly; and, with θ, the uniform shift of all
/// θ_j (isotropic cross-section). Translations and the θ shift are exact null
/// vectors everywhere; away from equilibria the rotations are soft modes.
///
/// Units: [length] from the positions, stiffnesses from RodMaterial, energies
/// in [energy] = [pressure]·[length]³, θ and Θ in radians.
#include <Eigen/SparseCore>
#include <cstdint>
#include <vector>

#include "ek/core/hessian_kind.hpp"
#include "ek/core/sparse_assembler.hpp"
#include "ek/geometry/types.hpp"
#include "ek/rod/material.hpp"

namespace ek {

/// Which unknowns describe the rod.
enum class TwistModel {
  /// Centerline only (3n dofs). With Θ free and an isotropic cross-section the
  /// twist relaxes to zero, so equilibria need only stretching and bending:
  /// the fast path for the paper's data set. Tw = 0, Lk = Wr.
  TwistFree,
  /// Positions, θ_j and Θ (4n + 1 dofs): the full model with Θ free.
  FreeTheta,
  /// Positions and θ_j (4n dofs); Θ is held fixed (set_link), so the link
  /// Lk = Tw + Wr is prescribed and preserved.
  FixedLink,
};
std::string to_string(TwistModel model);  ///< "twist-free", "free-theta", "fixed-link"

/// Energy terms, each evaluable on its own: Stretch, Bend, Twist (0 in
/// TwistFree) or All, their sum.
enum class EnergyTerm { Stretch, Bend, Twist, All };

/// A closed discrete elastic rod (see the file comment for the formulas).
class ElasticRod {
 public:
  /// Closed rod through the rows of `positions` (n by 3, n >= 3); rest edge
  /// lengths are the input's edge lengths; straight rest shape.
  ElasticRod(const Points& positions, RodMaterial material, TwistModel model);
  /// As above with given rest edge lengths (n, all > 0; rest_edge_lengths(j)
  /// belongs to edge j from vertex j to vertex j+1).
  ElasticRod(const Points& positions, const VecX& rest_edge_lengths, RodMaterial material, TwistModel model);

  int num_vertices() const { return n_; }                    ///< n, the number of vertices (= edges).
  int num_dofs() const;                                      ///< 3n (TwistFree), 4n + 1 (FreeTheta) or 4n (FixedLink).
  TwistModel model() const { return model_; }                ///< The unknowns of the rod (TwistModel).
  const RodMaterial& material() const { return material_; }  ///< E, ν and r of the wire.

  /// [x (3n) | θ (n) | Θ (FreeTheta only)].
  VecX dofs() const;
  /// Sets positions (and θ, Θ); size num_dofs(). The source frames are not
  /// changed: reference directors and twists follow by time-parallel transport
  /// from the source (see update_reference_frames()).
  void set_dofs(const VecX& x);
  const Points& positions() const { return x_; }  ///< Current vertices x_i (n by 3).
  /// Material angles θ_j (n; zero in TwistFree).
  const VecX& thetas() const { return theta_; }

  /// Energy of one term or of all (TwistFree: the twist term is 0).
  double energy(EnergyTerm term = EnergyTerm::All) const;
  /// Exact gradient, size num_dofs().
  VecX gradient(EnergyTerm term = EnergyTerm::All) const;
  /// Adds the exact Hessian (upper triangle) at dofs 0 .. num_dofs()-1. The
  /// sequence of positions added is the same for every call and every term
  /// (entries a term does not touch are added as zeros), so a SparseAssembler
  /// segment with hessian_structure() replays it.
  void add_hessian(SparseAssembler& A, EnergyTerm term = EnergyTerm::All) const;
  /// As above; with HessianKind::Projected the stretching term of every compressed
  /// edge uses rod::stretch_hessian_projected() (its negative transverse
  /// eigenvalues EA/l̄ (1 - l̄/|e|) < 0 clamped to 0), a positive
  /// semidefinite modification for descent directions far from equilibrium;
  /// bending and twisting stay exact. Same sequence of positions.
  void add_hessian(SparseAssembler& A, EnergyTerm term, HessianKind kind) const;
  /// Convenience: the full symmetric Hessian.
  Eigen::SparseMatrix<double> hessian(EnergyTerm term = EnergyTerm::All) const;
  /// Identifier of the Hessian's sparsity pattern (depends on n and the model only).
  std::uint64_t hessian_structure() const;

  /// Time-parallel transport of the reference frames to the current edges:
  /// the current reference directors, tangents and reference twists become the
  /// source. Call after each accepted step (keep steps between calls small
  /// compared with π in tangent rotation).
  void update_reference_frames();

  /// Complete state (positions, angles, source frames), for a line search:
  /// save() before trial points, restore() to go back (conventions 8).
  struct State {
    Points x;            ///< Vertices (n by 3).
    VecX theta;          ///< Material angles θ_j (n) [rad].
    double Theta = 0.0;  ///< Injected twist Θ [rad].
    ///@{
    /// Source tangents s_j and source directors u_j of the parallel transport
    /// (3 by n, column j for edge j).
    Eigen::Matrix3Xd source_tangents, source_directors;
    ///@}
    VecX source_twist;                                   ///< n, m_i at the source
  };
  State save() const;                ///< The complete state, to return to with restore().
  /// Returns to a state that save() took; std::invalid_argument for a state of another size.
  void restore(const State& state);

  /// Sets θ (and Θ in FreeTheta) to the minimiser of the twisting energy for
  /// the current positions: in FreeTheta every τ_i = 0; in FixedLink the fixed
  /// total Θ + Σm is spread as τ_i ∝ l̄_i^V (uniform twist density). θ_0 is
  /// kept. No-op in TwistFree. Bending and stretching do not depend on θ.
  void relax_twist();

  /// Reference twist m_i at vertex i [rad].
  double reference_twist(int i) const;
  /// Sum of the reference twists Σ_i m_i [rad].
  double total_reference_twist() const;
  /// Twist angle τ_i = θ_i - θ_{i-1} + m_i (+ Θ at i = 0) [rad]; 0 in TwistFree.
  double twist_angle(int i) const;
  /// Tw = (Θ + Σ_i m_i) / (2π) (Appendix C, eq.\ 6); 0 in TwistFree.
  double twist() const;
  /// Wr = ek::writhe(positions) (Appendix C, eq.\ 5). O(n²).
  double writhe() const;
  /// Lk = Tw + Wr.
  double link() const;
  /// Sets Θ so that Tw + Wr = Lk (FreeTheta and FixedLink; θ unchanged, so the
  /// new twist sits at vertex 0 until relax_twist() or a solve spreads it).
  /// Throws std::invalid_argument in TwistFree.
  void set_link(double Lk);
  /// Θ [rad]; in TwistFree the Θ of the relaxed framing, -Σ m_i.
  double theta_total() const;

  /// (κb)_i at vertex i (dimensionless, |κb| = 2 tan(φ_i/2)); the pointwise
  /// curvature is |(κb)_i| / l̄_i^V.
  Vec3 curvature_binormal(int i) const;
  /// Current reference director d_j of edge j (unit, ⟂ t_j).
  Vec3 reference_director(int j) const;
  /// Current material director d1_j = cos θ_j d_j + sin θ_j t_j × d_j.
  Vec3 material_director(int j) const;

  /// Rest edge lengths l̄_j (n).
  const VecX& rest_edge_lengths() const { return rest_len_; }
  /// Rest Voronoi lengths l̄_i^V = (l̄_{i-1} + l̄_i)/2 (n).
  const VecX& rest_voronoi_lengths() const { return rest_vor_; }

 private:
  int n_;
  RodMaterial material_;
  TwistModel model_;
  Points x_;
  VecX theta_;
  double Theta_ = 0.0;
  VecX rest_len_, rest_vor_;
  // source frames
  Eigen::Matrix3Xd src_t_, src_d_;  // 3 by n
  VecX src_m_;
  // caches of the current configuration: edges, lengths, tangents, and the
  // reference twists (kept up to date only when the model has θ)
  Eigen::Matrix3Xd e_, t_;  // 3 by n
  VecX len_;
  VecX m_;

  bool has_theta() const { return model_ != TwistModel::TwistFree; }
  struct Terms {
    bool stretch, bend, twist;  // twist only when the model has material angles
  };
  Terms selected_terms(EnergyTerm term) const;
  int theta_index(int j) const { return 3 * n_ + j; }
  int Theta_index() const { return 4 * n_; }
  void init(const Points& positions, const VecX& rest_edge_lengths);
  void update_geometry();
  double compute_reference_twist(int i) const;
};

/// Smallest nonzero eigenvalue of the rod Hessian in a straight configuration
/// (the solver's shift λ_min, paper Section 6, "Numerical Solver").
///
/// "Straight" is the closed rod cut open at one vertex and laid straight: an
/// open rod of n edges of rest length h (n + 1 vertices, n - 1 interior
/// vertices carrying bending and twist), at rest, same material. Its Hessian
/// decouples into
///  - axial stretching: EA/h times the Laplacian of the path with n + 1 nodes,
///    λ = 4 (EA/h) sin²(π/(2(n+1)));
///  - bending, twice (two transverse directions): EI/h³ Dᵀ D with D the
///    (n-1) by (n+1) second-difference matrix; its smallest nonzero eigenvalue
///    is the smallest eigenvalue of D Dᵀ (Spectra, shift-invert);
///  - twisting (FreeTheta, FixedLink): GJ/h times the Laplacian of the path
///    with n nodes (the edge angles), λ = 4 (GJ/h) sin²(π/(2n)).
/// The result is the smallest of these (bending, for slender rods).
double straight_rod_min_eigenvalue(int n, double edge_length, const RodMaterial& material, TwistModel model);

}  // namespace ek
