// solver: the energy of a curve and its relaxation to a stable equilibrium.
#include "common.hpp"
#include "ek/core/atomic_file.hpp"
#include "ek/core/errors.hpp"
#include "ek/geometry/curve_io.hpp"
#include "ek/solver/energy.hpp"
#include "ek/solver/json.hpp"
#include "ek/geometry/link.hpp"
#include "ek/solver/relax_request.hpp"

namespace ek::python {
namespace {

Result relax_points(const py::handle& points, const RelaxRequest& request, const std::optional<std::string>& output,
                    const std::optional<std::string>& trace) {
  const Points P = curve_arg(points, "points");
  const RelaxOptions options = request.options();
  if (output) check_writable(*output);
  if (trace) check_writable(*trace);
  RelaxResult r;
  {
    py::gil_scoped_release release;
    r = relax(P, options);
  }
  if (const std::string change = topology_change(r); !change.empty()) throw TopologyError(change);
  if (output) write_curve(*output, r.positions);
  if (trace) write_trace_file(*trace, r);
  Result result = result_from_json(relax_json(r, request.method), "relax");
  if (output) result.fields["output"] = *output;
  if (trace) result.fields["trace"] = *trace;
  result.fields["points"] = to_array(r.positions);
  return result;
}

Result relax_link_components(const py::list& components, const RelaxRequest& request,
                             const std::optional<std::string>& output) {
  Link link;
  for (const py::handle& c : components) link.push_back(curve_arg(c, "components"));
  require_input(link.size() >= 2, "relax_link: a link needs at least 2 components (relax a knot with relax())");
  if (output) check_writable(*output);
  RelaxResult r;
  {
    py::gil_scoped_release release;
    r = relax(link, request.options());
  }
  if (const std::string change = topology_change(r); !change.empty()) throw TopologyError("relax: " + change);
  if (output) write_link(*output, r.components());
  Result result = result_from_json(link_relax_json(r), "relax_link");
  if (output) result.fields["output"] = *output;
  py::list out;
  for (const Points& P : r.components()) out.append(to_array(P));
  result.fields["points"] = out;
  return result;
}

}  // namespace

void bind_solver(py::module_& m) {
  m.def(
      "relax_link",
      [](const py::list& components, std::optional<std::string> output, std::optional<double> tol, int max_iter,
         double radius, double young, double poisson, std::optional<double> contact_stiffness,
         std::vector<double> continuation, std::string method) {
        RelaxRequest q;
        q.tol = tol;
        q.max_iter = max_iter;
        q.radius = radius;
        q.young = young;
        q.poisson = poisson;
        q.contact_stiffness = contact_stiffness;
        q.continuation = std::move(continuation);
        q.method = std::move(method);
        return relax_link_components(components, q, output);
      },
      py::arg("components"), py::kw_only(), py::arg("output") = py::none(), py::arg("tol") = py::none(),
      py::arg("max_iter") = RelaxRequest{}.max_iter, py::arg("radius") = RelaxRequest{}.radius,
      py::arg("young") = RelaxRequest{}.young, py::arg("poisson") = RelaxRequest{}.poisson,
      py::arg("contact_stiffness") = py::none(), py::arg("continuation") = std::vector<double>{},
      py::arg("method") = RelaxRequest{}.method,
      R"doc(Relaxes a link, a list of at least 2 closed polygons (n_c, 3) (their edge lengths are the
rest lengths), as `knots relax` relaxes a link file (docs/models.md, "Links"): one twist-free
rod per component, contact between all edges, Newton at n with the method's Newton settings.
Options as the command's: output (a link file, written atomically), tol, max_iter, radius,
young, poisson, contact_stiffness, continuation, method.

Fields: the JSON keys of `knots relax` on a link (components, vertices, status, iterations,
seconds, energy, gradient_norm, min_distance, alexander, linking_numbers,
alexander_preserved, linking_preserved, conway, conway_preserved), output when given, and
points, the list of the components' equilibria. A change of a component's knot type, of a
linking number or of the link's Conway polynomial raises TopologyError. Releases the GIL while it relaxes.)doc");

  m.def(
      "energy",
      [](const py::handle& points, double radius, double young, double poisson, std::optional<double> link,
         std::optional<double> rest_length) {
        CurveEnergyOptions opt;
        opt.material.radius = radius;
        opt.material.young = young;
        opt.material.poisson = poisson;
        opt.link = link;
        opt.rest_length = rest_length;
        return result_from_json(curve_energy_json(curve_energy(curve_arg(points, "points"), opt)), "energy");
      },
      py::arg("points"), py::kw_only(), py::arg("radius") = RodMaterial{}.radius, py::arg("young") = RodMaterial{}.young,
      py::arg("poisson") = RodMaterial{}.poisson, py::arg("link") = py::none(), py::arg("rest_length") = py::none(),
      R"doc(Energy of the closed polygon points, (n, 3), as the elastic rod with self-contact (paper
Section 6), as `knots energy`. Without link: the twist-free model (Tw = 0, Lk = Wr); with
link: the full model with Theta fixed so that Tw + Wr = link, at uniform twist density.
rest_length: of every edge (None: the curve's own edge lengths, no stretching).

Fields: vertices, model, energy, energy_stretch, energy_bend, energy_twist,
energy_contact, gradient_norm, contacts, twist, writhe, link.)doc");

  m.def(
      "relax",
      [](const py::handle& points, std::optional<std::string> output, std::optional<double> link,
         std::optional<double> planar, bool release, std::optional<double> tol, int max_iter, double radius,
         double young, double poisson, std::optional<double> contact_stiffness, std::vector<double> continuation, bool full_model,
         std::string method, std::optional<int> coarse_levels, std::string factorization, bool eigen,
         bool stop_at_saddle, std::optional<std::string> trace, bool verbose) {
        RelaxRequest q;
        q.link = link;
        q.planar = planar;
        q.release = release;
        q.tol = tol;
        q.max_iter = max_iter;
        q.radius = radius;
        q.young = young;
        q.poisson = poisson;
        q.contact_stiffness = contact_stiffness;
        q.continuation = std::move(continuation);
        q.full_model = full_model;
        q.method = std::move(method);
        q.coarse_levels = coarse_levels;
        q.factorization = std::move(factorization);
        q.eigen = eigen;
        q.stop_at_saddle = stop_at_saddle;
        q.trace = trace.has_value();
        q.verbose = verbose;
        return relax_points(points, q, output, trace);
      },
      py::arg("points"), py::kw_only(), py::arg("output") = py::none(), py::arg("link") = py::none(),
      py::arg("planar") = py::none(), py::arg("release") = false, py::arg("tol") = py::none(),
      py::arg("max_iter") = RelaxRequest{}.max_iter, py::arg("radius") = RelaxRequest{}.radius,
      py::arg("young") = RelaxRequest{}.young, py::arg("poisson") = RelaxRequest{}.poisson,
      py::arg("contact_stiffness") = py::none(),
      py::arg("continuation") = std::vector<double>{}, py::arg("full_model") = false,
      py::arg("method") = RelaxRequest{}.method, py::arg("coarse_levels") = py::none(),
      py::arg("factorization") = RelaxRequest{}.factorization, py::arg("eigen") = false,
      py::arg("stop_at_saddle") = false, py::arg("trace") = py::none(), py::arg("verbose") = false,
      R"doc(Relaxes the closed polygon points, (n, 3) (its edge lengths are the rest lengths), to a
stable equilibrium of the elastic rod with self-contact (paper Section 6), as `knots relax`.
Options as the command's (docs/cli.md): output (write the equilibrium, atomically), link,
planar (slab half-thickness H), release, tol (None: default), max_iter, radius, young,
poisson, contact_stiffness (None: default), continuation (factors in (0, 1)), full_model,
method ("default", "gauss-newton", "two-level", "one-level", "eigen-projected", "hybrid", "exact", "paper"),
coarse_levels (None: the method's),
factorization ("block", "cholmod"), eigen, stop_at_saddle, trace (a CSV path: one row per Newton iteration),
verbose (lines on stderr).

Fields: the JSON keys of `knots relax` (status, converged, stable, iterations,
total_iterations, seconds, energy and its parts, gradient_norm, contacts, min_distance,
link, twist, writhe, alexander_preserved, alexander, model, vertices, smallest_eigenvalue,
method, phases, report, ...), output and trace when given, and points, the (n, 3)
equilibrium. A result that did not converge is returned (converged False); a change of
knot type raises TopologyError. Releases the GIL while it relaxes.)doc");
}

}  // namespace ek::python
