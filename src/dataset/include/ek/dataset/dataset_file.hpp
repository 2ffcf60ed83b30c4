#pragma once
/// \file
/// The data-set file: one HDF5 file holds the equilibria of many knot types
/// (paper Section 7.4). Layout (docs/dataset-format.md documents it for users):
///
/// ~~~{.unparsed}
///   /                                  attributes: format = "elastic-knots-dataset", format_version = 2,
///                                      and one per field of metadata_fields() (metadata.hpp): material,
///                                      n, solver, sampling, lattice walk, seed, stiffness flag, provenance
///   knot_names          string  [k]    the knots, in table order
///   /knots/<name>/                     one group per knot type; attributes: name, crossing_number,
///                                      bridge_index, braid_index (-1 unknown), alexander (int list),
///                                      samples_used, adaptive (0/1), complete (0/1)
///     equilibria        float64 [m, n, 3]  the stored (converged) equilibria
///     attributes        float64 [m, k]     one row per equilibrium, columns named by
///     attribute_names   string  [k]
///     runs/             one entry per relaxation run (also failures), columns of length r:
///       sample int64, seed int64, status string, equilibrium int64 (-1: not stored),
///       iterations int64, seconds float64, energy float64, gradient_norm float64,
///       contacts int64, topology_preserved int64 (1/0), message string
///     similarity        float64 [m, m]     pairwise similarity (Section 7.1)
///     linkage           float64 [m-1, 4]   complete-linkage merges (a, b, height, size), SciPy layout
///     score_history     float64 [b]        adaptive-sampling importance score after each batch
/// ~~~
///
/// A link (several closed components) is stored in the same group layout:
/// its equilibria hold the components back to back ([m, n_0 + n_1 + ..., 3]);
/// the group attributes `components` (int list: n_c per component),
/// `conway` (∇'s coefficients) and `linking_numbers` (int list, m by m row by
/// row) say so; `alexander` is the unknot's; the attribute columns are
/// link_attribute_names() (pipeline.hpp); `similarity` is 1 − d, d the link
/// state distance (ek/analysis/link_states.hpp); the runs' `topology_preserved`
/// is 1 when every component's Alexander polynomial, every linking number and
/// ∇ were kept. A group without `components` is a knot.
///
/// Version 1 files read as version 2: their runs' column `alexander_preserved`
/// is `topology_preserved` (it held the whole check of a link already), and
/// a link's attribute `energy`, which was the elastic energy without the
/// contact part, is read with `energy_contact` added (the total, as a knot's).
///
/// Files are always written to a temporary name and renamed into place.
#include <cstdint>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include "ek/dataset/metadata.hpp"
#include "ek/geometry/link.hpp"
#include "ek/geometry/types.hpp"

namespace ek {

/// How a run ended: its relaxation's status (RelaxStatus: the solver's, or
/// TopologyChanged), or Error when the run threw (RunRecord::message says
/// why). Stored as text: "converged-stable", "converged-unstable",
/// "max-iterations", "stalled", "topology-changed", "error".
enum class RunStatus { ConvergedStable, ConvergedUnstable, MaxIterations, Stalled, TopologyChanged, Error };
std::string to_string(RunStatus status);  ///< the texts above
/// The status of a text written by to_string; InputError for any other text.
RunStatus parse_run_status(const std::string& text);
/// Prints to_string(status) (messages, test failures).
std::ostream& operator<<(std::ostream& out, RunStatus status);

/// One relaxation run (successful or not).
struct RunRecord {
  int sample = 0;                ///< index of the lattice sample within the knot
  std::uint64_t seed = 0;        ///< seed of the walk that produced it
  RunStatus status = RunStatus::Error;  ///< how it ended
  int equilibrium = -1;          ///< row in `equilibria`, -1 when not stored
  int iterations = 0;            ///< [1] Newton iterations of the relaxation
  double seconds = 0.0;          ///< [s]
  double energy = 0.0;           ///< [energy] at the result
  double gradient_norm = 0.0;    ///< [energy/length] ||g||₂ at the result
  int contacts = 0;              ///< [1] active contact pairs at the result
  /// The knot's type (its Alexander polynomial) or the link's (every
  /// component's polynomial, every linking number and ∇) kept.
  bool topology_preserved = true;
  std::string message;           ///< error text for failed runs
};

/// What names a knot type's entry and how it was sampled: the fields a data
/// set's entry and a ledger's (ledger.hpp) share, stored alike in both files
/// (the knot group's attributes and its score_history).
struct KnotHeader {
  std::string name;                           ///< the knot's (or link's) table name
  int crossing_number = 0;                    ///< [1] of the table
  int bridge_index = -1;                      ///< -1: unknown (and for links)
  int braid_index = -1;                       ///< -1: unknown (and for links)
  std::vector<std::int64_t> alexander;        ///< coefficients, lowest degree first
  bool adaptive = false;                      ///< sampled by the adaptive rule (ExploreOptions::adaptive)
  bool complete = true;                       ///< the attribute `complete` (0/1); the pipeline writes true
  int samples_used = 0;                       ///< [1] lattice samples relaxed for the entry
  std::vector<double> score_history;          ///< [1] adaptive score after each batch
  /// A link: each component's vertex count n_c, summing to the equilibria's
  /// rows (each component's rows in order); empty for a knot.
  std::vector<int> components;
  std::vector<std::int64_t> conway;           ///< a link's ∇ coefficients, lowest degree first (empty for a knot)
  std::vector<std::int64_t> linking_numbers;  ///< a link's m by m linking numbers, row by row (empty for a knot)

