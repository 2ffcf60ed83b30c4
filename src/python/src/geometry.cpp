// geometry: curve files and the writhe.
#include "common.hpp"
#include "ek/geometry/curve_io.hpp"
#include "ek/geometry/link.hpp"
#include "ek/geometry/writhe.hpp"

namespace ek::python {

void bind_geometry(py::module_& m) {
  m.def(
      "read_curve", [](const std::string& path) { return to_array(read_curve(path)); }, py::arg("path"),
      R"doc(The closed curve in a .obj or .txt file (docs/cli.md, "Curve files") as an (n, 3) float array.
ValueError naming the file and line for a malformed file.)doc");
  m.def(
      "write_curve", [](const std::string& path, const py::handle& points) { write_curve(path, curve_arg(points, "points")); },
      py::arg("path"), py::arg("points"),
      R"doc(Writes points, an (n, 3) array, as a .obj or .txt curve file (by extension), atomically,
with 17 significant digits (read_curve gives the same numbers back).)doc");
  m.def(
      "read_link",
      [](const std::string& path) {
        py::list out;
        for (const Points& P : read_link(path)) out.append(to_array(P));
        return out;
      },
      py::arg("path"),
      R"doc(The link in a .obj (one closed l loop per component) or .txt (a blank line between
components) file (docs/cli.md, "Curve files") as a list of (n_c, 3) float arrays, one per
component; a curve file gives a list of one. ValueError for a malformed file or touching
components.)doc");
  m.def(
      "write_link",
      [](const std::string& path, const py::list& components) {
        Link link;
        for (const py::handle& c : components) link.push_back(curve_arg(c, "components"));
        write_link(path, link);
      },
      py::arg("path"), py::arg("components"),
      R"doc(Writes components, a list of (n_c, 3) arrays, as a link file (.obj or .txt, by
extension), atomically, with 17 significant digits; a list of one is a curve file.)doc");
  m.def(
      "linking_number",
      [](const py::handle& a, const py::handle& b) { return linking_number(curve_arg(a, "a"), curve_arg(b, "b")); },
      py::arg("a"), py::arg("b"),
      R"doc(The linking number of the closed polygons a and b, (n_a, 3) and (n_b, 3), as the exact
Gauss double sum over segment pairs (docs/models.md, "Links"): an integer up to rounding for
disjoint polygons; +1 for b passing once through a disc bounded by a along a's right-hand
normal.)doc");
  m.def(
      "writhe", [](const py::handle& points) { return writhe(curve_arg(points, "points")); }, py::arg("points"),
      "Writhe Wr of the closed polygon points, (n, 3): the exact Gauss double sum (docs/models.md).");
}

}  // namespace ek::python
