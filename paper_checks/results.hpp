#pragma once
// Reading the experiments' results files in the paper checks: summary.json
// as the experiment's summary struct (experiments/schema/*_summary.hpp, the
// same definition the experiment writes with), CSV tables as text.
#include <cstdlib>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "json_fields.hpp"
#include "thresholds.hpp"

namespace ek::paper {

/// Results folder of one experiment: $EK_PAPER_RESULTS/<experiment> when the
/// environment variable is set (`make claims` checks another scale's results),
/// otherwise the ci-scale fixtures' folder compiled in.
inline std::string results(const std::string& experiment) {
  const char* root = std::getenv("EK_PAPER_RESULTS");
  return std::string(root && *root ? root : EK_PAPER_RESULTS) + "/" + experiment;
}

/// The experiment's summary.json read as its struct, e.g.
/// summary<results::MilnorSummary>("milnor").
template <class Summary>
Summary summary(const std::string& experiment) {
  const std::string path = results(experiment) + "/summary.json";
  std::ifstream in(path);
  if (!in) throw std::runtime_error("missing " + path + " (did the experiment run?)");
  return ek::results::parse_summary<Summary>(nlohmann::json::parse(in), path);
}

/// A CSV flag cell: "true" or "false". Anything else throws.
inline bool flag(const std::string& cell) {
  if (cell == "true") return true;
  if (cell == "false") return false;
  throw std::runtime_error("CSV flag '" + cell + "': expected true or false");
}

/// A numeric CSV cell of `row` (as read by csv()) in `column`.
inline double number(const std::map<std::string, std::string>& row, const std::string& column) {
  return std::atof(row.at(column).c_str());
}

/// An optional measured value for printing: the value, or "n/a".
template <class T>
std::string or_na(const std::optional<T>& v) {
  if (!v) return "n/a";
  std::ostringstream s;
  s << *v;
  return s.str();
}

/// Rows of a CSV file with a header, as maps column -> text (every column
/// present: trailing empty cells as "").
inline std::vector<std::map<std::string, std::string>> csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("missing " + path);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> header;
  std::stringstream hs(line);
  for (std::string c; std::getline(hs, c, ',');) header.push_back(c);
  std::vector<std::map<std::string, std::string>> rows;
  while (std::getline(in, line)) {
    std::stringstream ls(line);
    std::map<std::string, std::string> row;
    size_t k = 0;
    for (std::string c; std::getline(ls, c, ',') && k < header.size(); ++k) row[header[k]] = c;
    for (; k < header.size(); ++k) row[header[k]] = "";  // trailing empty cells (getline drops the last)
    rows.push_back(row);
  }
  return rows;
}

}  // namespace ek::paper
