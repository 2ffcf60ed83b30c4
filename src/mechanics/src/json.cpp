#include "ek/mechanics/json.hpp"

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
    sj["released_status"] = s.released_status;
    sj["released_energy"] = json_number(s.released_energy);
    sj["released_match"] = released_matches[k];
    j["snaps"].push_back(sj);
  }
  j["seconds"] = json_number(r.path.seconds);
  return j;
}

}  // namespace ek
