// exp_periodic_braids: periodic braids (paper Section 8.4, Fig. 16).
// (σ1σ2⁻¹)^p on 3 strands and (σ1σ2⁻¹σ3)^p on 4 strands, the members whose
// closure is a knot (experiments/common/periodic_family.hpp), each with
// wire length ∝ p (n = 100·p unit edges at every scale) and the data set's
// wire (r = 0.2), relaxed twist-free. Per member:
//  - from our flat coil (multicovered_circle()): the relaxed state, its
//    Alexander polynomial against the table, its p-fold symmetry
//    (ek::find_symmetry_axis; error against a (p+1)-fold control) and the
//    braid's crossings seen along the axis (two p-gons, ek::crossing_polygons);
//  - from the paper's start, the braid on a tall cylinder (BraidStyle::
//    Cylinder): the equilibrium of the default method and of the paper's
//    (--method paper), and the paper's solver stopped at 100 and 200
//    iterations (the transient, not converged);
//  - the p-fold symmetric critical point (ek::find_symmetric_critical_point):
//    Newton within the p-fold symmetric subspace from the cylinder, whose
//    critical points are critical points of the full energy; its Morse index
//    (negative eigenvalues of the full Hessian, rigid modes removed), each
//    mode's Fourier class (which modes break the symmetry), its p-gons. When
//    the subspace's minimum is flat, the search for a 3D one: the restricted
//    descent from a cylinder as tall as it is wide (kSearchHeight), its 3D
//    image (3D-ness >= kSearchThreedim) of least gradient norm (the
//    bottleneck of the flow) and Newton–Raphson within the subspace from it. A critical point of index >= 1 is displaced along its most negative
//    mode both ways and relaxed: where it falls.
// Writes periodic.csv, critical_points.csv, curves/<family>_p<p>*.obj and
// summary.json (docs/results.md). The link scan of the coils (the paper's
// Section 8.3 pipeline) is exp_periodic_links.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <numeric>
#include <sstream>

#include "ek/analysis/attributes.hpp"
#include "ek/analysis/symmetry.hpp"
#include "ek/core/parallel.hpp"
#include "ek/embedding/embedding.hpp"
#include "ek/geometry/curve_io.hpp"
#include "ek/geometry/link.hpp"
#include "ek/geometry/polyline.hpp"
#include "ek/knots/alexander.hpp"
#include "ek/solver/relax.hpp"
#include "ek/solver/symmetric.hpp"
#include "experiment.hpp"
#include "periodic_braids_summary.hpp"
#include "periodic_family.hpp"
#include "scales.hpp"

using namespace ek;
using namespace ek::exp;

