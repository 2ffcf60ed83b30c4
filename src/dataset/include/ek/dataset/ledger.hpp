#pragma once
/// \file
/// The ledger: a data set's result, small enough to commit and read without
/// the data set (paper Section 7.4 builds the data set; Fig.\ 9 and the
/// planarity claim only need per-knot results). Per knot type it keeps the
/// runs (sample, status, stored row, iterations, seconds), every stored
/// equilibrium's attributes and its state, the complete-linkage dendrogram,
/// and for each distinct state at the ledger's cut its member count and its
/// representative's curve (for the lowest-energy states, up to a number per
/// knot); it drops the other curves and the m × m similarity matrix, which
/// hold almost all of a data set's bytes. A state whose curve is not kept
/// is reproduced by rerunning its representative's sample (the ledger's
/// parameters, the knot's name and representative_sample() determine it).
///
/// States are clusters_at_cut() (pipeline.hpp) at `cut`: sorted by
/// increasing lowest energy, represented by their lowest-energy member. The
/// dendrogram is kept, so the states at any coarser cut are unions of these,
/// and their representatives (the lowest-energy member of the union) are
/// among the stored curves.
///
/// File layout (docs/dataset-format.md, "Ledgers"): HDF5 with the data set's
/// checksum header; root attributes format = "elastic-knots-ledger",
/// format_version = 1, the data set's parameters (metadata_fields()) and the
/// provenance (LedgerProvenance); columnar tables over all knots of the file
/// (runs/, equilibria/, states/, curves/, each column one HDF5 dataset,
/// compressed; the curves as integer steps on a grid of `curve_quantum`),
/// and one group per knot under knots/ holding its scalar fields and its
/// rows of the tables.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "ek/dataset/dataset_file.hpp"
#include "ek/dataset/metadata.hpp"

namespace ek {

/// One relaxation run, as the ledger keeps it.
struct LedgerRun {
  int sample = 0;             ///< [1] index of the lattice sample within the knot
  RunStatus status = RunStatus::Error;  ///< RunRecord::status
  int equilibrium = -1;       ///< [1] row of the knot's attribute table, -1 when not stored
  int iterations = 0;         ///< [1]
  double seconds = 0.0;       ///< [s] wall time of the relaxation (one thread)
  bool topology_kept = true;  ///< RunRecord::topology_preserved
};

/// One distinct state at the ledger's cut.
struct LedgerState {
  int representative = -1;  ///< [1] row of the knot's attribute table: the member of lowest energy
  int members = 0;          ///< [1] stored equilibria in the state
  /// n by 3: the representative, each coordinate rounded to the nearest
  /// multiple of the ledger's curve_quantum (so within quantum / 2); empty
  /// (0 rows) when the ledger does not keep it (beyond curves_per_knot)
  Points curve;
};

/// The smallest, median and largest value of one attribute over a state's members.
struct AttributeSpread {
  ///@{
  /// The smallest, the median and the largest value.
  double min = 0.0, median = 0.0, max = 0.0;
  ///@}
};

/// One knot type (or link) of a ledger: the data set's header fields
/// (KnotHeader), then its results.
struct LedgerEntry : KnotHeader {
  std::vector<LedgerRun> runs;              ///< every relaxation run of the knot, failures included
  std::vector<std::string> attribute_names;  ///< k names (KnotEntry::attribute_names)
  Eigen::MatrixXd attributes;               ///< m by k: every stored equilibrium's attributes
  std::vector<int> state;                   ///< m: each equilibrium's state (index into `states`)
  Eigen::MatrixXd linkage;                  ///< (m−1) by 4: complete-linkage merges (a, b, height, size)
  std::vector<LedgerState> states;          ///< by increasing lowest energy

