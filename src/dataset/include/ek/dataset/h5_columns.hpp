#pragma once
/// \file
/// The one column codec of the project's HDF5 tables: a table is a group
/// holding one dataset per column, one row per record, and is described
/// once by a list of Column<Row, Context> that both the writer and the
/// reader walk in order (the order is the file's: datasets are created in
/// it). The data set's runs (dataset_file.hpp), the ledger's runs
/// (ledger.hpp) and every table of the transitions file
/// (ek/transitions/transitions_file.hpp) are written and read through it.
///
/// ~~~{.unparsed}
///   ColumnType  stored as
///   Int64       int64 [rows]           (integers and flags, 1/0)
///   Float64     float64 [rows]
///   Text        variable-length UTF-8 string [rows]
///   Curves      float64 [rows, n, 3]   (one curve of n vertices per row)
/// ~~~
#include <cstdint>
#include <functional>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "ek/core/errors.hpp"
#include "ek/core/types.hpp"
#include "ek/dataset/h5.hpp"

namespace ek::h5 {

/// How a column (or an attribute) is stored.
enum class ColumnType { Int64, Float64, Text, Curves };

/// One cell of a column, or an attribute's value; std::monostate: not
/// recorded (an optional value left out, or absent from the file).
using Cell = std::variant<std::monostate, std::int64_t, double, std::string, Points>;

/// The storage of a member of type T: integers and bool as Int64, double,
/// std::string, Points (curves).
template <class T>
constexpr ColumnType column_type_of() {
  if constexpr (std::is_same_v<T, double>) return ColumnType::Float64;
  else if constexpr (std::is_same_v<T, std::string>) return ColumnType::Text;
  else if constexpr (std::is_same_v<T, Points>) return ColumnType::Curves;
  else {
    static_assert(std::is_integral_v<T>, "columns are integers, flags, doubles, strings or curves");
    return ColumnType::Int64;
  }
}

/// The cell of a value (bool as 1/0, integers as int64).
template <class T>
Cell to_cell(const T& v) {
  if constexpr (std::is_same_v<T, bool>) return std::int64_t{v ? 1 : 0};
  else if constexpr (std::is_integral_v<T>) return static_cast<std::int64_t>(v);
  else return v;
}

/// The value of a cell of column_type_of<T>() stored in `out`.
template <class T>
void from_cell(Cell&& c, T& out) {
  if constexpr (std::is_same_v<T, bool>) out = std::get<std::int64_t>(c) != 0;
  else if constexpr (std::is_integral_v<T>) out = static_cast<T>(std::get<std::int64_t>(c));
  else out = std::get<T>(std::move(c));
}

/// What a column's value may depend on besides its row: nothing.
struct NoContext {};

/// One column of a table of Row records. `get` has the writer's context
/// (for columns derived from it); a column without `set` is derived from
/// others (written, required in the file, not read back).
template <class Row, class Context = NoContext>
struct Column {
  std::string name;                                 ///< the dataset's name in the table's group
  ColumnType type;                                  ///< how it is stored
  std::function<Cell(const Row&, const Context&)> get;  ///< a row's cell, written
  std::function<void(Row&, Cell&&)> set;            ///< stores a cell read into a row; empty: derived
};

/// The column that is the member `m` (of Row or of a base of it).
template <class Row, class Context = NoContext, class Class, class T>
Column<Row, Context> member_column(std::string name, T Class::*m) {
  return {std::move(name), column_type_of<T>(), [m](const Row& r, const Context&) { return to_cell(r.*m); },
          [m](Row& r, Cell&& c) { from_cell(std::move(c), r.*m); }};
}

/// A Float64 column derived from a row and the context (written only).
template <class Row, class Context = NoContext>
Column<Row, Context> derived_column(std::string name, std::function<double(const Row&, const Context&)> get) {
  return {std::move(name), ColumnType::Float64,
          [get = std::move(get)](const Row& r, const Context& c) { return Cell(get(r, c)); }, {}};
}

/// Writes `cells` as the column `name` of `g`, stored as `type` (every
/// curve of a Curves column with the same vertex count, else std::invalid_argument).
void write_cells(hid_t g, const std::string& name, ColumnType type, const std::vector<Cell>& cells);
/// The column `name` of `g` as cells of `type`; InputError naming it by
/// `where` ("states/energy") when it is missing, not one-dimensional or not
/// an array of curves.
std::vector<Cell> read_cells(hid_t g, const std::string& name, ColumnType type, const std::string& where);

/// Writes one dataset per column of `columns` into `g`, one row per record.
template <class Row, class Context>
void write_columns(hid_t g, const std::vector<Column<Row, Context>>& columns, const std::vector<Row>& rows,
                   const Context& context) {
  for (const Column<Row, Context>& c : columns) {
    std::vector<Cell> cells;
    cells.reserve(rows.size());
    for (const Row& r : rows) cells.push_back(c.get(r, context));
    write_cells(g, c.name, c.type, cells);
  }
}

/// The records of `g` (named `where` in errors): every column must be
/// there, all of one length (InputError "WHERE: column 'b' has 2 rows, 'a' 3").
template <class Row, class Context>
std::vector<Row> read_columns(hid_t g, const std::vector<Column<Row, Context>>& columns, const std::string& where) {
  std::vector<Row> rows;
  const Column<Row, Context>* first = nullptr;
  for (const Column<Row, Context>& c : columns) {
    if (!c.set) {  // derived: only required
      if (!exists(g, c.name)) throw InputError("the column '" + where + "/" + c.name + "' is missing");
      continue;
    }
    std::vector<Cell> cells = read_cells(g, c.name, c.type, where + "/" + c.name);
    if (!first) {
      first = &c;
      rows.resize(cells.size());
    } else if (cells.size() != rows.size()) {
      throw InputError(where + ": column '" + c.name + "' has " + std::to_string(cells.size()) + " rows, '" +
                       first->name + "' " + std::to_string(rows.size()));
    }
    for (size_t k = 0; k < cells.size(); ++k) c.set(rows[k], std::move(cells[k]));
  }
  return rows;
}

}  // namespace ek::h5
