// knots ccd START END [--radius R] [--separation S] [--json]
#include <cmath>
#include <iostream>

#include "args.hpp"
#include "commands.hpp"
#include "ek/contact/contact_potential.hpp"
#include "ek/core/errors.hpp"
#include "ek/geometry/curve_io.hpp"
#include "ek/geometry/polyline.hpp"
#include "output.hpp"

namespace ek::cli {

int cmd_ccd(int argc, char** argv) {
  std::string start_file, end_file;
  double radius = 0.2;
  ContactOptions opt;
  bool json = false;
  ArgParser args("ccd", "START END [--radius R] [--separation S] [--json]");
  args.positional("START", &start_file, "curve at the start of the motion (.obj or .txt)");
  args.positional("END", &end_file, "curve at the end of the motion, same vertex count (vertex i moves on a line)");
  args.option("--radius", &radius, "wire radius r; the barrier distance is 2r (default 0.2)");
  args.option("--separation", &opt.ccd_separation,
              "keep every pair at >= this fraction of min(its start distance, 2r) (default 0.1, in (0, 1))");
  args.flag("--json", &json, "print one JSON object");
  if (!args.parse(argc, argv)) return 0;
  require_input(radius > 0.0 && std::isfinite(radius), "--radius must be positive");
  require_input(opt.ccd_separation > 0.0 && opt.ccd_separation < 1.0, "--separation must be in (0, 1)");
  opt.dhat = 2.0 * radius;

  const Points x = read_curve(start_file);
  const Points y = read_curve(end_file);
  require_input(x.rows() == y.rows(), end_file + ": has " + std::to_string(y.rows()) + " vertices, " + start_file +
                                          " has " + std::to_string(x.rows()));
  const Points dx = y - x;
  const int n = static_cast<int>(x.rows());
  ContactPotential contact(CurveTopology::single(n), opt);
  const StepReport r = contact.max_step_report(x, dx);
  const Points at_t = x + r.t * dx;
  // clearance (edges sharing no vertex) along the certified part of the motion
  double min_sampled = clearance(x).distance;
  const int samples = 64;
  for (int k = 1; k <= samples; ++k) min_sampled = std::min(min_sampled, clearance(x + (r.t * k / samples) * dx).distance);
  const double c_start = clearance(x).distance, c_t = clearance(at_t).distance, c_end = clearance(y).distance;

  if (json) {
    Json j;
    j["start"] = start_file;
    j["end"] = end_file;
    j["vertices"] = n;
    j["t"] = number(r.t);
    j["full_step"] = r.t >= 1.0;
    j["separation"] = number(opt.ccd_separation);
    j["dhat"] = number(opt.dhat);
    j["candidates"] = r.candidates;
    if (r.edge_a >= 0)
      j["limiting_edges"] = {r.edge_a, r.edge_b};
    else
      j["limiting_edges"] = nullptr;
    j["clearance_start"] = number(c_start);
    j["clearance_at_t"] = number(c_t);
    j["clearance_end"] = number(c_end);
    j["min_clearance_sampled"] = number(min_sampled);
    print_json(j);
    return 0;
  }
  std::cout << "vertices:              " << n << "\n"
            << "t:                     " << fmt(r.t) << (r.t >= 1.0 ? " (the whole motion is collision free)" : "")
            << "\n"
            << "pairs tested:          " << r.candidates << "\n";
  if (r.edge_a >= 0) std::cout << "limiting edges:        " << r.edge_a << " and " << r.edge_b << "\n";
  std::cout << "clearance at start:    " << fmt(c_start) << "\n"
            << "clearance at t:        " << fmt(c_t) << "\n"
            << "clearance at end:      " << fmt(c_end) << "\n"
            << "min clearance on [0,t] (" << samples + 1 << " samples): " << fmt(min_sampled) << "\n";
  return 0;
}

}  // namespace ek::cli
