#pragma once
// summary.json of exp_multistability (docs/results.md, "multistability"):
// scale, cut and planar_threshold, then one object per knot under the knot's
// name ("4_1", "7_7", "8_1").
#include <map>
#include <optional>
#include <string>

#include "json_fields.hpp"

namespace ek::results {

/// The distinct states of one knot.
struct KnotStates {
  long samples = 0;                          ///< [1] lattice samples relaxed
  long equilibria = 0;                       ///< [1] stable equilibria stored
  int distinct = 0;                          ///< [1] clusters at the cut
  int distinctly_3d = 0;                     ///< [1] clusters whose representative has 3D-ness >= planar_threshold
  double distinctly_3d_share = 0.0; ///< [1] distinctly_3d / distinct
};
EK_JSON_FIELDS(KnotStates, samples, equilibria, distinct, distinctly_3d, distinctly_3d_share)

struct MultistabilitySummary {
  std::string scale;
  double cut = 0.0;               ///< [1] kClusterCut
  double planar_threshold = 0.0;  ///< [1] kPlanarThreedim
  std::map<std::string, KnotStates> knots;  ///< by knot name
};

template <class BasicJsonType,
          ::nlohmann::detail::enable_if_t<::nlohmann::detail::is_basic_json<BasicJsonType>::value, int> = 0>
void to_json(BasicJsonType& j, const MultistabilitySummary& s) {
  j["scale"] = s.scale;
  j["cut"] = s.cut;
  j["planar_threshold"] = s.planar_threshold;
  for (const auto& [name, k] : s.knots) j[name] = k;
}

template <class BasicJsonType,
          ::nlohmann::detail::enable_if_t<::nlohmann::detail::is_basic_json<BasicJsonType>::value, int> = 0>
void from_json(const BasicJsonType& j, MultistabilitySummary& s) {
  read_field(j, "scale", s.scale);
  read_field(j, "cut", s.cut);
  read_field(j, "planar_threshold", s.planar_threshold);
  s.knots.clear();
  for (auto it = j.begin(); it != j.end(); ++it)
    if (it->is_object()) s.knots[it.key()] = it->template get<KnotStates>();
}

}  // namespace ek::results
