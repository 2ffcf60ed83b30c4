// exp_periodic_braids: periodic braids (paper Section 8.4, Fig. 16).
// (σ1 σ2⁻¹)^p on 3 strands (p = 2, 4, 5, 7, 8; p = 2 is 4_1, 4 is 8_18, 5 is
// 10_123) and (σ1 σ2⁻¹ σ3)^p on 4 strands (p = 3, 5, 7; p = 3 is 9_40), the
// values of p whose closure is a knot. Each starts as the multi-covered
// circle of its braid with wire length ∝ p (n = 100·p unit edges, every scale)
// and the data set's thickness (r = 0.2), and is relaxed.
// Measured per member (the analysis is ek/analysis/symmetry.hpp): the
// Alexander polynomial (against the table where the knot is tabulated);
// p-fold rotational symmetry about a principal axis:
//   error = mean over vertices of the distance from the rotated vertex to the
//   curve, divided by the radius of gyration (the axis: the direction within
//   0.1 rad of a principal axis, on a 0.01 rad grid, with the smallest error;
//   written to summary.json, where Fig. 16 reads it);
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
// (ek::symmetrize()) relaxed again with the same rest lengths; the same measures
// on it ("symmetric" in summary.json). The relaxation from the coil can stop
// in a slightly asymmetric neighbour (measured: 4_1's symmetric state is
// 1.1e-4 lower in energy, 9_40's 7e-6 higher; both converged-stable).
// A tall start per member ("tall_start" in summary.json): the same braid with
// its strands stacked along the axis (EmbeddingOptions::braid_tilt = π/2,
// spacing kTallSpacing/s of the coil radius; an isotopy of the coil, 3D-ness
// 0.2-0.4), relaxed; its energy and 3D-ness against the coil's.
// The link scan per member ("link_scan" in summary.json; paper Section 8.3's
// jumping-knot pipeline, which the paper names for Fig. 16's states): the
// coil relaxed with the full model at prescribed links Lk = Tw + Wr, under
// the slab |z| < 2 d̂ and then released (ek::scan_links(), ek/dataset/
// deploy.hpp), on a grid of links and bisected at the two ends of the
// interval where the flat coil is stable. Each 3D state's p-fold symmetry
// error; the p-fold symmetric 3D state (see linked_symmetric():
// candidates averaged over their p periods and relaxed again at their
// links; "link_scan.symmetric"), with its crossing p-gons.
// The links are Lk_0 + t, Lk_0 the flat coil's twist-free link (its writhe,
// rounded: the braid's exponent sum, 0 for (σ1σ2⁻¹)^p and p for
// (σ1σ2⁻¹σ3)^p), t the twist added:
//   ci:      t = -8, 0, 1, 8 [turns], no bisection, 1 + 1 candidates symmetrized
//   default: t = -12, -11, ..., 12, 3 bisection steps per onset, 3 + 3 candidates
//   paper:   t = -14, -13.5, ..., 14, 4 bisection steps, 5 + 5 candidates
// Braids of the two families whose closure has more than one component
// ((σ1σ2⁻¹)^p for p divisible by 3: p = 3 is the Borromean rings) are
// skipped and listed in "skipped".
// Writes periodic.csv, links.csv, curves/<family>_p<p>[_symmetric].obj,
// curves/<family>_p<p>_lk<link>.obj (3D states of the scan),
// curves/<family>_p<p>_lk_symmetric.obj and summary.json (docs/results.md).
#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <thread>

#include "ek/analysis/attributes.hpp"
#include "ek/analysis/symmetry.hpp"
#include "ek/dataset/deploy.hpp"
#include "ek/embedding/embedding.hpp"
#include "ek/geometry/curve_io.hpp"
#include "ek/geometry/polyline.hpp"
#include "ek/geometry/writhe.hpp"
#include "ek/knots/alexander.hpp"
#include "ek/solver/relax.hpp"
#include "experiment.hpp"
#include "periodic_braids_summary.hpp"
#include "scales.hpp"

