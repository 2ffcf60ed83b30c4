#include "ek/dataset/h5_columns.hpp"

namespace ek::h5 {
namespace {

void write_curves(hid_t g, const std::string& name, const std::vector<Cell>& cells) {
  const hsize_t n = cells.empty() ? 0 : static_cast<hsize_t>(std::get<Points>(cells.front()).rows());
  std::vector<double> data;
  data.reserve(cells.size() * n * 3);
  for (const Cell& c : cells) {
    const Points& p = std::get<Points>(c);
    require(static_cast<hsize_t>(p.rows()) == n, "write_cells: the curves of column '" + name +
                                                     "' have different vertex counts");
    for (Eigen::Index i = 0; i < p.rows(); ++i)
      for (int a = 0; a < 3; ++a) data.push_back(p(i, a));
  }
  write_doubles(g, name, {static_cast<hsize_t>(cells.size()), n, 3}, data.data());
}

template <class T>
std::vector<T> values(const std::vector<Cell>& cells) {
  std::vector<T> out;
  out.reserve(cells.size());
  for (const Cell& c : cells) out.push_back(std::get<T>(c));
  return out;
}

}  // namespace

void write_cells(hid_t g, const std::string& name, ColumnType type, const std::vector<Cell>& cells) {
  switch (type) {
    case ColumnType::Int64: {
      const auto v = values<std::int64_t>(cells);
      write_int64(g, name, {v.size()}, v.data());
      break;
    }
    case ColumnType::Float64: {
      const auto v = values<double>(cells);
      write_doubles(g, name, {v.size()}, v.data());
      break;
    }
    case ColumnType::Text: write_strings(g, name, values<std::string>(cells)); break;
    case ColumnType::Curves: write_curves(g, name, cells); break;
  }
}

std::vector<Cell> read_cells(hid_t g, const std::string& name, ColumnType type, const std::string& where) {
  if (!exists(g, name)) throw InputError("the column '" + where + "' is missing");
  std::vector<hsize_t> shape;
  std::vector<Cell> out;
  const auto one_dimensional = [&] {
    if (shape.size() != 1) throw InputError("'" + where + "' is not a column");
  };
  switch (type) {
    case ColumnType::Int64:
      for (const std::int64_t v : read_int64(g, name, &shape)) out.emplace_back(v);
      one_dimensional();
      break;
    case ColumnType::Float64:
      for (const double v : read_doubles(g, name, &shape)) out.emplace_back(v);
      one_dimensional();
      break;
    case ColumnType::Text:
      for (std::string& v : read_strings(g, name)) out.emplace_back(std::move(v));
      break;
    case ColumnType::Curves: {
      const std::vector<double> data = read_doubles(g, name, &shape);
      if (shape.size() != 3 || shape[2] != 3) throw InputError("'" + where + "' is not an array of curves");
      size_t k = 0;
      for (hsize_t j = 0; j < shape[0]; ++j) {
        Points p(static_cast<Eigen::Index>(shape[1]), 3);
        for (Eigen::Index i = 0; i < p.rows(); ++i)
          for (int a = 0; a < 3; ++a) p(i, a) = data[k++];
        out.emplace_back(std::move(p));
      }
      break;
    }
  }
  return out;
}

}  // namespace ek::h5
