#pragma once
// JSON of saddle searches (`knots saddles`; docs/cli.md lists the keys, they
// are a contract).
#include "ek/transitions/saddles.hpp"
#include "output.hpp"

namespace ek::cli {

inline Json start_json(const SaddleStart& s) {
  Json j;
  j["start_energy"] = number(s.energy);
  j["start_gradient_norm"] = number(s.gradient_norm);
  j["energy_scale"] = number(s.energy_scale);
  std::vector<double> modes(s.mode_eigenvalues.data(), s.mode_eigenvalues.data() + s.mode_eigenvalues.size());
  j["mode_eigenvalues"] = modes;
  return j;
}

/// The distinct verified saddles: energy, barriers from the start (forward)
/// and from the other minimum (backward), also divided by EI/L (`scale`).
inline Json saddles_json(const std::vector<SaddleRecord>& records, double start_energy, double scale) {
  Json a = Json::array();
  for (size_t k = 0; k < records.size(); ++k) {
    const SaddleRecord& r = records[k];
    if (!r.verified || r.duplicate_of >= 0) continue;
    Json j;
    j["search"] = k;
    j["energy"] = number(r.energy);
    j["barrier"] = number(r.energy - start_energy);
    j["other_energy"] = number(r.minima[1].energy);
    j["start_similarity"] = number(r.minima[0].start_similarity);
    j["other_similarity"] = number(r.minima[1].start_similarity);
    j["barrier_forward"] = number(r.energy - start_energy);
    j["barrier_backward"] = number(r.energy - r.minima[1].energy);
    j["barrier_forward_scaled"] = number((r.energy - start_energy) / scale);
    j["barrier_backward_scaled"] = number((r.energy - r.minima[1].energy) / scale);
    j["negative_eigenvalue"] = number(r.negative_eigenvalue);
    j["second_eigenvalue"] = number(r.second_eigenvalue);
    j["index"] = r.index;
    j["gradient_norm"] = number(r.gradient_norm);
    Json minima = Json::array();
    for (const SaddleMinimum& m : r.minima) {
      Json mj;
      mj["energy"] = number(m.energy);
      mj["status"] = to_string(m.status);
      mj["gradient_norm"] = number(m.gradient_norm);
      mj["start_similarity"] = number(m.start_similarity);
      mj["images"] = m.images.size();
      mj["alexander_preserved"] = m.alexander_preserved;
      mj["link_preserved"] = m.link_preserved;
      minima.push_back(mj);
    }
    j["minima"] = minima;
    a.push_back(j);
  }
  return a;
}

/// Every search with its outcome; barrier, other_energy and start_similarity
/// are null unless both descents ran.
inline Json searches_json(const std::vector<SaddleRecord>& records, double start_energy) {
  Json a = Json::array();
  for (const SaddleRecord& r : records) {
    Json j;
    j["mode"] = r.mode;
    j["direction"] = r.direction;
    j["status"] = to_string(r.status);
    j["verified"] = r.verified;
    j["duplicate_of"] = r.duplicate_of;
    j["energy"] = number(r.energy);
    j["gradient_norm"] = number(r.gradient_norm);
    j["index"] = r.index;
    const bool descended = !r.minima[0].images.empty();
    j["barrier"] = descended ? number(r.energy - start_energy) : Json(nullptr);
    j["other_energy"] = descended ? number(r.minima[1].energy) : Json(nullptr);
    j["start_similarity"] = descended ? number(r.minima[0].start_similarity) : Json(nullptr);
    j["iterations"] = r.iterations;
    j["seconds"] = number(r.seconds);
    a.push_back(j);
  }
  return a;
}

}  // namespace ek::cli
