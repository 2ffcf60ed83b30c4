#pragma once
/// \file
/// The KnotInfo knot table (C. Livingston and A. H. Moore, KnotInfo: Table of
/// Knot Invariants), as a CSV file: the unknot and the 2,977 prime knots with
/// up to 12 crossings (the table the paper's data set was computed on, paper
/// Section 7.4). Read from disk (see knot_table_path()); never copied.
///
/// Required columns: Name, DT Notation, PD Notation, Braid Notation, Crossing
/// Number, Bridge Index, Braid Index, Symmetry Type. Unknown values are '?'.
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ek/knots/codes.hpp"

namespace ek {

/// One knot type (one row of the table).
struct KnotRecord {
  std::string name;              ///< "3_1", "10_123", "12a_1019", "0_1" (unknot)
  int row = 0;                   ///< 1-based data row in the file (header is row 0)
  int crossing_number = 0;       ///< Column Crossing Number.
  std::optional<int> bridge_index;  ///< absent when the table says '?'
  std::optional<int> braid_index;  ///< Column Braid Index; absent when the table says '?'.
  /// Column Unknotting Number when present and a single integer (absent for '?' and ranges such as "[1;2]").
  std::optional<int> unknotting_number;
  std::optional<bool> alternating;  ///< Column Alternating ("Y"/"N") when present.
  std::string symmetry_type;        ///< "reversible", "chiral", ... ('' when unknown)
  std::optional<DTCode> dt;         ///< absent for the unknot
  std::optional<PDCode> pd;         ///< absent for the unknot
  std::optional<BraidWord> braid;   ///< the listed word with fewest strands; absent when unknown
  std::vector<BraidWord> braids;    ///< every word the table lists (KnotInfo gives two for some knots)
  std::map<std::string, std::string> fields;  ///< every column, verbatim
};

/// The knot table read from the KnotInfo CSV file: the records in file order
/// and a look-up by name.
class KnotTable {
 public:
  /// Loads and validates the table. Every problem (missing file, missing
  /// column, wrong number of fields, malformed number or code) throws
  /// InputError with one line naming the file, the row and the column.
  static KnotTable load(const std::string& path);
  /// The same from the file's text; `path` names the source in messages.
  static KnotTable parse(const std::string& text, const std::string& path);
  /// Loads the table at knot_table_path() once per process and returns it.
  static const KnotTable& global();

  /// The record of `name`; throws InputError("unknown knot ...") otherwise.
  /// Accepts the table's names and the aliases "unknot" and "0" for 0_1 (when no
  /// row has that name).
  const KnotRecord& at(const std::string& name) const;
  /// nullptr when the name is unknown.
  const KnotRecord* find(const std::string& name) const;
  /// All records in table order.
  const std::vector<KnotRecord>& records() const { return records_; }
  /// Records with the given crossing number, in table order.
  std::vector<const KnotRecord*> with_crossings(int crossing_number) const;
  /// Records with crossing number <= c, in table order (the unknot excluded
  /// unless include_unknot).
  std::vector<const KnotRecord*> up_to_crossings(int c, bool include_unknot = false) const;
  /// The file the table was read from (`path` of load() or parse()).
  const std::string& path() const { return path_; }
  size_t size() const { return records_.size(); }  ///< Number of records (rows).

 private:
  std::string path_;
  std::vector<KnotRecord> records_;
  std::map<std::string, size_t> by_name_;
};

}  // namespace ek
