// exp_periodic_braids: periodic braids (paper Section 8.4, Fig. 16).
// (σ1 σ2⁻¹)^p on 3 strands (p = 2, 4, 5, 7, 8; p = 2 is 4_1, 4 is 8_18, 5 is
// 10_123) and (σ1 σ2⁻¹ σ3)^p on 4 strands (p = 3, 5, 7; p = 3 is 9_40), the
// values of p whose closure is a knot. Each starts as the multi-covered
// circle of its braid with wire length ∝ p (n = 100·p unit edges, every scale)
// and the data set's thickness (r = 0.2), and is relaxed.
// Measured per member: the Alexander polynomial (against the table where the
// knot is tabulated); p-fold rotational symmetry about a principal axis:
//   error = mean over vertices of the distance from the rotated vertex to the
//   curve, divided by the radius of gyration (the axis: the direction within
//   0.1 rad of a principal axis, on a 0.01 rad grid, with the smallest error);
//   control_error = the same for a (p+1)-fold rotation about that axis (what
//   a state without the p-fold symmetry scores);
// and the braid's crossings seen along that axis: the crossings of the
// projection whose two strands pass within kCrossingGap of each other along
// the axis (where the strands cross they touch, ~d̂ apart; a 3D state's
// projection also shows strands that pass each other far apart, e.g. 4_1's
// 4 braid crossings at gap 0.46-0.48 and 4 more at gap ~31 near the axis),
// split into the two halves by height: each half's angles against a regular
// p-gon (largest deviation, in degrees) and the rotation between the two
// p-gons (expected 0 for odd p and π/p for even p).
// The p-fold symmetric equilibrium next to each state: its p-fold average
// (symmetrize()) relaxed again with the same rest lengths; the same measures
// on it ("symmetric" in summary.json). The relaxation from the coil can stop
// in a slightly asymmetric neighbour (measured: 4_1's symmetric state is
// 1.1e-4 lower in energy, 9_40's 7e-6 higher; both converged-stable).
// A tall start per member ("tall_start" in summary.json): the same braid with
// its strands stacked along the axis (EmbeddingOptions::braid_tilt = π/2,
// spacing kTallSpacing/s of the coil radius; an isotopy of the coil, 3D-ness
// 0.2-0.4), relaxed; its energy and 3D-ness against the coil's.
// Writes periodic.csv, curves/<family>_p<p>[_symmetric].obj and summary.json.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <tuple>

#include "ek/analysis/attributes.hpp"
#include "ek/embedding/embedding.hpp"
#include "ek/geometry/curve_io.hpp"
#include "ek/geometry/polyline.hpp"
#include "ek/geometry/segment_distance.hpp"
#include "ek/knots/alexander.hpp"
#include "ek/solver/relax.hpp"
#include "experiment.hpp"
#include "scales.hpp"

using namespace ek;
using namespace ek::exp;

namespace {

double symmetry_error(const Points& P, const Vec3& c, const Vec3& axis, int p) {
  const Eigen::AngleAxisd R(2.0 * M_PI / p, axis);
  const int n = static_cast<int>(P.rows());
  double rg = 0.0;
  for (int i = 0; i < n; ++i) rg += (P.row(i).transpose() - c).squaredNorm();
  rg = std::sqrt(rg / n);
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    const Vec3 q = c + R * (P.row(i).transpose() - c);
    double best = 1e300;
    for (int j = 0; j < n; ++j)
      best = std::min(best, point_segment_distance_squared(q, P.row(j).transpose(), P.row((j + 1) % n).transpose()));
    sum += std::sqrt(best);
  }
  return sum / n / rg;
}

double wrap(double a, double period) {  // to [-period/2, period/2)
  a = std::fmod(a, period);
  if (a < -period / 2) a += period;
  if (a >= period / 2) a -= period;
  return a;
}

struct Gon {
  int count = 0;
  double phase = 0.0;      // [rad] of the p-gon
  double max_error = 0.0;  // [deg] largest deviation of a crossing from the nearest p-gon vertex
};

