#pragma once
// Reading the experiments' results files in the paper checks.
#include <cstdlib>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

namespace ek::paper {

/// Results folder of one experiment: $EK_PAPER_RESULTS/<experiment> when the
/// environment variable is set (`make claims` checks another scale's results),
/// otherwise the ci-scale fixtures' folder compiled in.
inline std::string results(const std::string& experiment) {
  const char* root = std::getenv("EK_PAPER_RESULTS");
  return std::string(root && *root ? root : EK_PAPER_RESULTS) + "/" + experiment;
}

inline nlohmann::json summary(const std::string& experiment) {
  std::ifstream in(results(experiment) + "/summary.json");
  if (!in) throw std::runtime_error("missing " + results(experiment) + "/summary.json (did the experiment run?)");
  return nlohmann::json::parse(in);
}

/// Rows of a CSV file with a header, as maps column -> text.
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
    rows.push_back(row);
  }
  return rows;
}

}  // namespace ek::paper
