// knots ccd START END [--radius R] [--separation S] [--json]
#include <cmath>
#include <iostream>

#include "args.hpp"
#include "commands.hpp"
#include "ek/contact/json.hpp"
#include "ek/contact/motion.hpp"
#include "ek/core/errors.hpp"
#include "ek/geometry/curve_io.hpp"
#include "output.hpp"

namespace ek::cli {

int cmd_ccd(int argc, char** argv) {
  std::string start_file, end_file;
  MotionCheckOptions opt;
  bool json = false;
  ArgParser args("ccd", "START END [--radius R] [--separation S] [--json]");
  args.positional("START", &start_file, "curve at the start of the motion (.obj or .txt)");
  args.positional("END", &end_file, "curve at the end of the motion, same vertex count (vertex i moves on a line)");
  args.option("--radius", &opt.radius, "wire radius r; the barrier distance is 2r (default 0.2)");
  args.option("--separation", &opt.separation,
              "keep every pair at >= this fraction of min(its start distance, 2r) (default 0.1, in (0, 1))");
  args.flag("--json", &json, "print one JSON object");
  if (!args.parse(argc, argv)) return 0;
  opt.validate();

  const Points x = read_curve(start_file);
  const Points y = read_curve(end_file);
  require_input(x.rows() == y.rows(), end_file + ": has " + std::to_string(y.rows()) + " vertices, " + start_file +
                                          " has " + std::to_string(x.rows()));
  const MotionCheck m = check_linear_motion(x, y, opt);
  if (json) {
    Json j;
    j["start"] = start_file;
    j["end"] = end_file;
    j.update(motion_check_json(m));
    print_json(j);
    return 0;
  }
  const StepReport& r = m.step;
  std::cout << "vertices:              " << m.vertices << "\n"
            << "t:                     " << fmt(r.t) << (r.t >= 1.0 ? " (the whole motion is collision free)" : "")
            << "\n"
            << "pairs tested:          " << r.candidates << "\n";
  if (r.edge_a >= 0) std::cout << "limiting edges:        " << r.edge_a << " and " << r.edge_b << "\n";
  std::cout << "clearance at start:    " << fmt(m.clearance_start) << "\n"
            << "clearance at t:        " << fmt(m.clearance_at_t) << "\n"
            << "clearance at end:      " << fmt(m.clearance_end) << "\n"
            << "min clearance on [0,t] (" << opt.samples + 1 << " samples): " << fmt(m.min_clearance_sampled) << "\n";
  return 0;
}

}  // namespace ek::cli
