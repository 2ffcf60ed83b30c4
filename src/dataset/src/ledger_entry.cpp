// The ledger of a data set (ledger.hpp): its knots' states at a cut. Apart
// from the file (ledger.cpp), which the parsers-only build reads without the
// pipeline.
#include "ek/dataset/ledger.hpp"
#include "ek/dataset/pipeline.hpp"

#include <filesystem>

#include "ek/analysis/unseen.hpp"
#include "ek/core/errors.hpp"

namespace ek {

LedgerEntry ledger_entry(const KnotEntry& k, double cut, int curves_per_knot) {
  LedgerEntry e;
  static_cast<KnotHeader&>(e) = k;
  for (const RunRecord& r : k.runs)
    e.runs.push_back({r.sample, r.status, r.equilibrium, r.iterations, r.seconds, r.alexander_preserved});
  e.attribute_names = k.attribute_names;
  e.attributes = k.attributes;
  e.linkage = k.linkage;
  if (k.equilibria.empty()) return e;
  const std::vector<StateCluster> clusters = clusters_at_cut(k, cut, &e.state);
  for (const StateCluster& c : clusters) {
    const bool kept = static_cast<int>(e.states.size()) < curves_per_knot;
    e.states.push_back({c.representative, static_cast<int>(c.members.size()),
                        kept ? k.equilibria[static_cast<size_t>(c.representative)] : Points(0, 3)});
  }
  return e;
}

Ledger ledger_of_dataset(const std::string& path, const LedgerProvenance& provenance) {
  const DatasetReader reader(path);
  Ledger out;
  out.parameters = reader.metadata();
  out.provenance = provenance;
  for (const std::string& name : reader.knot_names())
    out.entries.push_back(ledger_entry(reader.read(name), provenance.cut, provenance.curves_per_knot));
  return out;
}

std::vector<LedgerEntry> read_results_entries(const std::string& folder, double cut, std::string* source) {
  const std::string dataset = folder + "/dataset/dataset.h5", ledgers = folder + "/ledgers";
  std::vector<LedgerEntry> out;
  if (std::filesystem::exists(dataset)) {
    if (source) *source = dataset;
    const DatasetReader reader(dataset);
    for (const std::string& name : reader.knot_names()) out.push_back(ledger_entry(reader.read(name), cut, 0));
    return out;
  }
  if (!std::filesystem::is_directory(ledgers))
    throw InputError("neither a data set '" + dataset + "' nor a ledger folder '" + ledgers + "'");
  if (source) *source = ledgers;
  return read_ledger_folder(ledgers).entries;
}

UnseenEstimate ledger_unseen(const LedgerEntry& e, double energy_factor) {
  std::vector<int> counts;
  if (e.states.empty()) return estimate_unseen(counts);
  const int energy = e.attribute_column("energy");
  const double lowest = e.attributes.col(energy).minCoeff();
  for (const LedgerState& s : e.states)
    if (energy_factor <= 0.0 || e.attributes(s.representative, energy) <= energy_factor * lowest)
      counts.push_back(s.members);
  return estimate_unseen(counts);
}

}  // namespace ek