  int equilibria() const { return static_cast<int>(attributes.rows()); }  ///< m, the stored equilibria
  /// Column of an attribute by name; InputError naming the known ones otherwise.
  int attribute_column(const std::string& attribute) const;
  /// Runs that ended converged-stable.
  int stable_runs() const;
  /// Runs per status.
  std::map<RunStatus, int> status_counts() const;
  /// [s] summed relaxation time of the runs (one thread each).
  double run_seconds() const;
  /// min, median (the mean of the middle two for an even count) and max of
  /// attribute `column` over the members of state `s`.
  AttributeSpread spread(int s, int column) const;
  /// The rows of the attribute table in state `s`, increasing.
  std::vector<int> members(int s) const;
  /// The lattice sample whose relaxation is state `s`'s representative
  /// (rerunning it reproduces the curve); -1 when no run names it.
  int representative_sample(int s) const;
};

/// Where and how a ledger was made. Empty fields are "not recorded" (a
/// ledger made from an existing data set knows neither its wall time nor
/// the machine that ran it).
struct LedgerProvenance {
  double cut = 0.05;                   ///< [1] the states' cut in 1 − similarity
  /// [1] curves kept per knot: those of its lowest-energy states (the
  /// committed paper-scale ledgers, 645 knots with up to 256 states each,
  /// must stay within tens of MB)
  int curves_per_knot = 16;
  /// [length] the grid the kept curves' coordinates are rounded to (1e-4:
  /// within 5e-5 of the equilibrium, 1/4000 of the default wire radius)
  double curve_quantum = 1e-4;
  std::string commit;                  ///< source_commit() of the program that computed the runs
  std::string created;                 ///< ISO 8601 time the ledger was written
  std::string source;                  ///< what it summarises, e.g. "knots dataset --shard 3/20"
  std::optional<int> cores;            ///< [1] hardware threads of the machine
  std::optional<int> jobs;             ///< [1] worker threads of the run
  std::optional<double> wall_seconds;  ///< [s] the run's wall time
  std::optional<double> cpu_seconds;   ///< [s] the run's process CPU time (user + system)
};

/// A ledger: the data set's parameters, where and how it was made, and one
/// entry per knot (see the file's description).
struct Ledger {
  DatasetMetadata parameters;          ///< the data set's parameters (metadata.hpp)
  LedgerProvenance provenance;         ///< where and how it was made
  std::vector<LedgerEntry> entries;    ///< in the data set's order
};

/// The ledger entry of a data set's knot: its states at `cut`
/// (clusters_at_cut), the curves of the first `curves_per_knot` of them (by
/// energy; the others empty).
LedgerEntry ledger_entry(const KnotEntry& entry, double cut, int curves_per_knot);

/// The ledger of a whole data-set file at provenance.cut, keeping
/// provenance.curves_per_knot curves per knot, with `provenance`'s other fields.
Ledger ledger_of_dataset(const std::string& dataset_path, const LedgerProvenance& provenance);

/// The knots of a results folder (the experiments' layout) as ledger
/// entries: DIR/dataset/dataset.h5, each knot's states at `cut`, when it
/// exists; else the ledgers DIR/ledgers/*.ledger.h5 merged (their own cut).
/// `source` (optional) receives which was read. InputError when neither exists.
std::vector<LedgerEntry> read_results_entries(const std::string& folder, double cut, std::string* source = nullptr);

/// [samples] A data set's full sampling budget per knot: the fixed samples
/// ("fixed:N") or adaptive sampling's maximum ("adaptive:...,max=M,...");
/// 0 when the sampling is not recorded.
int sampling_budget(const DatasetMetadata& parameters);

/// A results folder's knots (read_results_entries) with their parameters,
/// and the full-budget entries of DIR/full_budget/*.ledger.h5 in place of
/// the folder's own. Those ledgers (scripts/ledger_far_end.sh) hold knots of
/// an adaptive scale sampled again at its full budget, with every other
/// parameter equal (so each knot's walk, and its first samples, are those of
/// the adaptive run): Fig.\ 9's far end is decided on them (far_end.hpp).
struct ResultsKnots {
  std::vector<LedgerEntry> entries;   ///< the folder's knots in its order, each full-budget entry in place
  DatasetMetadata parameters;         ///< the folder's parameters (its data set's or its ledgers')
  std::string source;                 ///< what was read: the data set, or the ledger folder
  /// [samples] sampling_budget(parameters), or, when the sampling is not
  /// recorded, the largest number of runs of a knot
  int budget = 0;
  std::vector<LedgerEntry> replaced;  ///< the folder's own entries that full-budget ones replaced
};

/// Reads a results folder as read_results_entries does; with `full_budget`,
/// also DIR/full_budget/ when it holds ledgers (*.ledger.h5). InputError when a
/// full-budget ledger's parameters differ from the folder's in anything but
/// the sampling, its sampling is not "fixed:<budget>", or it names a knot
/// the folder does not have.
ResultsKnots read_results_knots(const std::string& folder, double cut, bool full_budget);

/// Writes `ledger` to `path` (a temporary renamed into place: an existing
/// file is replaced only by a complete one). Each kept curve is stored as
/// its first vertex and its steps on the grid of provenance.curve_quantum
/// (integers: reading sums them back exactly). Throws InputError when the
/// file cannot be written, std::invalid_argument for an inconsistent ledger
/// (tables of different lengths, curves of different sizes, a quantum that
/// is not positive).
void write_ledger(const std::string& path, const Ledger& ledger);

/// Reads a ledger. A damaged file (checksum), another kind of file, a file
/// without the checksum header or any table that contradicts another is
/// refused with one InputError naming the file.
Ledger read_ledger(const std::string& path);

/// Whether `path` is a ledger (its root attribute `format`), checked
/// without reading its tables: false for a data set and for a path that does
/// not exist (the data-set reader then names it); InputError for a file that
/// is damaged or not HDF5.
bool is_ledger_file(const std::string& path);

/// The ledgers as one: equal parameters (DatasetMetadata::difference), cut
/// and curve quantum, each knot in one ledger only (InputError otherwise);
/// curves_per_knot is the largest of theirs. Entries keep
/// their order, ledger by ledger; the provenance keeps the cut and the
/// parameters, sums wall and CPU time where every ledger records them, and
/// lists the commits (comma-separated, each once) and sources.
Ledger merge_ledgers(const std::vector<Ledger>& ledgers);

/// The ledger files (*.ledger.h5) in `folder`, in name order; none when it is
/// not a folder. InputError when it cannot be read.
std::vector<std::string> ledger_files(const std::string& folder);

/// Every ledger file (*.ledger.h5) in `folder`, in name order, merged. InputError for none.
Ledger read_ledger_folder(const std::string& folder);

struct UnseenEstimate;  // ek/analysis/unseen.hpp

/// [1] "Low-energy" states for the unseen estimates: a representative's
/// energy at most this factor times the knot's lowest equilibrium energy.
inline constexpr double kLowEnergyFactor = 1.1;

/// What the knot's sampling has not seen yet (estimate_unseen, unseen.hpp),
/// from its states' member counts (a state's members are the samples that
/// relaxed into it); with `energy_factor` > 0 only the states whose
/// representative's energy is at most energy_factor times the knot's lowest
/// equilibrium energy, and their samples. Not in the parsers-only build.
UnseenEstimate ledger_unseen(const LedgerEntry& entry, double energy_factor = 0.0);

/// Whether `path` names ledgers: a folder (of ledgers) or a ledger file.
bool is_ledger_source(const std::string& path);
/// The ledger of a folder (read_ledger_folder) or of a ledger file (read_ledger).
Ledger read_ledger_source(const std::string& path);

}  // namespace ek
