#pragma once
/// \file
/// The parameters of a data set (the root attributes of its HDF5 file) as one
/// table, metadata_fields(): every field's attribute name, unit, how it is
/// compared, what a file written before the attribute existed reads as, and
/// its name in the journal key. The file's writer and reader, difference(),
/// journal_key(), text() and json() are all generated from it, so a
/// parameter added to the table is written, read, compared, journaled and
/// described at once. docs/dataset-format.md ("Parameters") lists it for users.
///
/// A parameter belongs in the table when it changes which equilibria a run
/// stores (material, n, solver, sampling, lattice walk, seed) or which
/// attributes it computes (the stiffness); such parameters must be equal for
/// a data set to be extended or merged.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace ek {

/// Parameters shared by every knot of a data set. Every field is empty until
/// set: dataset_metadata() (pipeline.hpp) sets all of them for a run, the
/// model's d̂, ω and tolerance from resolve_model(); DatasetReader leaves
/// empty the fields that an older file does not record (WhenAbsent::NotRecorded).
struct DatasetMetadata {
  // Physical and numerical parameters: must match to extend or merge.
  std::optional<double> young;              ///< [pressure] Young's modulus E
  std::optional<double> poisson;            ///< [1] Poisson ratio ν
  std::optional<double> radius;             ///< [length] wire radius r
  std::optional<int> vertices;              ///< [1] n, vertices per curve
  std::optional<double> edge_length;        ///< [length] rest edge length of the lattice samples
  std::optional<double> tolerance;          ///< [energy/length] gradient tolerance of the solver
  std::optional<double> contact_stiffness;  ///< [energy/length²] ω
  std::optional<double> dhat;               ///< [length] barrier distance d̂
  std::optional<std::string> twist_model;   ///< "twist-free", "free-theta" or "fixed-link"
  /// "multilevel" or "direct" (RelaxMethod), as relax() applies it: the
  /// multilevel method only for the twist-free model without a slab.
  std::optional<std::string> relax_method;
  std::optional<int> coarse_levels;         ///< [1] multilevel: coarse levels below n (direct: empty)
  /// [1] multilevel: continuation factors of the coarsest level (direct: empty).
  std::optional<std::vector<double>> coarse_continuation;
  /// Multilevel: how the coarse levels are found, to_string(CoarseningOptions)
  /// ("even", or e.g. "either-parity,recheck-30x6,min-100"); "even" for the direct
  /// method, which has no coarse levels (the value files before the field read as).
  std::optional<std::string> coarsening;
  std::optional<std::string> newton_hessian;  ///< NewtonOptions::hessian: "hybrid" or "exact"
  std::optional<bool> remove_rigid_motions;   ///< NewtonOptions::remove_rigid_motions
  /// The contact pairs' Hessian in the projected iterations:
  /// "eigen-projected" or "gauss-newton" (RelaxOptions::contact_gauss_newton).
  std::optional<std::string> contact_hessian;
  std::optional<bool> damp_short_steps;       ///< NewtonOptions::damp_short_steps
  std::optional<int> max_iterations;        ///< [1] Newton iterations per relaxation phase
  std::optional<int> burn_in;               ///< [samples] walk samples discarded before sample 0
  /// ExploreOptions::sampling_description(): "fixed:50" or
  /// "adaptive:50+10,max=500,S>0.1,delta=0.1", then ",burn-in=B" when B > 0.
  std::optional<std::string> sampling;
  std::optional<double> grow_fugacity;      ///< [1] BFACF β of the growth phase
  std::optional<double> shrink_fugacity;    ///< [1] BFACF β of the shrink phase
  std::optional<double> growth_factor;      ///< [1] the growth phase ends at growth_factor·n vertices
  std::optional<long long> decorrelation_moves;  ///< [moves] extra moves at the peak per sample
  std::optional<std::uint64_t> seed;        ///< run seed (each knot's walk seed derives from it)
  std::optional<bool> compute_stiffness;    ///< whether the stiffness attribute was computed
  /// [1] contact-stiffness continuation factors in (0, 1), in order; empty: off.
  std::optional<std::vector<double>> contact_continuation;
  // Provenance: describes the file, never compared.
  std::optional<std::string> project_version;  ///< version of the program that wrote the file (project_version())
  std::optional<std::string> knot_table;   ///< path of the knot table used
  std::optional<std::string> created;      ///< ISO 8601 time of the first write

