// dataset: reading a data set (docs/dataset-format.md): its knots, equilibria,
// attributes, queries, clusters and parameters.
#include <memory>

#include "common.hpp"
#include "ek/core/errors.hpp"
#include "ek/dataset/dataset_file.hpp"
#include "ek/dataset/json.hpp"
#include "ek/dataset/pipeline.hpp"
#include "ek/dataset/query.hpp"

namespace ek::python {
namespace {

struct Dataset {
  std::string path;
  std::shared_ptr<DatasetReader> reader;
};

template <typename T>
py::array_t<T> column(const std::vector<T>& v) {
  py::array_t<T> a(static_cast<py::ssize_t>(v.size()));
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

py::object string_column(const std::vector<std::string>& v) {
  return py::module_::import("numpy").attr("array")(py::cast(v), py::arg("dtype") = "str");
}

py::array_t<double> equilibria_array(const KnotEntry& e, const Dataset& d) {
  const py::ssize_t m = static_cast<py::ssize_t>(e.equilibria.size());
  const py::ssize_t n = m > 0 ? e.equilibria.front().rows() : d.reader->metadata().vertices.value_or(0);
  py::array_t<double> a({m, n, py::ssize_t{3}});
  for (py::ssize_t i = 0; i < m; ++i)
    Eigen::Map<Points>(a.mutable_data(i), n, 3) = e.equilibria[static_cast<size_t>(i)];
  return a;
}

/// Attribute columns of some knots: knot, index, then one float column per attribute.
Result attribute_columns(const Dataset& d, const std::vector<std::string>& names) {
  std::vector<std::string> knot;
  std::vector<std::int64_t> index;
  std::vector<std::string> columns;
  std::vector<std::vector<double>> values;
  for (const std::string& name : names) {
    const KnotEntry e = d.reader->read(name);
    if (columns.empty()) {
      columns = e.attribute_names;
      values.resize(columns.size());
    }
    for (Eigen::Index i = 0; i < e.attributes.rows(); ++i) {
      knot.push_back(name);
      index.push_back(i);
      for (size_t c = 0; c < columns.size(); ++c) values[c].push_back(e.attributes(i, e.attribute_column(columns[c])));
    }
  }
  Result r{"attributes", py::dict()};
  r.fields["knot"] = string_column(knot);
  r.fields["index"] = column(index);
  for (size_t c = 0; c < columns.size(); ++c) r.fields[py::str(columns[c])] = column(values[c]);
  return r;
}

Result runs_columns(const KnotEntry& e) {
  std::vector<std::int64_t> sample, seed, equilibrium, iterations, contacts, preserved;
  std::vector<double> seconds, energy, gradient_norm;
  std::vector<std::string> status, message;
  for (const RunRecord& r : e.runs) {
    sample.push_back(r.sample);
    seed.push_back(static_cast<std::int64_t>(r.seed));
    status.push_back(to_string(r.status));
    equilibrium.push_back(r.equilibrium);
    iterations.push_back(r.iterations);
    seconds.push_back(r.seconds);
    energy.push_back(r.energy);
    gradient_norm.push_back(r.gradient_norm);
    contacts.push_back(r.contacts);
    preserved.push_back(r.topology_preserved ? 1 : 0);
    message.push_back(r.message);
  }
  Result r{"runs", py::dict()};
  r.fields["sample"] = column(sample);
  r.fields["seed"] = column(seed);
  r.fields["status"] = string_column(status);
  r.fields["equilibrium"] = column(equilibrium);
  r.fields["iterations"] = column(iterations);
  r.fields["seconds"] = column(seconds);
  r.fields["energy"] = column(energy);
  r.fields["gradient_norm"] = column(gradient_norm);
  r.fields["contacts"] = column(contacts);
  r.fields["topology_preserved"] = column(preserved);
  r.fields["message"] = string_column(message);
  return r;
}

py::object optional_index(int v) { return v < 0 ? py::none() : py::object(py::int_(v)); }

Result knot_entry(const Dataset& d, const std::string& name) {
  const KnotEntry e = d.reader->read(name);
  Result r{"knot", py::dict()};
  r.fields["name"] = e.name;
  r.fields["crossing_number"] = e.crossing_number;
  r.fields["bridge_index"] = optional_index(e.bridge_index);
  r.fields["braid_index"] = optional_index(e.braid_index);
  r.fields["alexander"] = e.alexander;
  r.fields["samples_used"] = e.samples_used;
  r.fields["adaptive"] = e.adaptive;
  r.fields["complete"] = e.complete;
  r.fields["equilibria"] = equilibria_array(e, d);
  r.fields["attributes"] = attribute_columns(d, {name});
  r.fields["runs"] = runs_columns(e);
  r.fields["similarity"] = to_array(e.similarity);
  r.fields["linkage"] = to_array(e.linkage);
  r.fields["score_history"] = column(e.score_history);
  if (e.is_link()) {  // docs/dataset-format.md, "Links"
    const size_t m = e.components.size();
    std::vector<std::vector<std::int64_t>> lk(m);
    for (size_t i = 0; i < m; ++i) lk[i].assign(e.linking_numbers.begin() + static_cast<long>(i * m),
                                                e.linking_numbers.begin() + static_cast<long>((i + 1) * m));
    r.fields["components"] = e.components;
    r.fields["conway"] = e.conway;
    r.fields["linking_numbers"] = lk;
  }
  return r;
}

std::vector<std::string> where_list(const py::handle& where) {
  if (where.is_none()) return {};
  if (py::isinstance<py::str>(where)) return {where.cast<std::string>()};
  return where.cast<std::vector<std::string>>();
}

}  // namespace

void bind_dataset(py::module_& m) {
  py::class_<Dataset>(m, "Dataset", R"doc(
A data set file (docs/dataset-format.md), read-only: its knots, their equilibria as arrays,
attributes as numpy columns, queries with the filter syntax of `knots query`, clusters at a
cut as `knots cluster`, and the parameters it was computed with as `knots describe`.
ValueError naming the file when it is not a data set.)doc")
      .def(py::init([](const std::string& path) { return Dataset{path, std::make_shared<DatasetReader>(path)}; }),
           py::arg("path"))
      .def_property_readonly("path", [](const Dataset& d) { return d.path; })
      .def_property_readonly("knots", [](const Dataset& d) { return d.reader->knot_names(); },
                             "The knot names, in table order.")
      .def("__len__", [](const Dataset& d) { return d.reader->knot_names().size(); })
      .def("__contains__", [](const Dataset& d, const std::string& name) { return d.reader->has_knot(name); })
      .def("__repr__", [](const Dataset& d) {
        return "Dataset('" + d.path + "', " + std::to_string(d.reader->knot_names().size()) + " knots)";
      })
      .def(
          "describe",
          [](const Dataset& d) {
            Json j;
            j["file"] = d.path;
            j.update(describe_json(*d.reader));
            return result_from_json(j, "describe");
          },
          R"doc(The parameters the data set was computed with, as `knots describe --json`: file,
parameters (attribute name -> value, None when not recorded), knots.)doc")
      .def("knot", &knot_entry, py::arg("name"),
           R"doc(Everything stored for one knot: name, crossing_number, bridge_index, braid_index (None:
unknown), alexander, samples_used, adaptive, complete, equilibria (m, n, 3), attributes
(columns as attributes()), runs (one column per run field), similarity (m, m), linkage
(m - 1, 4), score_history. ValueError for a knot not in the file.)doc")
      .def(
          "equilibria", [](const Dataset& d, const std::string& name) { return equilibria_array(d.reader->read(name), d); },
          py::arg("name"), "The stored equilibria of a knot as an (m, n, 3) array (index i as in query rows).")
      .def(
          "attributes",
          [](const Dataset& d, std::optional<std::string> knot) {
            return attribute_columns(d, knot ? std::vector<std::string>{*knot} : d.reader->knot_names());
          },
          py::kw_only(), py::arg("knot") = py::none(),
          R"doc(The attributes of every equilibrium (of one knot, or of all) as numpy columns: knot,
index (within the knot), then one float column per attribute (names as in
docs/dataset-format.md: energy, total_curvature, threedim, ...). pandas.DataFrame(
ds.attributes().to_dict()) makes a table.)doc")
      .def(
          "query",
          [](const Dataset& d, std::optional<std::string> knot, const std::string& sort, const py::handle& where,
             std::optional<int> limit) {
            QueryOptions q;
            q.knot = std::move(knot);
            q.sort = sort;
            q.where = where_list(where);
            q.limit = limit;
            return result_from_json(query_json(query_dataset(*d.reader, q)), "query");
          },
          py::kw_only(), py::arg("knot") = py::none(), py::arg("sort") = "", py::arg("where") = py::none(),
          py::arg("limit") = py::none(),
          R"doc(Filters and sorts the equilibria, as `knots query --json`: knot (only this knot type),
sort ("ATTR", "ATTR:asc" or "ATTR:desc"; stable), where ("ATTR<VALUE" or a list of them, all
must hold; operators < <= > >= = == !=), limit. Fields: rows (each with knot, index and one
field per attribute), count. ValueError for an unknown attribute, listing the known ones.)doc")
      .def(
          "clusters",
          [](const Dataset& d, const std::string& name, double cut) {
            if (!(cut >= 0.0 && cut <= 1.0)) throw InputError("--cut must be in [0, 1]");  // as knots cluster
            const KnotEntry e = d.reader->read(name);
            return result_from_json(entry_clusters_json(e, cut), "clusters");
          },
          py::arg("name"), py::kw_only(), py::arg("cut"),
          R"doc(The clusters of a knot's equilibria at a distance cut in [0, 1] (complete linkage on
1 - similarity), sorted by energy, as `knots cluster --json`: name, cut, equilibria,
clusters (each with size, representative, energy_min, energy_max, members), unseen and
unseen_low_energy (the states not yet seen: samples, found, estimated, lower, upper,
new_state_probability, good_turing).)doc");
}

}  // namespace ek::python
