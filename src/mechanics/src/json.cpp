#include "ek/mechanics/json.hpp"

#include <algorithm>

#include "ek/analysis/attributes.hpp"
#include "ek/core/errors.hpp"

namespace ek {

Json knot_load_json(const KnotLoadOptions& o, const KnotLoadResult& r, const Json& start_match,
                    const std::vector<Json>& released_matches) {
  require(released_matches.size() == r.snaps.size(), "knot_load_json: one released match per snap");
  const auto& pts = r.path.points;
  const auto last = [&](double PathPoint::*field) { return pts.empty() ? Json(nullptr) : json_number(pts.back().*field); };
  Json j;
  j["load"] = to_string(o.kind);
  j["parameter"] = r.parameter_name;
  j["from"] = json_number(r.from);
  j["to"] = json_number(o.to);
  j["vertices"] = o.kind == LoadKind::Plates ? Json(nullptr) : Json(r.vertices);
  j["normal"] = o.kind == LoadKind::Plates ? Json({r.normal(0), r.normal(1), r.normal(2)}) : Json(nullptr);
  j["pull_stiffness"] = o.kind == LoadKind::Pull ? json_number(r.pull_stiffness) : Json(nullptr);
  j["status"] = to_string(r.path.status);
  j["points"] = pts.size();
  j["start_energy"] = json_number(r.start_energy);
  j["end_energy"] = last(&PathPoint::energy);
  j["end_parameter"] = last(&PathPoint::parameter);
  j["work"] = json_number(r.work);
  j["dissipated"] = json_number(r.dissipated);
  j["branch_jumps"] = r.branch_jumps;
  j["alexander_preserved"] = r.alexander_preserved;
  j["start_match"] = start_match;
  j["snaps"] = Json::array();
  for (size_t k = 0; k < r.snaps.size(); ++k) {
    const Snap& s = r.snaps[k];
    Json sj;
    sj["point"] = s.point;
    sj["parameter"] = json_number(s.parameter);
    sj["reaction"] = json_number(s.reaction);
    sj["jump"] = json_number(s.jump);
    sj["energy_drop"] = json_number(s.energy_drop);
    sj["loaded_energy"] = json_number(s.loaded_energy);
    sj["released_status"] = to_string(s.released_status);
    sj["released_energy"] = json_number(s.released_energy);
    sj["released_match"] = released_matches[k];
    j["snaps"].push_back(sj);
  }
  j["seconds"] = json_number(r.path.seconds);
  return j;
}

Json dynamics_json(const DynamicsOptions& o, const DynamicsResult& r, const Json& end_match, double seconds) {
  require(!r.frames.empty(), "dynamics_json: a run has its first frame");
  const DynamicsFrame &first = r.frames.front(), &last = r.frames.back();
  double max_threedim = 0.0;
  for (const DynamicsFrame& f : r.frames) max_threedim = std::max(max_threedim, threedim(f.positions));
  const auto total = [](const DynamicsFrame& f) { return f.kinetic + f.elastic + f.gravity; };
  Json j;
  j["model"] = to_string(r.model);
  j["link"] = o.model.link ? json_number(*o.model.link) : Json(nullptr);
  j["time_step"] = json_number(o.time_step);
  j["duration"] = json_number(o.duration);
  j["density"] = json_number(o.density);
  j["damping"] = json_number(o.damping);
  j["gravity"] = Json({o.gravity(0), o.gravity(1), o.gravity(2)});
  j["friction"] = json_number(o.friction);
  j["friction_velocity"] = json_number(o.friction_velocity);
  j["envelope"] = o.envelope ? json_number(o.envelope->half_thickness) : Json(nullptr);
  j["envelope_speed"] = json_number(o.envelope_speed);
  j["status"] = to_string(r.status);
  j["failed_status"] = r.failed_status ? Json(to_string(*r.failed_status)) : Json(nullptr);
  j["steps"] = r.steps;
  j["time"] = json_number(r.time);
  j["rest_time"] = r.rest_time ? json_number(*r.rest_time) : Json(nullptr);
  j["frames"] = r.frames.size();
  j["newton_iterations"] = r.newton_iterations;
  j["max_speed"] = json_number(r.max_speed);
  j["max_kinetic"] = json_number(r.max_kinetic);
  j["start_energy"] = json_number(first.elastic);
  j["end_energy"] = json_number(last.elastic);
  j["start_threedim"] = json_number(threedim(first.positions));
  j["end_threedim"] = json_number(threedim(last.positions));
  j["max_threedim"] = json_number(max_threedim);
  j["dissipated"] = json_number(total(first) - total(last));
  j["alexander_preserved"] = r.alexander_preserved;
  j["end_match"] = end_match;
  j["seconds"] = json_number(seconds);
  return j;
}

}  // namespace ek
