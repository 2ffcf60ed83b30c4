// exp_periodic_links: the periodic braids' coils at prescribed links (a
// study beside Fig. 16; `make studies`, not part of `make figures`). The
// jumping-knot pipeline of paper Section 8.3, which the paper names for Fig.
// 16's states: each member's coil (experiments/common/periodic_family.hpp,
// n = 100·p, r = 0.2) relaxed with the full model at prescribed links
// Lk = Tw + Wr under the slab |z| < 2 d̂ and then released (ek::scan_links(),
// ek/mechanics/deploy.hpp), on a grid of links and bisected at the two ends of
// the interval where the flat coil is stable. Each 3D state's p-fold
// symmetry error; the p-fold symmetric 3D state (linked_symmetric():
// candidates averaged over their p periods and relaxed again at their
// links), with its crossing p-gons.
// The links are Lk_0 + t, Lk_0 the flat coil's twist-free link (its writhe,
// rounded: the braid's exponent sum, 0 for (σ1σ2⁻¹)^p and p for
// (σ1σ2⁻¹σ3)^p), t the twist added:
//   ci:      t = -8, 0, 1, 8 [turns], no bisection, 1 + 1 candidates symmetrized
//   default: t = -12, -11, ..., 12, 3 bisection steps per onset, 3 + 3 candidates
//   paper:   t = -14, -13.5, ..., 14, 4 bisection steps, 5 + 5 candidates
// Writes links.csv, curves/<family>_p<p>_lk<link>.obj (3D states of the scan),
// curves/<family>_p<p>_lk_symmetric.obj and summary.json (docs/results.md).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "ek/analysis/attributes.hpp"
#include "ek/analysis/symmetry.hpp"
#include "ek/core/parallel.hpp"
#include "ek/mechanics/deploy.hpp"
#include "ek/embedding/embedding.hpp"
#include "ek/geometry/curve_io.hpp"
#include "ek/geometry/polyline.hpp"
#include "ek/geometry/writhe.hpp"
#include "ek/solver/relax.hpp"
#include "experiment.hpp"
#include "periodic_links_summary.hpp"
#include "periodic_family.hpp"
#include "scales.hpp"

using namespace ek;
using namespace ek::exp;

