#include "ek/mechanics/deploy.hpp"

#include <algorithm>
#include <cmath>

#include "ek/analysis/attributes.hpp"
#include "ek/core/errors.hpp"
#include "ek/geometry/polyline.hpp"

namespace ek {

void DeployOptions::validate() const {
  require_input(threedim_threshold >= 0.0, "deploy: threedim_threshold must be >= 0");
  require_input(buckling_writhe > 0.0, "deploy: buckling_writhe must be > 0");
  relax.validate();
}

void LinkScanOptions::validate() const {
  require_input(!grid.empty(), "scan_links: the link grid is empty");
  require_input(std::is_sorted(grid.begin(), grid.end()) &&
                    std::adjacent_find(grid.begin(), grid.end()) == grid.end(),
                "scan_links: the link grid must be strictly ascending");
  require_input(refinements >= 0, "scan_links: refinements must be >= 0");
}

DeployRun deploy_at_link(const Points& coil, double link, const DeployOptions& options) {
  options.validate();
  RelaxOptions ro = options.relax;
  ro.link = link;
  ro.method = RelaxMethod::Direct;  // the full model relaxes directly at n
  SlabOptions slab;
  const double dhat = ro.dhat.value_or(2.0 * ro.material.radius);
  slab.half_thickness = options.slab_half_thickness.value_or(2.0 * dhat);
  require_input(coil.rows() > 0 && coil.col(2).cwiseAbs().maxCoeff() < slab.half_thickness,
                "deploy: the coil must lie strictly inside the slab |z| < " + std::to_string(slab.half_thickness));
  ro.slab = slab;
  if (!ro.rest_lengths) ro.rest_lengths = edge_lengths(coil);
  const RelaxResult flat = relax(coil, ro);
  ro.slab.reset();
  const RelaxResult r = relax(flat.positions, ro);
  DeployRun out;
  out.link = link;
  out.flat_status = flat.status();
  out.flat_energy = flat.energy.total;
  out.flat_writhe = flat.writhe;
  out.status = r.status();
  out.energy = r.energy.total;
  out.writhe = r.writhe;
  out.link_error = std::fabs(r.link - link);
  out.stable = r.stable() && r.alexander_preserved;
  out.threedim = threedim(r.positions);
  out.buckled = out.stable && (std::fabs(r.writhe - flat.writhe) >= options.buckling_writhe ||
                               out.threedim >= options.threedim_threshold);
  out.three_d = out.stable && out.threedim >= options.threedim_threshold;
  out.positions = r.positions;
  out.theta = r.theta;
  return out;
}

namespace {

bool stays_flat(const DeployRun& r) { return r.stable && !r.buckled; }

/// The stable interval of the sorted runs around `center`, its buckled
/// neighbours and the nearest 3D states on either side.
void find_interval(LinkScan& s, double center) {
  s.flat_low.reset(), s.flat_high.reset(), s.buckled_below.reset(), s.buckled_above.reset();
  s.three_d_below.reset(), s.three_d_above.reset();
  const auto& R = s.runs;
  std::optional<size_t> mid;
  for (size_t i = 0; i < R.size(); ++i)
    if (!mid || std::fabs(R[i].link - center) < std::fabs(R[*mid].link - center)) mid = i;
  if (!mid || !stays_flat(R[*mid])) return;
  size_t lo = *mid, hi = *mid;
  while (lo > 0 && stays_flat(R[lo - 1])) --lo;
  while (hi + 1 < R.size() && stays_flat(R[hi + 1])) ++hi;
  s.flat_low = R[lo].link, s.flat_high = R[hi].link;
  if (lo > 0 && R[lo - 1].buckled) s.buckled_below = R[lo - 1].link;
  if (hi + 1 < R.size() && R[hi + 1].buckled) s.buckled_above = R[hi + 1].link;
  for (size_t i = lo; i-- > 0;)
    if (R[i].three_d) {
      s.three_d_below = R[i].link;
      break;
    }
  for (size_t i = hi + 1; i < R.size(); ++i)
    if (R[i].three_d) {
      s.three_d_above = R[i].link;
      break;
    }
}

/// Bisects the onset between the flat link `inner` and the buckled link `outer`.
void bisect(LinkScan& s, const Points& coil, double inner, double outer, int steps, const DeployOptions& options) {
  for (int k = 0; k < steps; ++k) {
    const double mid = 0.5 * (inner + outer);
    DeployRun r = deploy_at_link(coil, mid, options);
    const bool buckled = r.buckled, flat = stays_flat(r);
    s.runs.push_back(std::move(r));
    if (buckled)
      outer = mid;
    else if (flat)
      inner = mid;
    else
      return;
  }
}

}  // namespace

LinkScan scan_links(const Points& coil, const LinkScanOptions& scan, const DeployOptions& options) {
  scan.validate();
  options.validate();
  LinkScan s;
  for (double lk : scan.grid) s.runs.push_back(deploy_at_link(coil, lk, options));
  find_interval(s, scan.center);
  if (s.buckled_below) bisect(s, coil, *s.flat_low, *s.buckled_below, scan.refinements, options);
  if (s.buckled_above) bisect(s, coil, *s.flat_high, *s.buckled_above, scan.refinements, options);
  std::sort(s.runs.begin(), s.runs.end(), [](const DeployRun& a, const DeployRun& b) { return a.link < b.link; });
  find_interval(s, scan.center);
  return s;
}

}  // namespace ek