Gon fit_gon(const std::vector<double>& angles, int p) {
  Gon g;
  g.count = static_cast<int>(angles.size());
  if (angles.empty()) return g;
  double cs = 0.0, sn = 0.0;
  for (double a : angles) {
    cs += std::cos(p * a);
    sn += std::sin(p * a);
  }
  g.phase = std::atan2(sn, cs) / p;
  for (double a : angles)
    g.max_error = std::max(g.max_error, std::fabs(wrap(a - g.phase, 2.0 * M_PI / p)) * 180.0 / M_PI);
  return g;
}

/// The two p-gons of a state's braid crossings seen along `axis` (see the file comment).
struct Polygons {
  size_t crossings = 0, projected = 0;
  bool by_radius = false;
  Gon top, bottom;
  double rotation = 0.0;  // [deg] between the two p-gons, in [0, 180/p]
  double error() const { return std::max(top.max_error, bottom.max_error); }
};

/// The p-fold average of P about `axis` through c. The closed s-strand braid
/// winds s times about its axis, so moving k·n/p vertices along the curve
/// (k periods of the braid word) turns by 2π·k·s/p: vertex i + k·n/p is
/// rotated back by that angle (k = 0..p-1), in whichever sense of rotation
/// moves P less. A p-fold symmetric start for the symmetric equilibrium
/// (n divisible by p).
Points symmetrize(const Points& P, const Vec3& c, const Vec3& axis, int p, int strands) {
  const int n = static_cast<int>(P.rows());
  require(n % p == 0, "symmetrize: n must be divisible by p");
  Points best;
  double best_move = 1e300;
  for (const double sense : {1.0, -1.0}) {
    Points Q = Points::Zero(n, 3);
    for (int k = 0; k < p; ++k) {
      const Eigen::AngleAxisd R(-sense * 2.0 * M_PI * k * strands / p, axis);
      for (int i = 0; i < n; ++i)
        Q.row(i) += (c + R * (P.row((i + k * n / p) % n).transpose() - c)).transpose() / p;
    }
    const double move = (Q - P).rowwise().norm().maxCoeff();
    if (move < best_move) {
      best_move = move;
      best = Q;
    }
  }
  return best;
}

/// [length] the braid's crossings: strands at most this far apart along the
/// axis where their projections cross (2 d̂ of the data set's wire, d̂ = 0.4).
constexpr double kCrossingGap = 0.8;
/// [coil radius] total height of the tall start's strand stack (s - 1)/s of this
constexpr double kTallSpacing = 0.9;

