// The ledger of a data set (ledger.hpp): its knots' states at a cut. Apart
// from the file (ledger.cpp), which the parsers-only build reads without the
// pipeline.
#include "ek/dataset/ledger.hpp"
#include "ek/dataset/pipeline.hpp"

#include <algorithm>
#include <filesystem>

#include "ek/analysis/unseen.hpp"
#include "ek/core/errors.hpp"

namespace ek {

LedgerEntry ledger_entry(const KnotEntry& k, double cut, int curves_per_knot) {
  LedgerEntry e;
  static_cast<KnotHeader&>(e) = k;
  for (const RunRecord& r : k.runs)
    e.runs.push_back({r.sample, r.status, r.equilibrium, r.iterations, r.seconds, r.topology_preserved});
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
  ResultsKnots r = read_results_knots(folder, cut, false);
  if (source) *source = r.source;
  return std::move(r.entries);
}

int sampling_budget(const DatasetMetadata& parameters) {
  if (!parameters.sampling) return 0;
  const std::string& s = *parameters.sampling;
  std::string number;
  if (s.rfind("fixed:", 0) == 0) {
    number = s.substr(6);
  } else if (const size_t at = s.find(",max="); s.rfind("adaptive:", 0) == 0 && at != std::string::npos) {
    number = s.substr(at + 5);
  }
  const size_t digits = number.find_first_not_of("0123456789");
  number = number.substr(0, digits);
  if (number.empty()) throw InputError("unknown sampling '" + s + "': neither fixed:N nor adaptive:...,max=M");
  return std::stoi(number);
}

namespace {

/// The full-budget ledgers of a results folder, checked against it (read_results_knots).
void put_full_budget(const std::string& folder, ResultsKnots& r) {
  const Ledger extra = read_ledger_folder(folder);
  DatasetMetadata theirs = extra.parameters;
  if (!r.parameters.sampling)
    throw InputError("full-budget ledgers in '" + folder + "', but the scale's sampling is not recorded");
  const std::string& own = *r.parameters.sampling;  // the same walk: its burn-in too
  const size_t burn_in = own.find(",burn-in=");
  const std::string fixed = "fixed:" + std::to_string(r.budget) + (burn_in == std::string::npos ? "" : own.substr(burn_in));
  if (theirs.sampling != fixed)
    throw InputError("the full-budget ledgers in '" + folder + "' sample " + theirs.sampling.value_or("(unrecorded)") +
                     ", not " + fixed);
  theirs.sampling = r.parameters.sampling;
  if (const std::string d = r.parameters.difference(theirs); !d.empty())
    throw InputError("the full-budget ledgers in '" + folder + "' differ from the scale's: " + d);
  for (const LedgerEntry& e : extra.entries) {
    auto at = std::find_if(r.entries.begin(), r.entries.end(), [&](const LedgerEntry& x) { return x.name == e.name; });
    if (at == r.entries.end())
      throw InputError("knot " + e.name + " of the full-budget ledgers in '" + folder + "' is not in the scale");
    r.replaced.push_back(std::move(*at));
    *at = e;
  }
}

}  // namespace

ResultsKnots read_results_knots(const std::string& folder, double cut, bool full_budget) {
  const std::string dataset = folder + "/dataset/dataset.h5", ledgers = folder + "/ledgers";
  ResultsKnots r;
  if (std::filesystem::exists(dataset)) {
    r.source = dataset;
    const DatasetReader reader(dataset);
    r.parameters = reader.metadata();
    for (const std::string& name : reader.knot_names()) r.entries.push_back(ledger_entry(reader.read(name), cut, 0));
  } else if (std::filesystem::is_directory(ledgers)) {
    r.source = ledgers;
    Ledger l = read_ledger_folder(ledgers);
    r.parameters = std::move(l.parameters);
    r.entries = std::move(l.entries);
  } else {
    throw InputError("neither a data set '" + dataset + "' nor a ledger folder '" + ledgers + "'");
  }
  r.budget = sampling_budget(r.parameters);
  if (r.budget < 1)  // not recorded: the largest sample count stands for it
    for (const LedgerEntry& e : r.entries) r.budget = std::max(r.budget, static_cast<int>(e.runs.size()));
  const std::string extra = folder + "/full_budget";
  if (full_budget && !ledger_files(extra).empty()) put_full_budget(extra, r);
  return r;
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
