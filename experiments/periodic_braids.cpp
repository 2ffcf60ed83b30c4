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
// Writes periodic.csv, curves/<family>_p<p>[_symmetric].obj and summary.json
// (docs/results.md).
#include <array>
#include <cmath>
#include <filesystem>
#include <iostream>

#include "ek/analysis/attributes.hpp"
#include "ek/analysis/symmetry.hpp"
#include "ek/embedding/embedding.hpp"
#include "ek/geometry/curve_io.hpp"
#include "ek/geometry/polyline.hpp"
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

std::array<double, 3> array3(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

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
    results::PeriodicBraidsSummary sum;
    sum.scale = a.scale_name;
    sum.crossing_gap = kCrossingGap;
    sum.radius = RelaxOptions().material.radius;  // every member relaxes with the default material
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
      csv.row({m.family, std::to_string(m.strands), std::to_string(m.p), std::to_string(n), m.table_name, r.status(),
               Csv::num(r.energy.total),
               out.alexander_matches_table ? Csv::flag(*out.alexander_matches_table) : std::string(),
               Csv::num(out.symmetry_error), std::to_string(g.top.count), std::to_string(g.bottom.count),
               Csv::num(g.top.max_error), Csv::num(g.bottom.max_error), Csv::num(g.rotation),
               Csv::num(out.expected_rotation_deg), *out.curve});
      std::cout << "exp_periodic_braids: " << m.family << " p=" << m.p << " " << r.status() << " symmetry error "
                << out.symmetry_error << ", crossings " << g.top.count << "+" << g.bottom.count << ", rotation "
                << g.rotation << " deg (expected " << out.expected_rotation_deg << "); symmetric equilibrium "
                << rs.status() << " dE " << out.symmetric.energy_above << ", symmetry error "
                << out.symmetric.symmetry_error << ", p-gon error " << gs.error() << " deg, rotation " << gs.rotation
                << " deg; tall start (3D-ness " << out.tall_start.start_threedim << ") " << rt.status() << " dE "
                << out.tall_start.energy_above << ", 3D-ness " << out.tall_start.threedim << std::endl;
      sum.members.push_back(out);
    }
    csv.commit();
    write_summary(a, sum);
  });
}
