#include "ek/dataset/json.hpp"

#include <cmath>
#include <limits>
#include <map>
#include <sstream>

#include "ek/analysis/unseen.hpp"
#include "ek/dataset/dataset_search.hpp"
#include "ek/dataset/sampling_cost.hpp"
#include "ek/dataset/states.hpp"

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

namespace {

/// Runs per status, by the statuses' names (JSON keys).
std::map<std::string, int> status_texts(const std::map<RunStatus, int>& counts) {
  std::map<std::string, int> out;
  for (const auto& [status, count] : counts) out[to_string(status)] = count;
  return out;
}

template <class T>
Json optional_json(const std::optional<T>& v) {
  return v ? Json(*v) : Json(nullptr);
}

Json state_json(const LedgerEntry& e, int s) {
  const LedgerState& x = e.states[static_cast<size_t>(s)];
  Json j;
  j["members"] = x.members;
  j["representative"] = x.representative;
  for (size_t c = 0; c < e.attribute_names.size(); ++c) {
    const AttributeSpread a = e.spread(s, static_cast<int>(c));
    j[e.attribute_names[c]] = {{"value", json_number(e.attributes(x.representative, static_cast<Eigen::Index>(c)))},
                               {"min", json_number(a.min)},
                               {"median", json_number(a.median)},
                               {"max", json_number(a.max)}};
  }
  return j;
}


}  // namespace

Json ledger_json(const Ledger& l) {
  Json j;
  j["parameters"] = Json::parse(l.parameters.json());
  const LedgerProvenance& p = l.provenance;
  j["provenance"] = {{"cut", json_number(p.cut)},       {"commit", p.commit},
                     {"created", p.created},             {"source", p.source},
                     {"cores", optional_json(p.cores)},  {"jobs", optional_json(p.jobs)},
                     {"wall_seconds", optional_json(p.wall_seconds)},
                     {"cpu_seconds", optional_json(p.cpu_seconds)}};
  j["knots"] = Json::array();
  for (const LedgerEntry& e : l.entries) {
    Json k;
    k["name"] = e.name;
    k["crossing_number"] = e.crossing_number;
    k["bridge_index"] = e.bridge_index;
    k["braid_index"] = e.braid_index;
    k["samples_used"] = e.samples_used;
    k["stable"] = e.stable_runs();
    k["statuses"] = status_texts(e.status_counts());
    k["run_seconds"] = json_number(e.run_seconds());
    k["equilibria"] = e.equilibria();
    k["unseen"] = unseen_json(ledger_unseen(e));
    k["unseen_low_energy"] = unseen_json(ledger_unseen(e, kLowEnergyFactor));
    k["states"] = Json::array();
    for (int s = 0; s < static_cast<int>(e.states.size()); ++s) k["states"].push_back(state_json(e, s));
    j["knots"].push_back(k);
  }
  return j;
}

Json ledger_summary_json(const Ledger& l) {
  long equilibria = 0, states = 0, runs = 0;
  int links = 0;
  std::map<std::string, int> statuses;
  std::vector<KnotCost> costs;
  std::map<int, std::pair<int, long>> states_by_crossings;  // crossing number -> knots, states
  std::vector<double> p_new, p_new_low;
  double estimated = 0.0;
  for (const LedgerEntry& e : l.entries) {
    if (!e.states.empty()) {
      const UnseenEstimate u = ledger_unseen(e);
      p_new.push_back(u.new_state_probability);
      p_new_low.push_back(ledger_unseen(e, kLowEnergyFactor).new_state_probability);
      estimated += u.states;
    }
    equilibria += e.equilibria();
    states += static_cast<long>(e.states.size());
    runs += static_cast<long>(e.runs.size());
    for (const auto& [status, count] : e.status_counts()) statuses[to_string(status)] += count;
    if (e.is_link()) {
      ++links;
      continue;
    }
    costs.push_back({e.name, e.crossing_number, static_cast<int>(e.runs.size()), e.run_seconds()});
    auto& [knots, s] = states_by_crossings[e.crossing_number];
    ++knots;
    s += static_cast<long>(e.states.size());
  }
  Json j;
  j["knots"] = static_cast<long>(l.entries.size()) - links;
  j["links"] = links;
  j["equilibria"] = equilibria;
  j["states"] = states;
  j["runs"] = runs;
  j["statuses"] = statuses;
  j["wall_seconds"] = optional_json(l.provenance.wall_seconds);
  j["cpu_seconds"] = optional_json(l.provenance.cpu_seconds);
  if (!p_new.empty()) {
    j["estimated_states"] = json_number(estimated);
    j["median_new_state_probability"] = json_number(median_of(p_new));
    j["median_new_low_energy_state_probability"] = json_number(median_of(p_new_low));
  }
  if (costs.empty()) return j;
  const SamplingCost c = sampling_cost(costs, 500);
  j["median_samples"] = json_number(c.median_samples);
  j["mean_samples"] = json_number(static_cast<double>(c.samples) / c.knots);
  j["max_samples"] = c.max_samples;
  j["knots_at_500"] = c.knots_at_budget;
  j["stopped_before_500_share"] = json_number(1.0 - static_cast<double>(c.knots_at_budget) / c.knots);
  j["saving_vs_500"] = json_number(c.saving_vs_budget);
  j["run_core_seconds"] = json_number(c.run_seconds);
  j["by_crossing_number"] = Json::array();
  for (const CrossingCost& x : c.by_crossing_number) {
    const auto& [knots, s] = states_by_crossings.at(x.crossing_number);
    j["by_crossing_number"].push_back({{"crossing_number", x.crossing_number},
                                       {"knots", x.knots},
                                       {"median_samples", json_number(x.median_samples)},
                                       {"mean_samples", json_number(x.mean_samples)},
                                       {"seconds_per_run", json_number(x.seconds_per_run)},
                                       {"mean_states", json_number(static_cast<double>(s) / knots)}});
  }
  return j;
}

