// knots query DATASET [--knot NAME] [--sort ATTR[:asc|desc]] [--where 'ATTR<VALUE' ...] [--limit K] [--json]
#include <algorithm>
#include <cmath>
#include <iostream>

#include "args.hpp"
#include "commands.hpp"
#include "ek/core/errors.hpp"
#include "ek/dataset/dataset_file.hpp"
#include "output.hpp"

namespace ek::cli {
namespace {

struct Condition {
  std::string attribute, op;
  double value = 0.0;
  bool holds(double x) const {
    if (op == "<") return x < value;
    if (op == "<=") return x <= value;
    if (op == ">") return x > value;
    if (op == ">=") return x >= value;
    if (op == "=" || op == "==") return x == value;
    return x != value;  // "!="
  }
};

Condition parse_condition(const std::string& text) {
  for (const char* op : {"<=", ">=", "!=", "==", "<", ">", "="}) {
    const auto p = text.find(op);
    if (p == std::string::npos || p == 0) continue;
    Condition c;
    c.attribute = text.substr(0, p);
    c.op = op;
    c.value = parse_number(text.substr(p + std::string(op).size()), "--where '" + text + "'");
    return c;
  }
  throw InputError("--where '" + text + "': expected ATTR<VALUE (operators < <= > >= = !=)");
}

}  // namespace

int cmd_query(int argc, char** argv) {
  std::string file, sort;
  std::optional<std::string> knot;
  std::vector<std::string> where;
  std::optional<int> limit;
  bool json = false;
  ArgParser args("query", "DATASET [--knot NAME] [--sort ATTR[:asc|desc]] [--where 'ATTR<VALUE' ...] [--limit K] [--json]");
  args.positional("DATASET", &file, "data-set file");
  args.option("--knot", &knot, "only this knot type");
  args.option("--sort", &sort, "sort by an attribute, ascending (default) or :desc");
  args.option("--where", &where, "keep equilibria with ATTR<VALUE (also <=, >, >=, =, !=); repeatable");
  args.option("--limit", &limit, "print at most K rows");
  args.flag("--json", &json, "print one JSON object");
  if (!args.parse(argc, argv)) return 0;
  if (limit && *limit < 0) throw InputError("--limit must be >= 0");
  std::vector<Condition> conditions;
  for (const auto& w : where) conditions.push_back(parse_condition(w));
  std::string sort_attr = sort;
  bool descending = false;
  if (const auto colon = sort.find(':'); colon != std::string::npos) {
    sort_attr = sort.substr(0, colon);
    const std::string dir = sort.substr(colon + 1);
    if (dir != "asc" && dir != "desc") throw InputError("--sort '" + sort + "': direction must be asc or desc");
    descending = dir == "desc";
  }
  DatasetReader reader(file);
  std::vector<std::string> names = knot ? std::vector<std::string>{*knot} : reader.knot_names();
  struct Row {
    std::string knot;
    int index;
    std::vector<double> values;
  };
  std::vector<Row> rows;
  std::vector<std::string> columns;
  for (const auto& name : names) {
    const KnotEntry e = reader.read(name);
    if (columns.empty()) columns = e.attribute_names;
    std::vector<int> cond_cols;
    for (const auto& c : conditions) cond_cols.push_back(e.attribute_column(c.attribute));
    if (!sort_attr.empty()) e.attribute_column(sort_attr);
    for (Eigen::Index i = 0; i < e.attributes.rows(); ++i) {
      bool keep = true;
      for (size_t c = 0; c < conditions.size(); ++c)
        keep = keep && conditions[c].holds(e.attributes(i, cond_cols[c]));
      if (!keep) continue;
      Row r{name, static_cast<int>(i), {}};
      for (Eigen::Index c = 0; c < e.attributes.cols(); ++c) r.values.push_back(e.attributes(i, c));
      rows.push_back(std::move(r));
    }
  }
  if (!sort_attr.empty() && !columns.empty()) {
    const size_t col = static_cast<size_t>(std::find(columns.begin(), columns.end(), sort_attr) - columns.begin());
    // NaN (a value not computed) sorts last in both directions (a strict weak order)
    std::stable_sort(rows.begin(), rows.end(), [&](const Row& a, const Row& b) {
      const double x = a.values[col], y = b.values[col];
      if (std::isnan(x)) return false;
      if (std::isnan(y)) return true;
      return descending ? x > y : x < y;
    });
  }
  if (limit && rows.size() > static_cast<size_t>(*limit)) rows.resize(static_cast<size_t>(*limit));
  if (json) {
    Json j;
    j["rows"] = Json::array();
    for (const auto& r : rows) {
      Json rj;
      rj["knot"] = r.knot;
      rj["index"] = r.index;
      for (size_t c = 0; c < columns.size(); ++c) rj[columns[c]] = number(r.values[c]);
      j["rows"].push_back(rj);
    }
    j["count"] = rows.size();
    print_json(j);
    return 0;
  }
  std::cout << "knot        index";
  for (const auto& c : columns) std::cout << " " << c;
  std::cout << "\n";
  for (const auto& r : rows) {
    std::string k = r.knot;
    k.resize(std::max<size_t>(k.size(), 11), ' ');
    std::cout << k << " " << r.index;
    for (double v : r.values) std::cout << " " << fmt(v, 6);
    std::cout << "\n";
  }
  std::cout << rows.size() << " equilibria\n";
  return 0;
}

}  // namespace ek::cli
