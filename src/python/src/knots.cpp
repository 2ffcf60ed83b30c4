// knots: the knot table, Alexander polynomials and curve invariants.
#include "common.hpp"
#include "ek/knots/alexander.hpp"
#include "ek/knots/invariants.hpp"
#include "ek/knots/json.hpp"
#include "ek/knots/link_table.hpp"
#include "ek/knots/table.hpp"

namespace ek::python {
namespace {

Result knot_result(const KnotRecord& k) { return result_from_json(knot_info_json(k, KnotTable::global()), "knot"); }

/// The table as a Python sequence of knots (each computed when reached).
struct TableView {
  std::vector<const KnotRecord*> records;
};
struct TableIterator {
  std::vector<const KnotRecord*> records;
  size_t next = 0;
};

}  // namespace

void bind_knots(py::module_& m) {
  m.def(
      "knot",
      [](const std::string& name) {
        if (const LinkRecord* link = find_link(name)) return result_from_json(link_info_json(*link), "knot");
        return knot_result(KnotTable::global().at(name));
      },
      py::arg("name"),
      R"doc(A knot type of the KnotInfo table by name ("3_1", "10_123", "12a_1019", "0_1" or "unknot"),
or a link of the built-in link table ("hopf", "whitehead", "borromean", ... or "L6a4").

Fields as `knots info NAME --json`: name, crossing_number, bridge_index, braid_index,
unknotting_number, alternating, symmetry_type, dt, pd, braid, braid_strands (None when
unknown), alexander (coefficients, lowest degree first), determinant, table; a link's:
name, aliases, description, components, crossing_number, braid, braid_strands,
component_types, linking_numbers, conway, milnor_triple, table.
ValueError for an unknown name.)doc");

  py::class_<TableIterator>(m, "KnotTableIterator")
      .def("__iter__", [](TableIterator& it) -> TableIterator& { return it; }, py::return_value_policy::reference_internal)
      .def("__next__", [](TableIterator& it) {
        if (it.next >= it.records.size()) throw py::stop_iteration();
        return knot_result(*it.records[it.next++]);
      });
  py::class_<TableView>(m, "KnotTable", "The knots of the KnotInfo table in table order (len, iteration, index).")
      .def("__len__", [](const TableView& t) { return t.records.size(); })
      .def("__getitem__",
           [](const TableView& t, py::ssize_t i) {
             const auto n = static_cast<py::ssize_t>(t.records.size());
             if (i < 0) i += n;
             if (i < 0 || i >= n) throw py::index_error("knot table index out of range");
             return knot_result(*t.records[static_cast<size_t>(i)]);
           })
      .def("__getitem__", [](const TableView&, const std::string& name) { return knot_result(KnotTable::global().at(name)); })
      .def("__iter__", [](const TableView& t) { return TableIterator{t.records, 0}; })
      .def_property_readonly("names",
                             [](const TableView& t) {
                               std::vector<std::string> names;
                               for (const KnotRecord* k : t.records) names.push_back(k->name);
                               return names;
                             },
                             "The knot names, in table order.")
      .def_property_readonly("path", [](const TableView&) { return KnotTable::global().path(); });

  m.def(
      "knot_table",
      [](std::optional<int> max_crossings, bool include_unknot) {
        const KnotTable& table = KnotTable::global();
        TableView t;
        if (max_crossings) {
          t.records = table.up_to_crossings(*max_crossings, include_unknot);
        } else {
          for (const KnotRecord& k : table.records())
            if (include_unknot || k.crossing_number > 0) t.records.push_back(&k);
        }
        return t;
      },
      py::kw_only(), py::arg("max_crossings") = py::none(), py::arg("include_unknot") = true,
      R"doc(The knot table (KNOT_TABLE or the path built in; knot_table_path()), or its knots with at most
max_crossings crossings, in table order. Each item is knot(name); the polynomial of an item is
computed when the item is reached.)doc");

  m.def(
      "alexander",
      [](const py::handle& knot) {
        if (py::isinstance<py::str>(knot)) return table_alexander(KnotTable::global().at(knot.cast<std::string>())).coefficients;
        const Points P = curve_arg(knot, "points");
        py::gil_scoped_release release;
        return alexander(P).coefficients;
      },
      py::arg("knot"),
      R"doc(The Alexander polynomial's coefficients (lowest degree first, normal form: palindromic,
Δ(1) = 1) of a table knot by name, or of a closed polygon, an (n, 3) array (projected along a
generic direction). The trefoil: [1, -1, 1].)doc");

  m.def(
      "invariants",
      [](const py::handle& points) { return result_from_json(invariants_json(curve_invariants(curve_arg(points, "points"))), "invariants"); },
      py::arg("points"),
      R"doc(Invariants of the closed polygon points, (n, 3), as `knots invariants FILE --json`:
vertices, length, alexander, determinant, writhe, total_curvature, clearance.)doc");
}

}  // namespace ek::python
