// knots embed NAME --from braid|pd [--style coil|cylinder] [-n N] -o FILE [--edge-length L] [--strand-spacing S]
//             [--crossing-height H] [--crossing-offset H] [--tilt DEG] [--json]
#include <cmath>
#include <iostream>

#include "args.hpp"
#include "commands.hpp"
#include "ek/core/atomic_file.hpp"
#include "ek/core/errors.hpp"
#include "ek/embedding/embedding.hpp"
#include "ek/geometry/curve_io.hpp"
#include "ek/embedding/json.hpp"
#include "output.hpp"

namespace ek::cli {

int cmd_embed(int argc, char** argv) {
  std::string name, from = "braid", style = "coil", out;
  EmbeddingOptions opt;
  bool json = false;
  ArgParser args("embed",
                 "NAME --from braid|pd [--style coil|cylinder] [-n N] -o FILE [--edge-length L] [--strand-spacing S] "
                 "[--crossing-height H] [--crossing-offset H] [--tilt DEG] [--json]");
  args.positional("NAME", &name, "knot name as in the table");
  args.option("--from", &from, "braid (closed braid coil, default) or pd (planar drawing of the PD code)");
  args.option("--style", &style,
              "braid: coil (strands side by side in a plane, default) or cylinder (strands stacked along the "
              "axis one letter slot apart: the paper's public start)");
  args.option("-n,--vertices", &opt.vertices, "vertex count of the polygon (default 400)");
  args.option("--edge-length", &opt.edge_length, "common edge length (default 1)");
  args.option("--strand-spacing", &opt.strand_spacing,
              "braid: spacing of the strand positions in units of the radius, radial (coil) or axial (cylinder) "
              "(default: automatic for the coil, 2π/letters for the cylinder)");
  args.option("--crossing-height", &opt.crossing_height,
              "braid coil: height of the over/under offsets at a crossing in units of the strand spacing, > 0 "
              "(default 0.5)");
  args.option("--crossing-offset", &opt.cylinder_crossing_offset,
              "braid cylinder: radial offset of the strands at a crossing in edge lengths, > 0 (default 0.21)");
  double tilt_deg = 0.0;
  args.option("--tilt", &tilt_deg,
              "braid coil: turn of every cross-section about the core circle in degrees: 0 a flat coil (default), "
              "90 the strands stacked along the axis (a tall 3D start); same knot type at every angle");
  args.option("-o,--output", &out, "output curve file (.obj or .txt); written atomically");
  args.flag("--json", &json, "print a JSON summary");
  if (!args.parse(argc, argv)) return 0;
  if (out.empty()) throw InputError("missing -o FILE");
  opt.braid_tilt = tilt_deg * M_PI / 180.0;
  opt.braid_style = parse_braid_style(style);
  check_writable(out);
  const KnotRecord& knot = KnotTable::global().at(name);
  const Embedding e = embed_knot(knot, parse_embedding_source(from), opt);
  write_curve(out, e.points);
  if (json) {
    print_json(embedding_json(knot.name, e, out));
  } else {
    std::cout << "wrote " << out << ": " << knot.name << " from " << e.method << ", " << e.points.rows()
              << " vertices, edge length " << fmt(e.edge_length) << ", clearance " << fmt(e.clearance)
              << ", Alexander " << e.alexander->to_string() << "\n";
  }
  return 0;
}

}  // namespace ek::cli
