// knots embed NAME|--braid WORD|--pd CODE [--strands S] --from braid|pd [--style coil|cylinder] [-n N] -o FILE [--edge-length L] [--strand-spacing S]
//             [--crossing-height H] [--crossing-offset H] [--tilt DEG] [--json]
#include <cmath>
#include <iostream>

#include "args.hpp"
#include "commands.hpp"
#include "ek/core/atomic_file.hpp"
#include "ek/core/errors.hpp"
#include "ek/embedding/embedding.hpp"
#include "ek/geometry/curve_io.hpp"
#include "ek/geometry/link.hpp"
#include "ek/embedding/json.hpp"
#include "ek/knots/conway.hpp"
#include "ek/knots/link_table.hpp"
#include "output.hpp"

namespace ek::cli {

namespace {

/// A link embedded from a braid word or a PD code (`from`, `code` its text):
/// written as a link, summarised. A link of the link table (`record`) must
/// have its listed Conway polynomial on the polygons (a change of link type
/// is an error).
int write_embedded_link(const LinkEmbedding& e, const std::string& from, const std::string& code,
                        const LinkRecord* record, const std::string& out, bool json) {
  const ConwayPolynomial nabla = conway(e.components);
  if (record && nabla != record->conway)
    throw TopologyError("embed: the polygons of " + record->name + " have the Conway polynomial " + nabla.to_string() +
                        ", not the table's " + record->conway.to_string());
  write_link(out, e.components);
  const std::string name = record ? record->name : from + " " + code;
  int vertices = 0;
  for (const Points& P : e.components) vertices += static_cast<int>(P.rows());
  if (json) {
    print_json(link_embedding_json(name, from, e, nabla, out));
    return 0;
  }
  std::cout << "wrote " << out << ": " << (record ? record->description + ", " : std::string())
            << (from == "braid" ? "the closure of " : "the PD code ") << code << ", a link of " << e.components.size()
            << " components, " << vertices
            << " vertices, mean edge length " << fmt(e.edge_length) << ", Conway " << nabla.to_string() << "\n";
  return 0;
}

/// A knot's polygon: written, summarised (`what` says where it came from).
int write_embedded_knot(const Embedding& e, const std::string& name, const std::string& what, const std::string& out,
                        bool json) {
  write_curve(out, e.points);
  if (json) {
    print_json(embedding_json(name, e, out));
    return 0;
  }
  std::cout << "wrote " << out << ": " << what << ", " << e.points.rows() << " vertices, edge length "
            << fmt(e.edge_length) << ", clearance " << fmt(e.clearance) << ", Alexander " << e.alexander->to_string()
            << "\n";
  return 0;
}

}  // namespace

int cmd_embed(int argc, char** argv) {
  std::string from = "braid", style = "coil", out, braid, pd;
  std::vector<std::string> names;
  int strands = 0;
  EmbeddingOptions opt;
  bool json = false;
  ArgParser args("embed",
                 "NAME|--braid WORD|--pd CODE [--strands S] --from braid|pd [--style coil|cylinder] [-n N] -o FILE "
                 "[--edge-length L] [--strand-spacing S] [--crossing-height H] [--crossing-offset H] [--tilt DEG] "
                 "[--json]");
  args.rest("NAME", &names, "knot name as in the table, or a link of the link table (knots info NAME)");
  args.option("--braid", &braid,
              "instead of NAME: a braid word, letters ±1, ±2, ... separated by commas (σ_i⁻¹ is -i; the table's "
              "{1;-2;...} also), whose "
              "closure is a knot or a link (a link is written with one component per cycle of the word)");
  args.option("--pd", &pd,
              "instead of NAME: a PD code [[a;b;c;d];...] (KnotInfo's and LinkInfo's convention: each component's "
              "labels consecutive) of a knot or a link, drawn in the plane (as --from pd)");
  args.option("--strands", &strands, "with --braid: the number of strands (default: 1 + the largest |letter|)");
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
  if (names.size() > 1) throw InputError("one NAME at most, got '" + names[1] + "' too");
  const int sources = !names.empty() + !braid.empty() + !pd.empty();
  if (sources != 1)
    throw InputError(sources == 0 ? "missing argument NAME (or --braid WORD, --pd CODE)"
                                  : "give one of NAME, --braid WORD and --pd CODE");
  if (strands != 0 && braid.empty()) throw InputError("--strands applies to --braid only");
  if (names.empty() && from != "braid") throw InputError("--from applies to NAME only");
  if (out.empty()) throw InputError("missing -o FILE");
  opt.braid_tilt = tilt_deg * M_PI / 180.0;
  opt.braid_style = parse_braid_style(style);
  check_writable(out);
  if (!pd.empty()) {
    const PDLinkCode code = parse_pd_link(pd);
    if (code.components.size() > 1) return write_embedded_link(embed_pd_link(code, opt), "pd", to_string(code.code), nullptr, out, json);
    const std::string text = to_string(code.code);
    return write_embedded_knot(embed_pd(parse_pd(pd), opt), "pd " + text, "the PD code " + text, out, json);
  }
  if (!braid.empty()) {
    const bool braced = braid.find_first_not_of(" \t") != std::string::npos && braid[braid.find_first_not_of(" \t")] == '{';
    const BraidWord word = parse_braid_word(braced ? braid : "{" + braid + "}", strands);
    if (closure_components(word) > 1)
      return write_embedded_link(embed_braid_link(word, opt), "braid", to_string(word), nullptr, out, json);
    return write_embedded_knot(embed_braid(word, opt), "braid " + to_string(word), "the closure of " + to_string(word),
                               out, json);
  }
  const std::string& name = names[0];
  if (const LinkRecord* link = find_link(name)) {
    if (parse_embedding_source(from) == EmbeddingSource::PD) {
      const PDLinkCode code = link->pd();
      return write_embedded_link(embed_pd_link(code, opt), "pd", to_string(code.code), link, out, json);
    }
    return write_embedded_link(embed_braid_link(link->braid, opt), "braid", to_string(link->braid), link, out, json);
  }
  const KnotRecord& knot = KnotTable::global().at(name);
  const Embedding e = embed_knot(knot, parse_embedding_source(from), opt);
  return write_embedded_knot(e, knot.name, knot.name + " from " + to_string(e.method), out, json);
}

}  // namespace ek::cli
