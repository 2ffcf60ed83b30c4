// geometry: curve files and the writhe.
#include "common.hpp"
#include "ek/geometry/curve_io.hpp"
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
      "writhe", [](const py::handle& points) { return writhe(curve_arg(points, "points")); }, py::arg("points"),
      "Writhe Wr of the closed polygon points, (n, 3): the exact Gauss double sum (docs/models.md).");
}

}  // namespace ek::python
