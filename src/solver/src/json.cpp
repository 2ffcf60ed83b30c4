#include "ek/solver/json.hpp"

#include "ek/core/errors.hpp"

namespace ek {
namespace {

Json reports_json(const std::vector<NewtonReport>& reports) {
  Json a = Json::array();
  for (const NewtonReport& r : reports) a.push_back(newton_report_json(r));
  return a;
}

}  // namespace

Json energy_parts_json(const EnergyParts& e) {
  Json j;
  j["energy"] = json_number(e.total);
  j["energy_stretch"] = json_number(e.stretch);
  j["energy_bend"] = json_number(e.bend);
  j["energy_twist"] = json_number(e.twist);
  j["energy_contact"] = json_number(e.contact);
  j["energy_slab"] = json_number(e.slab);
  return j;
}

Json newton_report_json(const NewtonReport& r) {
  Json j;
  j["status"] = to_string(r.status);
  j["iterations"] = r.iterations;
  j["seconds"] = json_number(r.seconds);
  j["gradient_norm"] = json_number(r.gradient_norm);
  j["saddle_escapes"] = r.saddle_escapes;
  j["marginal"] = r.marginal;
  j["symbolic_factorizations"] = r.symbolic_factorizations;
  j["numeric_factorizations"] = r.numeric_factorizations;
  j["failed_factorizations"] = r.failed_factorizations;
  j["line_search_trials"] = r.line_search_trials;
  j["time_assembly"] = json_number(r.time_assembly);
  j["time_factorization"] = json_number(r.time_factorization);
  j["time_collision"] = json_number(r.time_collision);
  j["time_line_search"] = json_number(r.time_line_search);
  j["time_eigen"] = json_number(r.time_eigen);
  return j;
}

Json curve_energy_json(const CurveEnergy& e) {
  Json j;
  j["vertices"] = e.vertices;
  j["model"] = to_string(e.model);
  j["energy"] = json_number(e.energy.total);
  j["energy_stretch"] = json_number(e.energy.stretch);
  j["energy_bend"] = json_number(e.energy.bend);
  j["energy_twist"] = json_number(e.energy.twist);
  j["energy_contact"] = json_number(e.energy.contact);
  j["gradient_norm"] = json_number(e.gradient_norm);
  j["contacts"] = e.contacts;
  j["twist"] = json_number(e.twist);
  j["writhe"] = json_number(e.writhe);
  j["link"] = json_number(e.link);
  return j;
}

Json relax_json(const RelaxResult& r, const std::string& method) {
  const NewtonReport all = r.all_phases();
  Json j;
  j["status"] = to_string(r.status());
  j["converged"] = r.converged();
  j["stable"] = r.stable();
  j["iterations"] = r.report.iterations;
  j["total_iterations"] = all.iterations;
  j["seconds"] = json_number(all.seconds);
  j.update(energy_parts_json(r.energy));
  j["gradient_norm"] = json_number(r.report.gradient_norm);
  j["contacts"] = r.contacts;
  j["min_distance"] = json_number(r.min_distance);
  j["link"] = json_number(r.link);
  j["twist"] = json_number(r.twist);
  j["writhe"] = json_number(r.writhe);
  j["alexander_preserved"] = r.alexander_preserved;
  j["alexander"] = r.alexander.coefficients;
  j["model"] = to_string(r.model);
  j["vertices"] = r.positions.rows();
  j["smallest_eigenvalue"] = r.smallest_eigenvalue ? json_number(*r.smallest_eigenvalue) : Json(nullptr);
  j["method"] = method;
  j["phases"] = r.phases;
  j["report"] = newton_report_json(r.report);
  if (!r.coarse_reports.empty()) {
    j["coarse_reports"] = reports_json(r.coarse_reports);
    j["coarse_vertices"] = r.coarse_vertices;
  }
  if (!r.continuation_reports.empty()) j["continuation_reports"] = reports_json(r.continuation_reports);
  if (r.slab_report) {
    j["slab_report"] = newton_report_json(*r.slab_report);
    j["slab_energy"] = energy_parts_json(*r.slab_energy);
  }
  return j;
}

Json link_relax_json(const RelaxResult& r) {
  require(r.link_type.has_value(), "link_relax_json: a result of several components with its link type");
  Json j;
  j["components"] = r.component_sizes.size();
  j["vertices"] = r.positions.rows();
  j["status"] = to_string(r.status());
  j["iterations"] = r.report.iterations;
  j["seconds"] = json_number(r.report.seconds);
  j["energy"] = json_number(r.energy.total);
  j["gradient_norm"] = json_number(r.report.gradient_norm);
  j["min_distance"] = json_number(r.min_distance);
  Json alexander = Json::array();
  for (const AlexanderPolynomial& a : r.link_type->alexander) alexander.push_back(a.coefficients);
  j["alexander"] = alexander;
  j["linking_numbers"] = integer_matrix_json(r.link_type->linking_numbers);
  j["alexander_preserved"] = r.alexander_preserved;
  j["linking_preserved"] = r.linking_preserved;
  j["conway"] = r.link_type->conway.coefficients;
  j["conway_preserved"] = r.conway_preserved;
  return j;
}

}  // namespace ek