  bool is_link() const { return components.size() > 1; }  ///< A link: more than one component.
};

/// Everything stored for one knot type.
struct KnotEntry : KnotHeader {
  std::vector<Points> equilibria;                 ///< m curves, n by 3
  std::vector<std::string> attribute_names;       ///< k names
  Eigen::MatrixXd attributes;                     ///< m by k
  std::vector<RunRecord> runs;                    ///< every relaxation run, failures included
  Eigen::MatrixXd similarity;                     ///< m by m
  Eigen::MatrixXd linkage;                        ///< (m-1) by 4

  /// Equilibrium i as a link, one array per component (one component for a knot).
  Link equilibrium_link(int i) const;

  /// Column of an attribute, by name; throws InputError for an unknown name.
  int attribute_column(const std::string& attribute) const;
};

/// Streams knots into a new data-set file, written to "<path>.tmp.*" and
/// renamed onto `path` by commit(). Destroying an uncommitted writer removes
/// the temporary and leaves any existing file untouched. Every field of
/// `meta` must be set except those that may be "not recorded"
/// (WhenAbsent::NotRecorded, left out of the file); otherwise std::invalid_argument.
class DatasetWriter {
 public:
  /// Opens the temporary file next to `path` and writes `meta`; InputError when
  /// `path` cannot be written.
  DatasetWriter(const std::string& path, const DatasetMetadata& meta);
  ~DatasetWriter();  ///< Without commit(): removes the temporary file; an existing file at the path stays untouched.
  DatasetWriter(const DatasetWriter&) = delete;             ///< Not copyable.
  DatasetWriter& operator=(const DatasetWriter&) = delete;  ///< Not copyable.
  void add(const KnotEntry& knot);  ///< Writes one knot's group (its name must be new in the file).
  void commit();                    ///< Writes the knot list, seals the file and renames it onto `path`.

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Reads a data-set file. Every problem (not HDF5, wrong format, missing
/// fields) is an InputError naming the file. Attributes that files written
/// before them lack read as metadata_fields() says (a documented value, or
/// "not recorded").
class DatasetReader {
 public:
  /// Opens `path` and reads its metadata; InputError for a file that is not a
  /// data set.
  explicit DatasetReader(const std::string& path);
  ~DatasetReader();                              ///< Closes the file.
  DatasetReader(const DatasetReader&) = delete;  ///< Not copyable.
  DatasetReader& operator=(const DatasetReader&) = delete;  ///< Not copyable.
  const DatasetMetadata& metadata() const;       ///< The parameters the data set was computed with.
  std::vector<std::string> knot_names() const;   ///< in table order of the file
  bool has_knot(const std::string& name) const;  ///< Whether the file holds a group for `name`.
  KnotEntry read(const std::string& name) const;  ///< InputError if absent

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ek
