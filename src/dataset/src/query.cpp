#include "ek/dataset/query.hpp"

#include <algorithm>

#include "ek/core/errors.hpp"
#include "ek/core/parse.hpp"
#include "ek/dataset/ledger.hpp"

namespace ek {
namespace {

/// (attribute, descending) of "ATTR[:asc|desc]".
std::pair<std::string, bool> parse_sort(const std::string& sort) {
  const auto colon = sort.find(':');
  if (colon == std::string::npos) return {sort, false};
  const std::string dir = sort.substr(colon + 1);
  if (dir != "asc" && dir != "desc") throw InputError("--sort '" + sort + "': direction must be asc or desc");
  return {sort.substr(0, colon), dir == "desc"};
}

}  // namespace

bool QueryCondition::holds(double x) const {
  if (op == "<") return x < value;
  if (op == "<=") return x <= value;
  if (op == ">") return x > value;
  if (op == ">=") return x >= value;
  if (op == "=" || op == "==") return x == value;
  return x != value;  // "!="
}

QueryCondition parse_query_condition(const std::string& text) {
  for (const char* op : {"<=", ">=", "!=", "==", "<", ">", "="}) {
    const auto p = text.find(op);
    if (p == std::string::npos || p == 0) continue;
    QueryCondition c;
    c.attribute = text.substr(0, p);
    c.op = op;
    c.value = parse_number(text.substr(p + std::string(op).size()), "--where '" + text + "'");
    return c;
  }
  throw InputError("--where '" + text + "': expected ATTR<VALUE (operators < <= > >= = !=)");
}

namespace {

/// The rows of the knots `names` (read one at a time by `read`, which gives
/// an entry with attribute_names, attributes and attribute_column) that pass
/// every condition, sorted and limited.
template <class Read>
QueryResult query_entries(const std::vector<std::string>& names, Read&& read, const QueryOptions& options) {
  if (options.limit && *options.limit < 0) throw InputError("--limit must be >= 0");
  std::vector<QueryCondition> conditions;
  for (const auto& w : options.where) conditions.push_back(parse_query_condition(w));
  const auto [sort_attr, descending] = parse_sort(options.sort);
  QueryResult result;
  for (const auto& name : names) {
    const auto& e = read(name);
    if (result.columns.empty()) result.columns = e.attribute_names;
    std::vector<int> cond_cols;
    for (const auto& c : conditions) cond_cols.push_back(e.attribute_column(c.attribute));
    if (!sort_attr.empty()) e.attribute_column(sort_attr);
    for (Eigen::Index i = 0; i < e.attributes.rows(); ++i) {
      bool keep = true;
      for (size_t c = 0; c < conditions.size(); ++c)
        keep = keep && conditions[c].holds(e.attributes(i, cond_cols[c]));
      if (!keep) continue;
      QueryRow r{name, static_cast<int>(i), {}};
      for (Eigen::Index c = 0; c < e.attributes.cols(); ++c) r.values.push_back(e.attributes(i, c));
      result.rows.push_back(std::move(r));
    }
  }
  if (!sort_attr.empty() && !result.columns.empty()) {
    const auto& cols = result.columns;
    const size_t col = static_cast<size_t>(std::find(cols.begin(), cols.end(), sort_attr) - cols.begin());
    const bool desc = descending;
    // NaN (a value not computed) sorts last in both directions (a strict weak order)
    std::stable_sort(result.rows.begin(), result.rows.end(), [&](const QueryRow& a, const QueryRow& b) {
      const double x = a.values[col], y = b.values[col];
      if (std::isnan(x)) return false;
      if (std::isnan(y)) return true;
      return desc ? x > y : x < y;
    });
  }
  if (options.limit && result.rows.size() > static_cast<size_t>(*options.limit))
    result.rows.resize(static_cast<size_t>(*options.limit));
  return result;
}

}  // namespace

QueryResult query_dataset(const DatasetReader& reader, const QueryOptions& options) {
  const std::vector<std::string> names = options.knot ? std::vector<std::string>{*options.knot} : reader.knot_names();
  KnotEntry entry;
  return query_entries(
      names, [&](const std::string& name) -> const KnotEntry& { return entry = reader.read(name); }, options);
}

QueryResult query_ledger(const Ledger& ledger, const QueryOptions& options) {
  std::vector<std::string> names;
  for (const LedgerEntry& e : ledger.entries) names.push_back(e.name);
  if (options.knot) {
    if (std::find(names.begin(), names.end(), *options.knot) == names.end())
      throw InputError("knot '" + *options.knot + "' is not in the ledger");
    names = {*options.knot};
  }
  return query_entries(
      names,
      [&](const std::string& name) -> const LedgerEntry& {
        return *std::find_if(ledger.entries.begin(), ledger.entries.end(),
                             [&](const LedgerEntry& e) { return e.name == name; });
      },
      options);
}

}  // namespace ek
