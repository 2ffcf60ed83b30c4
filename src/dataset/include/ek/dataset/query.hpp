#pragma once
/// \file
/// Filtering and sorting the equilibria of a data set by their attributes,
/// as `knots query` does (and the Python module's Dataset.query()), on a
/// data set or on a ledger.
/// Attribute names as in docs/dataset-format.md ("Layout").
#include <optional>
#include <string>
#include <vector>

#include "ek/dataset/dataset_file.hpp"

namespace ek {

/// One filter, "ATTR<VALUE": the operators <, <=, >, >=, = (or ==) and !=.
struct QueryCondition {
  std::string attribute;  ///< the attribute's name (ATTR)
  std::string op;      ///< "<", "<=", ">", ">=", "=", "==" or "!="
  double value = 0.0;  ///< VALUE
  bool holds(double x) const;  ///< Whether `x` op `value` holds.
};
/// Parses "ATTR<VALUE" (InputError naming the text when malformed).
QueryCondition parse_query_condition(const std::string& text);

/// Which equilibria query_dataset() and query_ledger() return, and in which
/// order.
struct QueryOptions {
  std::optional<std::string> knot;   ///< only this knot type; none: every knot of the file
  /// "ATTR", "ATTR:asc" or "ATTR:desc"; empty: file order. The sort is stable.
  std::string sort;
  std::vector<std::string> where;    ///< conditions "ATTR<VALUE", all must hold
  std::optional<int> limit;          ///< [rows] at most this many rows, >= 0; none: all
};

/// One equilibrium of a query's result.
struct QueryRow {
  std::string knot;                  ///< the knot type's name
  int index = 0;                     ///< equilibrium index within the knot (0-based)
  std::vector<double> values;        ///< one per QueryResult::columns
};

/// The rows of a query and the names of their columns.
struct QueryResult {
  std::vector<std::string> columns;  ///< the attribute names (of the first knot read)
  std::vector<QueryRow> rows;        ///< the equilibria that pass, sorted and limited
};

/// The rows of the data set that pass every condition, sorted and limited.
/// InputError for an unknown attribute (listing the known ones), an unknown
/// knot, a malformed condition or sort, or a negative limit.
QueryResult query_dataset(const DatasetReader& reader, const QueryOptions& options);

struct Ledger;
/// The same over a ledger's equilibria (their attribute table: the rows and
/// indices of the data set the ledger was made from). InputError as above,
/// and for a knot the ledger does not hold.
QueryResult query_ledger(const Ledger& ledger, const QueryOptions& options);

}  // namespace ek