namespace {

/// [1] the search for a 3D symmetric critical point starts from the
/// restricted descent's images at least this 3D (well away from the flat coil)
constexpr double kSearchThreedim = 0.5;
/// [R] height of the search's start, a cylinder as tall as it is wide (the
/// paper's start is (s − 1)·2πR/L tall: flat for long words)
constexpr double kSearchHeight = 2.0;
/// [1] vertices per period of the word (every scale)
constexpr int kVerticesPerPeriod = 100;
/// [1] the paper's solver is stopped at these iteration counts (the transient)
constexpr int kTransientIterations[] = {100, 200};
/// [edge lengths] the largest vertex displacement along a negative mode
/// before relaxing (where a saddle falls)
constexpr double kSaddleKick = 0.05;

std::array<double, 3> array3(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

/// The crossing p-gons of P seen along `axis` through its centroid.
CrossingPolygons polygons(const Points& P, const Vec3& axis, int p) {
  return crossing_polygons(P, P.colwise().mean().transpose(), axis, p, kCrossingGap);
}

/// Everything one member needs: its word, the start and where to write.
struct Context {
  const Args& a;
  const PeriodicBraid& m;
  int n = 0;
  std::string stem;  ///< curves/<family>_p<p>
  std::string write(const std::string& suffix, const Points& P) const {
    const std::string rel = stem + suffix + ".obj";
    write_curve(a.out + "/" + rel, P);
    return rel;
  }
};

/// Relaxed from our flat coil: the member's base fields and its periodic.csv row.
void from_coil(const Context& c, results::PeriodicMember& out, std::vector<std::string>& row) {
  const Embedding emb = embed_braid(c.m.word(), multicovered_circle(c.n, c.m.strands));
  const RelaxResult r = relax(emb.points);
  const Points& P = r.positions;
  if (!c.m.table_name.empty())
    out.alexander_matches_table = alexander(P) == alexander(*KnotTable::global().at(c.m.table_name).pd);
  out.status = to_string(r.status());
  out.energy = r.energy.total;
  out.alexander_preserved = r.alexander_preserved;
  out.threedim = threedim(P);
  const SymmetryAxis sa = find_symmetry_axis(P, c.m.p);
  out.axis = array3(sa.axis);
  out.center = array3(sa.center);
  out.symmetry_error = sa.error;
  out.control_error = rotational_symmetry_error(P, sa.center, sa.axis, c.m.p + 1);
  const CrossingPolygons g = crossing_polygons(P, sa.center, sa.axis, c.m.p, kCrossingGap);
  out.crossings = g.crossings;
  out.projection_crossings = g.projected;
  out.polygon_split = g.by_radius ? "radius" : "height";
  out.polygon_error_deg = g.error();
  out.relative_rotation_deg = g.rotation;
  out.expected_rotation_deg = c.m.expected_rotation_deg();
  out.curve = c.write("", P);
  row = {c.m.family, std::to_string(c.m.strands), std::to_string(c.m.p), std::to_string(c.n), c.m.table_name,
         to_string(r.status()), Csv::num(r.energy.total),
         out.alexander_matches_table ? Csv::flag(*out.alexander_matches_table) : std::string(),
         Csv::num(out.symmetry_error), std::to_string(g.top.count), std::to_string(g.bottom.count),
         Csv::num(g.top.max_error), Csv::num(g.bottom.max_error), Csv::num(g.rotation),
         Csv::num(out.expected_rotation_deg), out.curve};
}

results::PeriodicEquilibrium equilibrium(const Context& c, const Points& start, const std::string& method) {
  const RelaxResult r = relax(start, with_method(RelaxOptions{}, method));
  results::PeriodicEquilibrium e;
  e.method = method;
  e.status = to_string(r.status());
  e.iterations = r.all_phases().iterations;
  e.energy = r.energy.total;
  e.threedim = threedim(r.positions);
  e.stable = r.status() == RelaxStatus::ConvergedStable;
  e.symmetry_error = find_symmetry_axis(r.positions, c.m.p).error;
  e.curve = c.write(method == "default" ? "_cylinder" : "_cylinder_" + method, r.positions);
  return e;
}

results::PeriodicTransient transient(const Context& c, const Points& start, int iterations) {
  RelaxOptions o = with_method(RelaxOptions{}, "paper");
  o.max_iterations = iterations;
  const RelaxResult r = relax(start, o);
  results::PeriodicTransient t;
  t.iterations = iterations;
  t.status = to_string(r.status());
  t.energy = r.energy.total;
  t.gradient_norm = r.report.gradient_norm;
  t.threedim = threedim(r.positions);
  t.symmetry_error = find_symmetry_axis(r.positions, c.m.p).error;
  t.curve = c.write("_paper_" + std::to_string(iterations), r.positions);
  return t;
}

/// Where a critical point of index >= 1 falls: relaxed from it displaced
/// along its most negative mode, both ways.
std::vector<results::PeriodicSaddleDescent> saddle_descents(const SymmetricCriticalPoint& s, const VecX& rest) {
  std::vector<results::PeriodicSaddleDescent> out;
  if (s.index < 1 || s.modes.empty()) return out;
  const VecX& v = s.modes.front().vector;
  const double scale = kSaddleKick * rest.mean() / v.cwiseAbs().maxCoeff();
  RelaxOptions o;
  o.rest_lengths = rest;
  for (int sign : {1, -1}) {
    Points P = s.positions;
    as_vector(P) += sign * scale * v;
    const RelaxResult r = relax(P, o);
    out.push_back({sign, to_string(r.status()), r.energy.total, threedim(r.positions)});
  }
  return out;
}

results::PeriodicCriticalPoint critical_point_summary(const Context& c, const SymmetricCriticalPoint& s,
                                                      const VecX& rest) {
  results::PeriodicCriticalPoint o;
  o.solve = to_string(s.solve);
  o.status = to_string(s.status);
  o.iterations = s.iterations;
  o.converged = s.converged;
  o.energy = s.energy;
  o.gradient_norm = s.gradient_norm;
  o.tolerance = s.tolerance;
  o.threedim = threedim(s.positions);
  o.residual = s.residual;
  o.alexander_preserved = s.alexander_preserved;
  o.index = s.index;
  o.index_complete = s.index_complete;
  o.near_zero = s.near_zero;
  o.subspace_index = s.subspace_index;
  o.threshold = s.threshold;
  for (const SymmetricMode& md : s.modes) o.modes.push_back({md.eigenvalue, md.dominant_class, md.classes});
  o.axis = array3(s.symmetry.axis);
  o.center = array3(s.symmetry.center);
  const CrossingPolygons g = polygons(s.positions, s.symmetry.axis, c.m.p);
  o.crossings = g.crossings;
  o.polygon_split = g.by_radius ? "radius" : "height";
  o.polygon_error_deg = g.error();
  o.rotation_deg = g.rotation;
  o.curve = c.write("_symmetric_critical", s.positions);
  o.descents = saddle_descents(s, rest);
  return o;
}

/// The restricted descent from a cylinder as tall as it is wide, its 3D
/// image of least gradient norm, and Newton–Raphson within the subspace
/// from it. `found` holds the 3D critical point when it converged to one.
results::PeriodicThreeDSearch search_3d(const Context& c, std::optional<SymmetricCriticalPoint>& found) {
  EmbeddingOptions eo;
  eo.vertices = c.n;
  eo.braid_style = BraidStyle::Cylinder;
  eo.strand_spacing = kSearchHeight / (c.m.strands - 1);
  const Points start = embed_braid(c.m.word(), eo).points;
  const VecX rest = edge_lengths(start);
  const CyclicSymmetry sym = fit_cyclic_symmetry(start, c.m.p, start.colwise().mean().transpose(), Vec3::UnitZ());
  const SymmetricDescent d = descend_symmetric(start, rest, sym);
  results::PeriodicThreeDSearch o;
  o.images = static_cast<int>(d.images.size());
  o.search_threedim = kSearchThreedim;
  // the image of smallest gradient norm (the first among equals) that is at
  // least that 3D: images in order of gradient norm, the first 3D one wins
  // (a bounding box per image tried, not per image)
  std::vector<size_t> order(d.images.size());
  std::iota(order.begin(), order.end(), size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return d.gradient_norms[a] < d.gradient_norms[b]; });
  int best = -1;
  for (const size_t k : order)
    if (threedim(d.images[k]) >= kSearchThreedim) {
      best = static_cast<int>(k);
      break;
    }
  if (best < 0) return o;  // the descent never was that 3D
  const Points& P = d.images[static_cast<size_t>(best)];
  o.image = best;
  o.energy = d.energies[static_cast<size_t>(best)];
  o.gradient_norm = d.gradient_norms[static_cast<size_t>(best)];
  o.threedim = threedim(P);
  const CrossingPolygons g = polygons(P, sym.axis, c.m.p);
  o.crossings = g.crossings;
  o.polygon_error_deg = g.error();
  o.rotation_deg = g.rotation;
  o.curve = c.write("_bottleneck", P);
  SymmetricSearchOptions so;
  so.solve = SymmetricSolve::Root;
  const SymmetricCriticalPoint root = find_symmetric_critical_point(P, rest, sym, so);
  o.root_status = to_string(root.status);
  o.root_energy = root.energy;
  o.root_gradient_norm = root.gradient_norm;
  o.root_threedim = threedim(root.positions);
  o.found = root.converged && o.root_threedim >= kPlanarThreedim;
  if (o.found) found = root;
  return o;
}

/// The member from the cylinder start: equilibria, transient, symmetric critical point.
void from_cylinder(const Context& c, results::PeriodicMember& out) {
  EmbeddingOptions eo;
  eo.vertices = c.n;
  eo.braid_style = BraidStyle::Cylinder;
  const Points start = embed_braid(c.m.word(), eo).points;
  const VecX rest = edge_lengths(start);
  out.start_threedim = threedim(start);
  c.write("_cylinder_start", start);
  out.equilibrium = equilibrium(c, start, "default");
  out.equilibrium_paper = equilibrium(c, start, "paper");
  for (int it : kTransientIterations) out.transient.push_back(transient(c, start, it));
  const CyclicSymmetry sym =
      fit_cyclic_symmetry(start, c.m.p, start.colwise().mean().transpose(), Vec3::UnitZ());
  std::optional<SymmetricCriticalPoint> scp = find_symmetric_critical_point(start, rest, sym);
  if (threedim(scp->positions) < kPlanarThreedim) out.three_d_search = search_3d(c, scp);
  out.symmetric_critical_point = critical_point_summary(c, *scp, rest);
}

std::string describe(const results::PeriodicMember& o) {
  const auto& s = o.symmetric_critical_point;
  std::ostringstream line;
  line << "exp_periodic_braids: " << o.family << " p=" << o.p << ": coil " << o.status << " 3D-ness " << o.threedim
       << "; cylinder: " << o.equilibrium.status << " E " << o.equilibrium.energy << " 3D-ness "
       << o.equilibrium.threedim << " (paper method E " << o.equilibrium_paper.energy << ", 3D-ness "
       << o.equilibrium_paper.threedim << "); symmetric critical point (" << s.solve << ") E " << s.energy
       << " |g| " << s.gradient_norm << " 3D-ness " << s.threedim << " index " << s.index
       << (s.index_complete ? "" : "+") << ", p-gons " << s.crossings << " err " << s.polygon_error_deg << " rot "
       << s.rotation_deg;
  if (o.three_d_search)
    line << "; 3D search: bottleneck |g| " << o.three_d_search->gradient_norm << " at E " << o.three_d_search->energy
         << " 3D-ness " << o.three_d_search->threedim << ", root " << o.three_d_search->root_status << " E "
         << o.three_d_search->root_energy << " 3D-ness " << o.three_d_search->root_threedim;
  return line.str();
}

results::PeriodicMember run_member(const Args& a, const PeriodicBraid& m, std::vector<std::string>& row) {
  const Context c{a, m, kVerticesPerPeriod * m.p, "curves/" + m.family + "_p" + std::to_string(m.p)};
  results::PeriodicMember out;
  out.family = m.family;
  out.p = m.p;
  if (!m.table_name.empty()) out.knot = m.table_name;
  from_coil(c, out, row);
  from_cylinder(c, out);
  std::cout << describe(out) << std::endl;
  return out;
}

void write_tables(const Args& a, const std::vector<results::PeriodicMember>& outs,
                  const std::vector<std::vector<std::string>>& rows) {
  Csv csv(a.out + "/periodic.csv",
          {"family", "strands", "p", "vertices", "knot", "status", "energy", "alexander_matches_table",
           "symmetry_error", "top_crossings", "bottom_crossings", "top_polygon_error_deg", "bottom_polygon_error_deg",
           "relative_rotation_deg", "expected_rotation_deg", "curve"});
  for (const auto& r : rows) csv.row(r);
  csv.commit();
  Csv cp(a.out + "/critical_points.csv",
         {"family", "p", "knot", "equilibrium_energy", "equilibrium_threedim", "equilibrium_stable", "energy",
          "threedim", "gradient_norm", "index", "index_complete", "subspace_index", "crossings", "polygon_error_deg",
          "rotation_deg", "bottleneck_gradient_norm", "bottleneck_energy", "bottleneck_threedim"});
  for (const auto& o : outs) {
    const auto& s = o.symmetric_critical_point;
    const auto b = o.three_d_search;
    cp.row({o.family, std::to_string(o.p), o.tabulated(), Csv::num(o.equilibrium.energy),
            Csv::num(o.equilibrium.threedim), Csv::flag(o.equilibrium.stable), Csv::num(s.energy),
            Csv::num(s.threedim), Csv::num(s.gradient_norm), std::to_string(s.index), Csv::flag(s.index_complete),
            std::to_string(s.subspace_index), std::to_string(s.crossings), Csv::num(s.polygon_error_deg),
            Csv::num(s.rotation_deg), b ? Csv::num(b->gradient_norm) : "", b ? Csv::num(b->energy) : "",
            b ? Csv::num(b->threedim) : ""});
  }
  cp.commit();
}

/// A member whose closure is a link, relaxed as a link from the coil
/// (multicovered_circle(), one component per cycle): its topology, energy,
/// 3D-ness and p-fold symmetry about the axis of least extent through the
/// centroid, with a (p+1)-fold control.
results::PeriodicLinkMember run_link(const Args& a, const PeriodicBraid& m) {
  const LinkEmbedding e = embed_braid_link(m.word(), multicovered_circle(kVerticesPerPeriod * m.p, m.strands));
  const RelaxResult r = relax(e.components);
  const Link components = r.components();
  results::PeriodicLinkMember out;
  out.family = m.family;
  out.p = m.p;
  out.components = static_cast<int>(components.size());
  out.status = to_string(r.status());
  out.energy = r.energy.total;
  out.alexander_preserved = r.alexander_preserved;
  out.linking_preserved = r.linking_preserved;
  out.conway_preserved = r.conway_preserved;
  const LinkType& type = *r.link_type;
  out.conway = type.conway.coefficients;
  for (Eigen::Index i = 0; i < type.linking_numbers.rows(); ++i)
    for (Eigen::Index j = 0; j < type.linking_numbers.cols(); ++j)
      out.linking_numbers.push_back(type.linking_numbers(i, j));
  out.min_distance = r.min_distance;
  const Points& all = r.positions;
  out.vertices = static_cast<int>(all.rows());
  out.threedim = threedim(all);
  const Vec3 c = all.colwise().mean().transpose();
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(all.rowwise() - c.transpose(), Eigen::ComputeThinV);
  const Vec3 axis = svd.matrixV().col(2);  // the axis of least extent
  out.symmetry_error = rotational_symmetry_error(components, c, axis, m.p);
  out.control_error = rotational_symmetry_error(components, c, axis, m.p + 1);
  out.curve = "curves/" + m.family + "_p" + std::to_string(m.p) + "_link.obj";
  write_link(a.out + "/" + out.curve, components);
  std::ostringstream line;  // one write: the links run in parallel
  line << "  " << m.label() << " (link of " << out.components << "): " << out.status << ", E " << out.energy
       << ", 3D-ness " << out.threedim << ", " << m.p << "-fold symmetry error " << out.symmetry_error << " (control "
       << out.control_error << ")\n";
  std::cout << line.str() << std::flush;
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  return run_experiment(argc, argv, "exp_periodic_braids", "Periodic braids of Fig. 16.", [](const Args& a) {
    results::PeriodicBraidsSummary sum;
    const std::vector<PeriodicBraid> members = periodic_family(sum.skipped);
    double edges = 0;
    for (const auto& m : members) edges += kVerticesPerPeriod * m.p;
    // per member about 10 relaxations' worth: two equilibria from the coil
    // and the cylinder, the transients, the restricted solves, the index
    announce(a, "exp_periodic_braids",
             std::to_string(members.size()) + " periodic braids, n = " + std::to_string(kVerticesPerPeriod) + "·p",
             edges / 400.0 * 10.0 * kSecondsPerRelaxation / a.jobs);
    std::filesystem::create_directories(a.out + "/curves");
    sum.scale = a.scale_name;
    sum.crossing_gap = kCrossingGap;
    sum.radius = RelaxOptions().material.radius;  // every member relaxes with the default material
    sum.threedim_threshold = kPlanarThreedim;
    std::vector<results::PeriodicMember> outs(members.size());
    std::vector<std::vector<std::string>> rows(members.size());
    parallel_for(members.size(), a.jobs, [&](size_t q) {
      try {
        outs[q] = run_member(a, members[q], rows[q]);
      } catch (const std::exception& e) {
        std::cerr << "exp_periodic_braids: " << members[q].label() << ": " << e.what() << std::endl;
        throw;
      }
    });
    write_tables(a, outs, rows);
    sum.members = outs;
    const std::vector<PeriodicBraid> links = periodic_link_members();
    sum.links.resize(links.size());
    parallel_for(links.size(), a.jobs, [&](size_t q) { sum.links[q] = run_link(a, links[q]); });
    write_summary(a, sum);
  });
}