Polygons measure_polygons(const Points& P, const Vec3& c, const Vec3& axis, int p, double max_gap) {
  Polygons out;
  Vec3 view = (axis + 1e-7 * Vec3(0.3, 0.7, 0.1)).normalized();
  bool generic = false;
  auto crossings = projection_crossings(P, view, &generic);
  for (int attempt = 1; !generic && attempt < 10; ++attempt) {
    view = (axis + 1e-5 * attempt * Vec3(0.3, -0.7, 0.2)).normalized();
    crossings = projection_crossings(P, view, &generic);
  }
  out.projected = crossings.size();
  // the braid's crossings: strands within max_gap along the axis
  crossings.erase(std::remove_if(crossings.begin(), crossings.end(),
                                 [&](const auto& x) { return std::fabs((x.over - x.under).dot(axis)) > max_gap; }),
                  crossings.end());
  out.crossings = crossings.size();
  // The two p-gons: the crossings split at the median height along the
  // axis (a 3D state: one p-gon at each end) or, when that fits worse, at
  // the median distance from the axis (a flat coil: inner and outer ring).
  const Vec3 u = axis.unitOrthogonal(), v = axis.cross(u);
  std::vector<Vec3> mids;  // each crossing's midpoint, relative to c
  for (const auto& x : crossings) mids.push_back(0.5 * (x.over + x.under) - c);
  auto split = [&](bool by_height) {
    std::vector<double> key;
    for (const Vec3& mid : mids) key.push_back(by_height ? mid.dot(axis) : (mid - mid.dot(axis) * axis).norm());
    std::vector<double> sorted = key;
    std::sort(sorted.begin(), sorted.end());
    const double median = sorted.empty() ? 0.0 : sorted[sorted.size() / 2];
    std::vector<double> hi, lo;
    for (size_t q = 0; q < mids.size(); ++q)
      (key[q] >= median ? hi : lo).push_back(std::atan2(mids[q].dot(v), mids[q].dot(u)));
    return std::make_pair(fit_gon(hi, p), fit_gon(lo, p));
  };
  std::tie(out.top, out.bottom) = split(true);
  const auto [rt, rb] = split(false);
  out.by_radius = std::max(rt.max_error, rb.max_error) < out.error();
  if (out.by_radius) {
    out.top = rt;
    out.bottom = rb;
  }
  out.rotation = std::fabs(wrap(out.top.phase - out.bottom.phase, 2.0 * M_PI / p)) * 180.0 / M_PI;
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  return run_experiment(argc, argv, "exp_periodic_braids", "Periodic braids of Fig. 16.", [](const Args& a) {
    struct Member {
      std::string family;
      int strands, p;
      std::vector<int> period;
      std::string table_name;
    };
    std::vector<Member> members;
    for (int p : {2, 4, 5, 7, 8})
      members.push_back({"s1s2i", 3, p, {1, -2}, p == 2 ? "4_1" : p == 4 ? "8_18" : p == 5 ? "10_123" : ""});
    for (int p : {3, 5, 7}) members.push_back({"s1s2is3", 4, p, {1, -2, 3}, p == 3 ? "9_40" : ""});
    const int per_p = 100;  // every scale: the same wire per period (n = 100·p unit edges)
    double total_edges = 0;
    for (const auto& m : members) total_edges += per_p * m.p;
    announce(a, "exp_periodic_braids", std::to_string(members.size()) + " periodic braids, n = " +
                                           std::to_string(per_p) + "·p",
             total_edges / 400.0 * 4.0 * kSecondsPerRelaxation);
    std::filesystem::create_directories(a.out + "/curves");
    Csv csv(a.out + "/periodic.csv",
            {"family", "strands", "p", "vertices", "knot", "status", "energy", "alexander_matches_table",
             "symmetry_error", "top_crossings", "bottom_crossings", "top_polygon_error_deg",
             "bottom_polygon_error_deg", "relative_rotation_deg", "expected_rotation_deg", "curve"});
    nlohmann::ordered_json j;
    j["scale"] = a.scale_name;
    j["members"] = nlohmann::ordered_json::array();
    for (const auto& m : members) {
      BraidWord w;
      w.strands = m.strands;
      for (int k = 0; k < m.p; ++k) w.letters.insert(w.letters.end(), m.period.begin(), m.period.end());
      require(closure_components(w) == 1, "periodic braid closure is not a knot");
      const int n = per_p * m.p;
      const EmbeddingOptions eo = multicovered_circle(n, m.strands);
      const Embedding emb = embed_braid(w, eo);
      const RelaxResult r = relax(emb.points);
      const Points& P = r.positions;
      std::string alex_ok = "-";
      if (!m.table_name.empty())
        alex_ok = (alexander(P) == alexander(*KnotTable::global().at(m.table_name).pd)) ? "1" : "0";
      // principal axes
      const Vec3 c = P.colwise().mean().transpose();
      Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
      for (int i = 0; i < n; ++i) cov += (P.row(i).transpose() - c) * (P.row(i) - c.transpose());
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cov);
      double best = 1e300;
      Vec3 axis = Vec3::UnitZ();
      // the axis: each principal axis, refined over tilts of up to ±0.1 rad
      // (principal axes of a nearly axisymmetric inertia are ill-conditioned)
      for (int k = 0; k < 3; ++k) {
        const Vec3 e0 = es.eigenvectors().col(k), e1 = e0.unitOrthogonal(), e2 = e0.cross(e1);
        for (int i = -10; i <= 10; ++i)
          for (int q = -10; q <= 10; ++q) {
            const Vec3 ax = (e0 + 0.01 * i * e1 + 0.01 * q * e2).normalized();
            const double err = symmetry_error(P, c, ax, m.p);
            if (err < best) {
              best = err;
              axis = ax;
            }
          }
      }
      const Polygons g = measure_polygons(P, c, axis, m.p, kCrossingGap);
      const Gon &gt = g.top, &gb = g.bottom;
      const double rot = g.rotation;
      // The p-fold symmetric equilibrium next to it: relax the p-fold average
      // (same rest lengths). Fig. 16's states are symmetric; the relaxation
      // from the coil may stop in a slightly asymmetric neighbour.
      RelaxOptions so;
      so.rest_lengths = edge_lengths(emb.points);
      const RelaxResult rs = relax(symmetrize(P, c, axis, m.p, m.strands), so);
      const Points& S = rs.positions;
      const Vec3 cs = S.colwise().mean().transpose();
      const double sym_error = symmetry_error(S, cs, axis, m.p);
      const Polygons gs = measure_polygons(S, cs, axis, m.p, kCrossingGap);
      const double expected = (m.p % 2 == 1) ? 0.0 : 180.0 / m.p;
      // A second, tall start: the same braid with its strands stacked along
      // the axis (cross-sections turned by 90°, an isotopy of the coil; a 3D
      // start), to see whether a 3D equilibrium is reached from there.
      EmbeddingOptions to = eo;
      to.braid_tilt = 0.5 * M_PI;
      to.strand_spacing = kTallSpacing / m.strands;
      const Embedding tall = embed_braid(w, to);
      const RelaxResult rt = relax(tall.points);
      const double tall_start_3d = threedim(tall.points), tall_end_3d = threedim(rt.positions);
      const std::string curve = "curves/" + m.family + "_p" + std::to_string(m.p) + ".obj";
      write_curve(a.out + "/" + curve, P);
      write_curve(a.out + "/curves/" + m.family + "_p" + std::to_string(m.p) + "_symmetric.obj", S);
      csv.row({m.family, std::to_string(m.strands), std::to_string(m.p), std::to_string(n),
               m.table_name.empty() ? "-" : m.table_name, r.status(), Csv::num(r.energy.total), alex_ok,
               Csv::num(best), std::to_string(gt.count), std::to_string(gb.count), Csv::num(gt.max_error),
               Csv::num(gb.max_error), Csv::num(rot), Csv::num(expected), curve});
      j["members"].push_back({{"family", m.family},
                              {"p", m.p},
                              {"knot", m.table_name},
                              {"status", r.status()},
                              {"energy", r.energy.total},
                              {"alexander_preserved", r.alexander_preserved},
                              {"alexander_matches_table", alex_ok},
                              {"threedim", threedim(P)},
                              {"symmetry_error", best},
                              {"control_error", symmetry_error(P, c, axis, m.p + 1)},
                              {"crossings", g.crossings},
                              {"projection_crossings", g.projected},
                              {"polygon_split", g.by_radius ? "radius" : "height"},
                              {"polygon_error_deg", g.error()},
                              {"relative_rotation_deg", rot},
                              {"expected_rotation_deg", expected},
                              {"symmetric",
                               {{"status", rs.status()},
                                {"energy", rs.energy.total},
                                {"energy_above", rs.energy.total - r.energy.total},
                                {"threedim", threedim(S)},
                                {"symmetry_error", sym_error},
                                {"crossings", gs.crossings},
                                {"polygon_split", gs.by_radius ? "radius" : "height"},
                                {"polygon_error_deg", gs.error()},
                                {"relative_rotation_deg", gs.rotation}}},
                              {"tall_start",
                               {{"start_threedim", tall_start_3d},
                                {"status", rt.status()},
                                {"energy", rt.energy.total},
                                {"energy_above", rt.energy.total - r.energy.total},
                                {"threedim", tall_end_3d}}}});
      std::cout << "exp_periodic_braids: " << m.family << " p=" << m.p << " " << r.status() << " symmetry error "
                << best << ", crossings " << gt.count << "+" << gb.count << ", rotation " << rot << " deg (expected "
                << expected << "); symmetric equilibrium " << rs.status() << " dE " << rs.energy.total - r.energy.total
                << ", symmetry error " << sym_error << ", p-gon error " << gs.error() << " deg, rotation "
                << gs.rotation << " deg; tall start (3D-ness " << tall_start_3d << ") " << rt.status()
                << " dE " << rt.energy.total - r.energy.total << ", 3D-ness " << tall_end_3d << std::endl;
    }
    csv.commit();
    write_json(a.out + "/summary.json", j);
  });
}
