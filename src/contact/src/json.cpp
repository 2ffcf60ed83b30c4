#include "ek/contact/json.hpp"

namespace ek {

Json motion_check_json(const MotionCheck& m) {
  Json j;
  j["vertices"] = m.vertices;
  j["t"] = json_number(m.step.t);
  j["full_step"] = m.step.t >= 1.0;
  j["separation"] = json_number(m.separation);
  j["dhat"] = json_number(m.dhat);
  j["candidates"] = m.step.candidates;
  j["limiting_edges"] = m.step.edge_a >= 0 ? Json({m.step.edge_a, m.step.edge_b}) : Json(nullptr);
  j["clearance_start"] = json_number(m.clearance_start);
  j["clearance_at_t"] = json_number(m.clearance_at_t);
  j["clearance_end"] = json_number(m.clearance_end);
  j["min_clearance_sampled"] = json_number(m.min_clearance_sampled);
  return j;
}

}  // namespace ek
