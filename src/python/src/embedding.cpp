// embedding: a 3D curve of a table knot from its braid word or PD code.
#include <cmath>

#include "common.hpp"
#include "ek/core/atomic_file.hpp"
#include "ek/core/errors.hpp"
#include "ek/embedding/embedding.hpp"
#include "ek/embedding/json.hpp"
#include "ek/geometry/curve_io.hpp"
#include "ek/geometry/link.hpp"
#include "ek/knots/link_table.hpp"

namespace ek::python {
namespace {

/// A link of the link table laid out as `knots embed NAME` does: its braid
/// closed as a coil, or its PD code; the Conway polynomial of the polygons
/// checked against the table's.
Result embed_link(const LinkRecord& link, EmbeddingSource source, const EmbeddingOptions& opt,
                  const std::optional<std::string>& output) {
  LinkEmbedding e;
  ConwayPolynomial nabla;
  std::string from;
  {
    py::gil_scoped_release release;
    from = source == EmbeddingSource::PD ? "pd" : "braid";
    e = source == EmbeddingSource::PD ? embed_pd_link(link.pd(), opt) : embed_braid_link(link.braid, opt);
    nabla = conway(e.components);
    if (nabla != link.conway)
      throw TopologyError("embed: the polygons of " + link.name + " have the Conway polynomial " + nabla.to_string() +
                          ", not the table's " + link.conway.to_string());
    if (output) write_link(*output, e.components);
  }
  Result r = result_from_json(link_embedding_json(link.name, from, e, nabla, output), "embedding");
  py::list points;
  for (const Points& P : e.components) points.append(to_array(P));
  r.fields["points"] = points;
  return r;
}

}  // namespace

void bind_embedding(py::module_& m) {
  m.def(
      "embed",
      [](const std::string& name, const std::string& from, int vertices, double edge_length,
         std::optional<double> strand_spacing, double crossing_height, double tilt, const std::string& style,
         double crossing_offset, std::optional<std::string> output) {
        EmbeddingOptions opt;
        opt.vertices = vertices;
        opt.edge_length = edge_length;
        opt.strand_spacing = strand_spacing;
        opt.crossing_height = crossing_height;
        opt.braid_tilt = tilt * M_PI / 180.0;
        opt.braid_style = parse_braid_style(style);
        opt.cylinder_crossing_offset = crossing_offset;
        if (output) check_writable(*output);
        if (const LinkRecord* link = find_link(name)) return embed_link(*link, parse_embedding_source(from), opt, output);
        const KnotRecord& knot = KnotTable::global().at(name);
        Embedding e;
        {
          py::gil_scoped_release release;
          e = embed_knot(knot, parse_embedding_source(from), opt);
          if (output) write_curve(*output, e.points);
        }
        Result r = result_from_json(embedding_json(knot.name, e, output), "embedding");
        r.fields["points"] = to_array(e.points);
        return r;
      },
      py::arg("name"), py::kw_only(), py::arg("from_") = "braid", py::arg("vertices") = EmbeddingOptions{}.vertices,
      py::arg("edge_length") = EmbeddingOptions{}.edge_length, py::arg("strand_spacing") = py::none(),
      py::arg("crossing_height") = EmbeddingOptions{}.crossing_height, py::arg("tilt") = 0.0,
      py::arg("style") = "coil", py::arg("crossing_offset") = EmbeddingOptions{}.cylinder_crossing_offset,
      py::arg("output") = py::none(),
      R"doc(A closed polygon of a table knot with `vertices` equal edges, as `knots embed`:
from_="braid" the closed braid as a coil around the z axis, from_="pd" the planar
drawing of the PD code lifted at the crossings (`from` is a Python keyword, hence
from_). strand_spacing (braid: in coil radii; None: automatic), crossing_height
(braid coil: in strand spacings), tilt (braid coil: degrees; 0 a flat coil, 90
stacked along the axis), style ("coil" or "cylinder": the strands stacked along the
axis one letter slot apart, the paper's public start), crossing_offset (braid
cylinder: radial offset at a crossing in edge lengths). output: also write the
curve file, atomically.

Fields: name, from, output (when given), vertices, edge_length, max_edge_deviation,
clearance, alexander, and points, the (vertices, 3) array. A link of the link table
(name as `knots info` lists it, e.g. "borromean"): name, from, components, vertices,
edge_length, max_edge_deviation, linking_numbers, conway, output (when given), and
points, the list of the components' (n_i, 3) arrays (as read_link and relax_link); a
change of link type on the polygons raises TopologyError.)doc");
}

}  // namespace ek::python