namespace {

/// [edge lengths] crossing height of the coil of the link scan: inside the
/// slab |z| < 2 d̂ (as in exp_jumping_knots)
constexpr double kScanCrossingHeight = 0.35;
/// [1] a p-fold average relaxed again counts as p-fold symmetric at or below
/// this rotational_symmetry_error
constexpr double kSymmetricError = 1e-6;
/// [1] vertices per period of the word (every scale)
constexpr int kVerticesPerPeriod = 100;

std::array<double, 3> array3(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

struct ScanScale {
  std::vector<double> offsets;  ///< [turns] links relative to the coil's twist-free link
  int refinements = 0;          ///< bisection steps per onset
  int symmetrized = 0;          ///< the most symmetric 3D states averaged and relaxed again
};

ScanScale scan_scale(const Args& a) {
  ScanScale sc;
  if (a.scale == Scale::CI) {
    sc.offsets = {-8.0, 0.0, 1.0, 8.0};  // t = 1: 9_40's coil is flat and stable at t = 0 and deploys at 1
  } else {
    const double step = by_scale(a, 1.0, 1.0, 0.5), top = by_scale(a, 12.0, 12.0, 14.0);
    for (double t = -top; t <= top + 1e-9; t += step) sc.offsets.push_back(t);
  }
  sc.refinements = by_scale(a, 0, 3, 4);
  sc.symmetrized = by_scale(a, 1, 3, 5);
  return sc;
}

std::string link_tag(double lk) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", lk);
  return buf;
}

/// The p-fold symmetric 3D state of the scan. Candidates: the scan's `tries`
/// 3D states nearest to the twist-free link Lk_0 and its `tries` most p-fold
/// symmetric ones, each averaged over its p periods and relaxed again at its
/// link. Chosen: a converged-stable, 3D, p-fold symmetric one (error <=
/// kSymmetricError) nearest to Lk_0 (the least twist added; lower energy
/// breaks ties), else the candidate of smallest symmetry error. Null when the
/// scan found no 3D state or every average intersects itself.
std::optional<results::PeriodicLinkedSymmetric> linked_symmetric(const Args& a, const PeriodicBraid& m, const LinkScan& ls,
                                                                 const results::PeriodicLinkScan& out,
                                                                 const VecX& rest, int tries) {
  std::vector<size_t> three_d;
  for (size_t i = 0; i < out.runs.size(); ++i)
    if (out.runs[i].three_d) three_d.push_back(i);
  if (three_d.empty()) return std::nullopt;
  const auto twist = [&](size_t i) { return std::fabs(out.runs[i].link - out.center); };
  std::vector<size_t> nearest = three_d, order = three_d;
  std::stable_sort(nearest.begin(), nearest.end(), [&](size_t i, size_t j) { return twist(i) < twist(j); });
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t i, size_t j) { return out.runs[i].symmetry_error < out.runs[j].symmetry_error; });
  nearest.resize(std::min<size_t>(nearest.size(), static_cast<size_t>(tries)));
  order.resize(std::min<size_t>(order.size(), static_cast<size_t>(tries)));
  for (size_t i : nearest)
    if (std::find(order.begin(), order.end(), i) == order.end()) order.push_back(i);
  std::optional<results::PeriodicLinkedSymmetric> best;
  std::optional<Points> best_curve;
  for (size_t i : order) {
    const DeployRun& d = ls.runs[i];
    const SymmetryAxis sa = find_symmetry_axis(d.positions, m.p);
    RelaxOptions so;
    so.rest_lengths = rest;
    so.link = d.link;
    RelaxResult rs;
    try {
      rs = relax(symmetrize(d.positions, sa.center, sa.axis, m.p, m.strands), so);
    } catch (const InputError&) {
      continue;  // the average of a state far from p-fold symmetry may intersect itself: no candidate
    }
    const Points& S = rs.positions;
    const Vec3 cs = S.colwise().mean().transpose();
    const CrossingPolygons gs = crossing_polygons(S, cs, sa.axis, m.p, kCrossingGap);
    results::PeriodicLinkedSymmetric y;
    y.link = d.link;
    y.from_symmetry_error = out.runs[i].symmetry_error;
    y.status = to_string(rs.status());
    y.energy = rs.energy.total;
    y.energy_above = rs.energy.total - d.energy;
    y.threedim = threedim(S);
    y.writhe = rs.writhe;
    y.symmetry_error = rotational_symmetry_error(S, cs, sa.axis, m.p);
    y.axis = array3(sa.axis);
    y.center = array3(cs);
    y.crossings = gs.crossings;
    y.polygon_split = gs.by_radius ? "radius" : "height";
    y.polygon_error_deg = gs.error();
    y.relative_rotation_deg = gs.rotation;
    y.curve = "curves/" + m.family + "_p" + std::to_string(m.p) + "_lk_symmetric.obj";
    const auto good = [](const results::PeriodicLinkedSymmetric& z) {
      return z.status == to_string(RelaxStatus::ConvergedStable) && z.threedim >= kPlanarThreedim && z.symmetry_error <= kSymmetricError;
    };
    const auto better = [&](const results::PeriodicLinkedSymmetric& u, const results::PeriodicLinkedSymmetric& v) {
      if (good(u) != good(v)) return good(u);
      if (!good(u)) return u.symmetry_error < v.symmetry_error;
      const double tu = std::fabs(u.link - out.center), tv = std::fabs(v.link - out.center);
      return tu != tv ? tu < tv : u.energy < v.energy;
    };
    if (!best || better(y, *best)) {
      best = y;
      best_curve = S;
    }
  }
  if (best) write_curve(a.out + "/" + best->curve, *best_curve);
  return best;
}

