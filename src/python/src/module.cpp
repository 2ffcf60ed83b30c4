// The Python module elastic_knots (docs/python.md): the library's functions
// on numpy arrays. One binding file per library module; the compositions
// live in the library, shared with the `knots` command.
#include "common.hpp"

PYBIND11_MODULE(elastic_knots, m) {
  m.doc() = R"doc(
Elastic knots: the library of the `knots` command on numpy arrays.

Curves are float arrays of shape (n, 3) (vertex i joined to vertex i + 1,
the last to the first). Keyword arguments are named as the command-line
options (docs/cli.md) in snake_case; results are Result objects whose
fields are the JSON keys of the matching command. Bad input raises
ValueError with the command's message; a change of knot type raises
TopologyError. relax(), sample() and load() release the GIL, so a thread
pool runs them in parallel.)doc";
  using namespace ek::python;
  bind_core(m);
  bind_geometry(m);
  bind_knots(m);
  bind_embedding(m);
  bind_lattice(m);
  bind_contact(m);
  bind_solver(m);
  bind_analysis(m);
  bind_mechanics(m);
  bind_dataset(m);
}
