#include "ek/dataset/json.hpp"

#include "ek/dataset/dataset_search.hpp"

namespace ek {

Json clusters_json(const std::string& name, double cut, int equilibria, const std::vector<StateCluster>& clusters) {
  Json j;
  j["name"] = name;
  j["cut"] = cut;
  j["equilibria"] = equilibria;
  j["clusters"] = Json::array();
  for (const auto& c : clusters) {
    Json cj;
    cj["size"] = c.members.size();
    cj["representative"] = c.representative;
    cj["energy_min"] = json_number(c.energy_min);
    cj["energy_max"] = json_number(c.energy_max);
    cj["members"] = c.members;
    j["clusters"].push_back(cj);
  }
  return j;
}

Json query_json(const QueryResult& result) {
  Json j;
  j["rows"] = Json::array();
  for (const auto& r : result.rows) {
    Json rj;
    rj["knot"] = r.knot;
    rj["index"] = r.index;
    for (size_t c = 0; c < result.columns.size(); ++c) rj[result.columns[c]] = json_number(r.values[c]);
    j["rows"].push_back(rj);
  }
  j["count"] = result.rows.size();
  return j;
}

Json describe_json(const DatasetReader& reader) {
  Json j;
  j["parameters"] = Json::parse(reader.metadata().json());
  j["knots"] = reader.knot_names();
  return j;
}

Json closest_equilibrium_json(const DatasetReader* reader, const Points& x) {
  if (!reader) return nullptr;
  DatasetSearchOptions so;
  so.max_results = 1;
  const DatasetSearchResult r = search_dataset(*reader, x, so);
  if (r.hits.empty()) return nullptr;
  Json j;
  j["knot"] = r.hits[0].knot;
  j["index"] = r.hits[0].equilibrium;
  j["distance"] = json_number(r.hits[0].distance);
  return j;
}

}  // namespace ek