/// The coil at prescribed links under the slab, released (ek::scan_links()).
results::PeriodicLinkScan link_scan(const Args& a, const PeriodicBraid& m, int n) {
  EmbeddingOptions eo = multicovered_circle(n, m.strands);
  eo.crossing_height = kScanCrossingHeight;
  const Points coil = embed_braid(m.word(), eo).points;
  const ScanScale sc = scan_scale(a);
  DeployOptions dop;
  dop.threedim_threshold = kPlanarThreedim;
  dop.relax.rest_lengths = edge_lengths(coil);
  LinkScanOptions lso;
  lso.center = std::round(writhe(coil));  // the twist-free link of the flat coil (its exponent sum)
  for (double t : sc.offsets) lso.grid.push_back(lso.center + t);
  lso.refinements = sc.refinements;
  const LinkScan ls = scan_links(coil, lso, dop);
  results::PeriodicLinkScan out;
  out.center = lso.center;
  out.grid = lso.grid;
  out.refinements = sc.refinements;
  out.slab_half_thickness = 2.0 * 2.0 * dop.relax.material.radius;  // deploy.hpp's default: 2 d̂
  out.buckling_writhe = dop.buckling_writhe;
  out.flat_low = ls.flat_low;
  out.flat_high = ls.flat_high;
  out.buckled_below = ls.buckled_below;
  out.buckled_above = ls.buckled_above;
  out.three_d_below = ls.three_d_below;
  out.three_d_above = ls.three_d_above;
  const std::string stem = "curves/" + m.family + "_p" + std::to_string(m.p) + "_lk";
  for (const DeployRun& d : ls.runs) {
    results::PeriodicLinkRun r{d.link, to_string(d.flat_status), d.flat_energy, d.flat_writhe, to_string(d.status), d.energy,
                               d.threedim, d.writhe, d.link_error, d.buckled, d.three_d,
                               find_symmetry_axis(d.positions, m.p).error, std::nullopt};
    if (d.three_d) {
      r.curve = stem + link_tag(d.link) + ".obj";
      write_curve(a.out + "/" + *r.curve, d.positions);
    }
    out.runs.push_back(r);
  }
  out.symmetric = linked_symmetric(a, m, ls, out, *dop.relax.rest_lengths, sc.symmetrized);
  std::ostringstream line;
  line << "exp_periodic_links: " << m.label() << " (Lk_0 " << out.center << "):";
  for (const auto& r : out.runs)
    line << " " << r.link << "(" << (r.three_d ? "3D " : r.buckled ? "buckled " : "") << r.status << " Wr " << r.writhe
         << " td " << r.threedim << " E " << r.energy << ")";
  if (out.symmetric)
    line << "; symmetric 3D state at Lk " << out.symmetric->link << " " << out.symmetric->status << ", 3D-ness "
         << out.symmetric->threedim << ", symmetry error " << out.symmetric->symmetry_error << ", p-gon error "
         << out.symmetric->polygon_error_deg << " deg, rotation " << out.symmetric->relative_rotation_deg << " deg";
  std::cout << line.str() << "\n" << std::flush;
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  return run_experiment(argc, argv, "exp_periodic_links", "Periodic braids' coils at prescribed links.",
                        [](const Args& a) {
    std::vector<std::string> skipped;
    const std::vector<PeriodicBraid> members = periodic_family(skipped);
    double edges = 0;
    for (const auto& m : members) edges += kVerticesPerPeriod * m.p;
    const ScanScale sc = scan_scale(a);
    const double runs = static_cast<double>(sc.offsets.size() + 2 * sc.refinements + sc.symmetrized);
    announce(a, "exp_periodic_links",
             std::to_string(members.size()) + " periodic braids, links " + std::to_string(sc.offsets.size()) +
                 " + 2·" + std::to_string(sc.refinements) + " bisections each",
             edges / 400.0 * 4.0 * runs * kSecondsPerRelaxation / a.jobs);
    std::filesystem::create_directories(a.out + "/curves");
    results::PeriodicLinksSummary sum;
    sum.scale = a.scale_name;
    sum.crossing_gap = kCrossingGap;
    sum.radius = RelaxOptions().material.radius;
    sum.threedim_threshold = kPlanarThreedim;
    sum.members.resize(members.size());
    parallel_for(members.size(), a.jobs, [&](size_t q) {
      const PeriodicBraid& m = members[q];
      results::PeriodicLinksMember& o = sum.members[q];
      o.family = m.family;
      o.p = m.p;
      if (!m.table_name.empty()) o.knot = m.table_name;
      o.expected_rotation_deg = m.expected_rotation_deg();
      o.link_scan = link_scan(a, m, kVerticesPerPeriod * m.p);
    });
    Csv links(a.out + "/links.csv", {"family", "p", "link", "flat_status", "flat_energy", "flat_writhe", "status",
                                     "energy", "threedim", "writhe", "buckled", "three_d", "symmetry_error", "curve"});
    for (const auto& o : sum.members)
      for (const auto& r : o.link_scan.runs)
        links.row({o.family, std::to_string(o.p), Csv::num(r.link), r.flat_status, Csv::num(r.flat_energy),
                   Csv::num(r.flat_writhe), r.status, Csv::num(r.energy), Csv::num(r.threedim), Csv::num(r.writhe),
                   Csv::flag(r.buckled), Csv::flag(r.three_d), Csv::num(r.symmetry_error), r.curve.value_or("")});
    links.commit();
    write_summary(a, sum);
  });
}
