// lattice: random cubic-lattice embeddings (BFACF, paper Section 5).
#include "common.hpp"
#include "ek/core/errors.hpp"
#include "ek/lattice/sampling.hpp"

namespace ek::python {

void bind_lattice(py::module_& m) {
  m.def(
      "sample",
      [](const py::handle& knot, int count, int vertices, long long seed, long long decorrelation,
         double grow_fugacity, double shrink_fugacity, double growth_factor) {
        if (seed < 0) throw InputError("--seed: must be >= 0");
        SampleOptions opt;
        opt.count = count;
        opt.vertices = vertices;
        opt.seed = static_cast<std::uint64_t>(seed);
        opt.decorrelation_moves = decorrelation;
        opt.grow_fugacity = grow_fugacity;
        opt.shrink_fugacity = shrink_fugacity;
        opt.growth_factor = growth_factor;
        const bool by_name = py::isinstance<py::str>(knot);
        const KnotRecord* record = by_name ? &KnotTable::global().at(knot.cast<std::string>()) : nullptr;
        const Points curve = by_name ? Points() : curve_arg(knot, "knot");
        SampleBatch batch;
        {
          py::gil_scoped_release release;
          const LatticeStart start = record ? lattice_start(*record) : lattice_start(curve);
          batch = sample_lattice_polygons(start.points, opt, start.alexander, record ? record->name : "the curve");
        }
        py::list samples;
        for (const LatticePoints& L : batch.samples) samples.append(to_array(ek::to_points(L)));
        return samples;
      },
      py::arg("knot"), py::kw_only(), py::arg("count") = 1, py::arg("vertices") = kDefaultLatticeVertices,
      py::arg("seed") = 1, py::arg("decorrelation") = 0, py::arg("grow_fugacity") = SampleOptions{}.grow_fugacity,
      py::arg("shrink_fugacity") = SampleOptions{}.shrink_fugacity,
      py::arg("growth_factor") = SampleOptions{}.growth_factor,
      R"doc(`count` random cubic-lattice embeddings of a knot type from one continuing BFACF walk
(paper Section 5), as `knots sample`: a list of (vertices, 3) float arrays with integer
coordinates and unit edges. knot: a table name (starts from the table's drawing rounded
onto Z^3) or a closed curve, an (n, 3) array (used as it is when it already is a lattice
polygon, rounded otherwise). vertices even; seed >= 0; decorrelation: extra attempted
moves between samples; grow_fugacity > 0.2135 > shrink_fugacity; growth_factor >= 1.
Every sample's Alexander polynomial is checked. Releases the GIL.)doc");
}

}  // namespace ek::python