using namespace ek;
using namespace ek::exp;

namespace {

/// [coil radius] total height of the tall start's strand stack (s - 1)/s of this
constexpr double kTallSpacing = 0.9;
/// [edge lengths] crossing height of the coil of the link scan: inside the
/// slab |z| < 2 d̂ (as in exp_jumping_knots)
constexpr double kScanCrossingHeight = 0.35;
/// [1] a p-fold average relaxed again counts as p-fold symmetric at or below
/// this rotational_symmetry_error (PaperPeriodicBraids' tolerance)
constexpr double kSymmetricError = 1e-6;

std::array<double, 3> array3(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

struct Member {
  std::string family;
  int strands, p;
  std::vector<int> period;
  std::string table_name;
  BraidWord word() const {
    BraidWord w;
    w.strands = strands;
    for (int k = 0; k < p; ++k) w.letters.insert(w.letters.end(), period.begin(), period.end());
    return w;
  }
};

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

/// The twist-free relaxation from the coil, its symmetric neighbour and the tall start (as before the link scan).
/// `row`: its periodic.csv row.
results::PeriodicMember twist_free(const Args& a, const Member& m, const BraidWord& w, int n,
                                   std::vector<std::string>& row) {
  const EmbeddingOptions eo = multicovered_circle(n, m.strands);
  const Embedding emb = embed_braid(w, eo);
  const RelaxResult r = relax(emb.points);
  const Points& P = r.positions;
  results::PeriodicMember out;
  out.family = m.family;
  out.p = m.p;
  if (!m.table_name.empty()) {
    out.knot = m.table_name;
    out.alexander_matches_table = alexander(P) == alexander(*KnotTable::global().at(m.table_name).pd);
  }
  out.status = r.status();
  out.energy = r.energy.total;
  out.alexander_preserved = r.alexander_preserved;
  out.threedim = threedim(P);
  const SymmetryAxis sa = find_symmetry_axis(P, m.p);
  const Vec3 &c = sa.center, &axis = sa.axis;
  out.axis = array3(axis);
  out.center = array3(c);
  out.symmetry_error = sa.error;
  out.control_error = rotational_symmetry_error(P, c, axis, m.p + 1);
  const CrossingPolygons g = crossing_polygons(P, c, axis, m.p, kCrossingGap);
  out.crossings = g.crossings;
  out.projection_crossings = g.projected;
  out.polygon_split = g.by_radius ? "radius" : "height";
  out.polygon_error_deg = g.error();
  out.relative_rotation_deg = g.rotation;
  out.expected_rotation_deg = (m.p % 2 == 1) ? 0.0 : 180.0 / m.p;
  // The p-fold symmetric equilibrium next to it: relax the p-fold average
  // (same rest lengths). Fig. 16's states are symmetric; the relaxation
  // from the coil may stop in a slightly asymmetric neighbour.
  RelaxOptions so;
  so.rest_lengths = edge_lengths(emb.points);
  const RelaxResult rs = relax(symmetrize(P, c, axis, m.p, m.strands), so);
  const Points& S = rs.positions;
  const Vec3 cs = S.colwise().mean().transpose();
  const CrossingPolygons gs = crossing_polygons(S, cs, axis, m.p, kCrossingGap);
  out.symmetric = {rs.status(), rs.energy.total, rs.energy.total - r.energy.total, threedim(S),
                   rotational_symmetry_error(S, cs, axis, m.p), gs.crossings, gs.by_radius ? "radius" : "height",
                   gs.error(), gs.rotation};
  // A second, tall start: the same braid with its strands stacked along
  // the axis (cross-sections turned by 90°, an isotopy of the coil; a 3D
  // start), to see whether a 3D equilibrium is reached from there.
  EmbeddingOptions to = eo;
  to.braid_tilt = 0.5 * M_PI;
  to.strand_spacing = kTallSpacing / m.strands;
  const Embedding tall = embed_braid(w, to);
  const RelaxResult rt = relax(tall.points);
  out.tall_start = {threedim(tall.points), rt.status(), rt.energy.total, rt.energy.total - r.energy.total,
                    threedim(rt.positions)};
  const std::string stem = "curves/" + m.family + "_p" + std::to_string(m.p);
  out.curve = stem + ".obj";
  out.symmetric_curve = stem + "_symmetric.obj";
  write_curve(a.out + "/" + *out.curve, P);
  write_curve(a.out + "/" + *out.symmetric_curve, S);
  row = {m.family, std::to_string(m.strands), std::to_string(m.p), std::to_string(n), m.table_name, r.status(),
         Csv::num(r.energy.total),
         out.alexander_matches_table ? Csv::flag(*out.alexander_matches_table) : std::string(),
         Csv::num(out.symmetry_error), std::to_string(g.top.count), std::to_string(g.bottom.count),
         Csv::num(g.top.max_error), Csv::num(g.bottom.max_error), Csv::num(g.rotation),
         Csv::num(out.expected_rotation_deg), *out.curve};
  std::ostringstream line;
  line << "exp_periodic_braids: " << m.family << " p=" << m.p << " twist-free " << r.status() << " 3D-ness "
       << out.threedim << ", symmetry error " << out.symmetry_error << ", crossings " << g.top.count << "+"
       << g.bottom.count << ", rotation " << g.rotation << " deg (expected " << out.expected_rotation_deg
       << "); symmetric equilibrium " << rs.status() << " dE " << out.symmetric.energy_above << "; tall start "
       << rt.status() << " 3D-ness " << out.tall_start.threedim << "\n";
  std::cout << line.str() << std::flush;
  return out;
}

/// The p-fold symmetric 3D state of the scan. Candidates: the scan's `tries`
/// 3D states nearest to the twist-free link Lk_0 and its `tries` most p-fold
/// symmetric ones, each averaged over its p periods and relaxed again at its
/// link. Chosen: a converged-stable, 3D, p-fold symmetric one (error <=
/// kSymmetricError) nearest to Lk_0 (the least twist added; lower energy
/// breaks ties), else the candidate of smallest symmetry error. Null when the
/// scan found no 3D state or every average intersects itself.
std::optional<results::PeriodicLinkedSymmetric> linked_symmetric(const Args& a, const Member& m, const LinkScan& ls,
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
    y.status = rs.status();
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
      return z.status == "converged-stable" && z.threedim >= kPlanarThreedim && z.symmetry_error <= kSymmetricError;
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
results::PeriodicLinkScan link_scan(const Args& a, const Member& m, const BraidWord& w, int n) {
  EmbeddingOptions eo = multicovered_circle(n, m.strands);
  eo.crossing_height = kScanCrossingHeight;
  const Points coil = embed_braid(w, eo).points;
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
    results::PeriodicLinkRun r{d.link,   d.flat_status, d.flat_energy, d.flat_writhe, d.status, d.energy,
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
  line << "exp_periodic_braids: " << m.family << " p=" << m.p << " link scan (Lk_0 " << out.center << "):";
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
  return run_experiment(argc, argv, "exp_periodic_braids", "Periodic braids of Fig. 16.", [](const Args& a) {
    // (σ1σ2⁻¹)^p, p = 2..8, and (σ1σ2⁻¹σ3)^p, p = 2..7: the knots are members, the links skipped.
    std::vector<Member> members;
    results::PeriodicBraidsSummary sum;
    std::vector<std::string> skipped;
    for (int p = 2; p <= 8; ++p)
      members.push_back({"s1s2i", 3, p, {1, -2}, p == 2 ? "4_1" : p == 4 ? "8_18" : p == 5 ? "10_123" : ""});
    for (int p = 2; p <= 7; ++p) members.push_back({"s1s2is3", 4, p, {1, -2, 3}, p == 3 ? "9_40" : ""});
    std::vector<Member> knots;
    for (const Member& m : members) {
      const int c = closure_components(m.word());
      if (c == 1) knots.push_back(m);
      else skipped.push_back(m.family + " p=" + std::to_string(m.p) + ": " + std::to_string(c) + " components");
    }
    members = knots;
    sum.skipped = skipped;
    const int per_p = 100;  // every scale: the same wire per period (n = 100·p unit edges)
    double total_edges = 0;
    for (const auto& m : members) total_edges += per_p * m.p;
    const ScanScale sc = scan_scale(a);
    const double scan_runs = static_cast<double>(sc.offsets.size() + 2 * sc.refinements + sc.symmetrized);
    announce(a, "exp_periodic_braids",
             std::to_string(members.size()) + " periodic braids, n = " + std::to_string(per_p) + "·p; links " +
                 std::to_string(sc.offsets.size()) + " + 2·" + std::to_string(sc.refinements) + " bisections each",
             total_edges / 400.0 * (4.0 + 4.0 * scan_runs) * kSecondsPerRelaxation / a.jobs);
    std::filesystem::create_directories(a.out + "/curves");
    sum.scale = a.scale_name;
    sum.crossing_gap = kCrossingGap;
    sum.radius = RelaxOptions().material.radius;  // every member relaxes with the default material
    sum.threedim_threshold = kPlanarThreedim;
    // One member per worker thread (each member's solves are single-threaded).
    std::vector<results::PeriodicMember> outs(members.size());
    std::vector<std::vector<std::string>> rows(members.size());
    // A member's error is rethrown after every worker has joined.
    std::atomic<size_t> next{0};
    std::vector<std::exception_ptr> errors(members.size());
    auto worker = [&] {
      for (size_t q = next++; q < members.size(); q = next++) {
        const Member& m = members[q];
        const BraidWord w = m.word();
        try {
          outs[q] = twist_free(a, m, w, per_p * m.p, rows[q]);
          outs[q].link_scan = link_scan(a, m, w, per_p * m.p);
        } catch (const std::exception& e) {
          std::cerr << "exp_periodic_braids: " << m.family << " p=" << m.p << ": " << e.what() << std::endl;
          errors[q] = std::current_exception();
        }
      }
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < std::min<int>(a.jobs, static_cast<int>(members.size())); ++t) pool.emplace_back(worker);
    worker();
    for (auto& t : pool) t.join();
    for (const auto& e : errors)
      if (e) std::rethrow_exception(e);
    Csv csv(a.out + "/periodic.csv",
            {"family", "strands", "p", "vertices", "knot", "status", "energy", "alexander_matches_table",
             "symmetry_error", "top_crossings", "bottom_crossings", "top_polygon_error_deg",
             "bottom_polygon_error_deg", "relative_rotation_deg", "expected_rotation_deg", "curve"});
    Csv links(a.out + "/links.csv", {"family", "p", "link", "flat_status", "flat_energy", "flat_writhe", "status",
                                     "energy", "threedim", "writhe", "buckled", "three_d", "symmetry_error", "curve"});
    for (size_t q = 0; q < members.size(); ++q) {
      const Member& m = members[q];
      const results::PeriodicMember& o = outs[q];
      csv.row(rows[q]);
      for (const auto& r : o.link_scan->runs)
        links.row({m.family, std::to_string(m.p), Csv::num(r.link), r.flat_status, Csv::num(r.flat_energy),
                   Csv::num(r.flat_writhe), r.status, Csv::num(r.energy), Csv::num(r.threedim), Csv::num(r.writhe),
                   Csv::flag(r.buckled), Csv::flag(r.three_d), Csv::num(r.symmetry_error), r.curve.value_or("")});
      sum.members.push_back(o);
    }
    csv.commit();
    links.commit();
    write_summary(a, sum);
  });
}