  /// Empty when every physical and numerical field equals o's (doubles to a
  /// relative 1e-12; a field that either side does not record matches);
  /// otherwise the first difference in table order as one line: the field's
  /// name and both values, "radius 0.2 vs 0.1".
  std::string difference(const DatasetMetadata& o) const;
  /// Empties every field that `o` does not record: the metadata of a file
  /// that holds knots computed under both (a merge, an extended file).
  void forget_unrecorded(const DatasetMetadata& o);
  /// One line per field: name, value ("not recorded" when empty), [unit].
  std::string text() const;
  /// One JSON object: attribute name -> value (null when not recorded; the
  /// continuation as a list of numbers).
  std::string json() const;
};

/// A field's value, whatever the member's type: integers and flags as int64,
/// the seed as uint64, monostate when the field is empty (not recorded).
using FieldValue = std::variant<std::monostate, double, std::int64_t, std::uint64_t, std::string, std::vector<double>>;

/// How a field is compared when a data set is extended or merged.
enum class FieldMatch {
  Exact,       ///< equal values
  Relative,    ///< equal to a relative 1e-12
  Provenance,  ///< describes the file: never compared, not in the journal key
};

/// What a file without the field's attribute (written before it existed) reads as.
enum class WhenAbsent {
  Required,     ///< every file of format version 1 has it: InputError when missing
  Default,      ///< MetadataField::absent_value, the value every such file was computed with
  NotRecorded,  ///< empty ("not recorded"), which matches any value
};

/// The type of a field's value and its HDF5 attribute.
enum class FieldKind {
  Real,     ///< double; float64 attribute
  Integer,  ///< integer or flag (0/1); int64 attribute
  Unsigned, ///< unsigned 64-bit (the seed); int64 attribute with the same bits
  Text,     ///< string; variable-length UTF-8 string attribute
  List,     ///< numbers; a string attribute in continuation_text() form
};

/// One row of the table.
struct MetadataField {
  std::string name;          ///< HDF5 attribute, JSON key and the name in difference()
  std::string unit;          ///< "length", "1" (dimensionless), "" (text, flag or seed)
  FieldMatch match = FieldMatch::Exact;  ///< how the field is compared (difference())
  WhenAbsent absent = WhenAbsent::Required;  ///< what a file without the attribute reads as
  FieldValue absent_value;   ///< for WhenAbsent::Default
  std::string key;           ///< name in the journal key; empty: not in the key
  /// Left out of the journal key when the value equals this (the value that
  /// keys written before the field was added imply); monostate: always in it.
  FieldValue key_omitted;
  FieldKind kind = FieldKind::Real;                              ///< the value's type and its HDF5 attribute
  std::function<FieldValue(const DatasetMetadata&)> get;         ///< reads the field of a DatasetMetadata
  std::function<void(DatasetMetadata&, const FieldValue&)> set;  ///< writes the field of a DatasetMetadata
};

/// The table, in the order of difference(), text(), json() and the journal key.
const std::vector<MetadataField>& metadata_fields();

/// The text identifying a run's parameters in its journals: "young=2000
/// poisson=0.29999999999999999 ... stiffness=1", doubles with 17 significant
/// digits, fields in table order, each under its key name; empty fields and
/// those at their MetadataField::key_omitted value are left out, so the key
/// of a run with the parameters of earlier versions is the key they wrote.
std::string journal_key(const DatasetMetadata& meta);

/// The continuation factors as stored in the file's contact_continuation
/// attribute: "0.001,0.10000000000000001" (17 significant digits, so the text
/// reads back bit for bit); "" when off.
std::string continuation_text(const std::vector<double>& factors);

/// Parses continuation_text(); empty unless every factor is a number in (0, 1).
std::optional<std::vector<double>> parse_continuation(const std::string& text);

}  // namespace ek