std::string ledger_text(const Ledger& l, bool states) {
  std::ostringstream out;
  const LedgerProvenance& p = l.provenance;
  const auto opt = [](const auto& v) { return v ? std::to_string(*v) : std::string("not recorded"); };
  out << l.parameters.text() << "ledger: cut " << p.cut << ", commit " << (p.commit.empty() ? "not recorded" : p.commit)
      << ", created " << p.created << ", cores " << opt(p.cores) << ", jobs " << opt(p.jobs) << ", wall s "
      << opt(p.wall_seconds) << ", CPU s " << opt(p.cpu_seconds) << "\nsource: " << p.source << "\n";
  for (const LedgerEntry& e : l.entries) {
    out << e.name << ": " << e.samples_used << " samples, " << e.stable_runs() << " stable, " << e.states.size()
        << " states";
    if (e.states.empty()) {
      out << "\n";
      continue;
    }
    const int energy = e.attribute_column("energy");
    const UnseenEstimate u = ledger_unseen(e);
    out << " (estimated " << std::lround(u.states) << ", " << std::lround(u.lower) << "–" << std::lround(u.upper)
        << "; next sample new " << u.new_state_probability << "), lowest energy "
        << e.attributes(e.states.front().representative, energy) << "\n";
    if (!states) continue;
    for (int s = 0; s < static_cast<int>(e.states.size()); ++s) {
      const AttributeSpread a = e.spread(s, energy);
      out << "  state " << s << ": " << e.states[static_cast<size_t>(s)].members << " members, energy "
          << e.attributes(e.states[static_cast<size_t>(s)].representative, energy) << " (" << a.min << " .. "
          << a.max << ")\n";
    }
  }
  return out.str();
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

Json unseen_json(const UnseenEstimate& u) {
  return {{"samples", u.samples},
          {"found", u.observed},
          {"estimated", json_number(u.states)},
          {"lower", json_number(u.lower)},
          {"upper", json_number(u.upper)},
          {"new_state_probability", json_number(u.new_state_probability)},
          {"good_turing", json_number(u.good_turing)}};
}

namespace {
PrefixUnseen entry_unseen(const KnotEntry& e, double cut) {
  return prefix_unseen(e, std::numeric_limits<int>::max(), cut, kLowEnergyFactor);
}
}  // namespace

Json entry_unseen_json(const KnotEntry& e, double cut) {
  const PrefixUnseen u = entry_unseen(e, cut);
  return {{"unseen", unseen_json(u.all)}, {"unseen_low_energy", unseen_json(u.low_energy)}};
}

Json entry_clusters_json(const KnotEntry& e, double cut) {
  Json j = clusters_json(e.name, cut, static_cast<int>(e.equilibria.size()), clusters_at_cut(e, cut));
  j.update(entry_unseen_json(e, cut));
  return j;
}

std::string entry_unseen_text(const KnotEntry& e, double cut) {
  const PrefixUnseen u = entry_unseen(e, cut);
  std::ostringstream s;
  s.precision(3);
  s << u.all.observed << " states found at cut " << cut << " (estimated " << std::lround(u.all.states) << ", "
    << std::lround(u.all.lower) << "–" << std::lround(u.all.upper) << "; next sample new "
    << u.all.new_state_probability << ", new and within " << kLowEnergyFactor << " of the lowest energy "
    << u.low_energy.new_state_probability << ")";
  return s.str();
}

}  // namespace ek
