#include "ek/dataset/dataset_search.hpp"

#include <algorithm>
#include <cmath>

#include "ek/core/errors.hpp"
#include "ek/core/parallel.hpp"

namespace ek {

void DatasetSearchOptions::validate() const {
  require_input(filter_relative_width >= 0.0 && filter_absolute_width >= 0.0,
                "search: filter widths must be >= 0");
  require_input(max_results >= 0, "search: the number of results must be >= 0");
  require_input(jobs >= 1, "search: jobs must be >= 1");
  alignment.validate();
}

namespace {

struct Candidate {
  int order = 0;  // knot position in the file
  std::string knot;
  int equilibrium = 0;
  const Points* curve = nullptr;
};

}  // namespace

std::pair<AttributeExtreme, AttributeExtreme> attribute_extremes(const DatasetReader& reader,
                                                                 const std::string& attribute) {
  std::pair<AttributeExtreme, AttributeExtreme> out;
  bool found = false;
  for (const auto& name : reader.knot_names()) {
    const KnotEntry e = reader.read(name);
    const int col = e.attribute_column(attribute);
    for (Eigen::Index i = 0; i < e.attributes.rows(); ++i) {
      const double v = e.attributes(i, col);
      if (std::isnan(v)) continue;
      const AttributeExtreme x{name, static_cast<int>(i), v};
      if (!found || v < out.first.value) out.first = x;
      if (!found || v > out.second.value) out.second = x;
      found = true;
    }
  }
  require_input(found, "the data set has no equilibrium with a value of '" + attribute + "'");
  return out;
}

DatasetSearchResult search_dataset(const DatasetReader& reader, const Points& query, const DatasetSearchOptions& options) {
  options.validate();
  std::vector<std::string> names = reader.knot_names();
  for (const auto& k : options.only_knots)
    require_input(reader.has_knot(k), "search: the data set has no knot '" + k + "'");
  const Attributes qa = compute_attributes(query);
  for (const auto& name : options.filter_attributes)
    require_input(attribute_value(qa, name).has_value(),
                  "search: the pre-filter attribute '" + name + "' is not computed from a curve alone");
  const std::vector<AttributeRange> ranges =
      ranges_around(qa, options.filter_attributes, options.filter_relative_width, options.filter_absolute_width);
  DatasetSearchResult result;
  std::vector<KnotEntry> entries;
  std::vector<Candidate> candidates;
  for (const auto& name : names) {
    if (std::find(options.exclude_knots.begin(), options.exclude_knots.end(), name) != options.exclude_knots.end())
      continue;
    if (!options.only_knots.empty() &&
        std::find(options.only_knots.begin(), options.only_knots.end(), name) == options.only_knots.end())
      continue;
    KnotEntry e = reader.read(name);
    if (e.is_link()) {  // the query is one polygon; a link's equilibria are several
      require_input(options.only_knots.empty(), "search: " + name + " is a link; the search aligns one closed polygon");
      continue;
    }
    entries.push_back(std::move(e));
  }
  for (size_t k = 0; k < entries.size(); ++k) {
    const KnotEntry& e = entries[k];
    std::vector<int> columns;
    for (const auto& r : ranges) columns.push_back(e.attribute_column(r.name));
    for (size_t i = 0; i < e.equilibria.size(); ++i) {
      ++result.searched;
      bool keep = true;
      for (size_t f = 0; f < ranges.size(); ++f) {
        const double v = e.attributes(static_cast<Eigen::Index>(i), columns[f]);
        keep = keep && v >= ranges[f].min && v <= ranges[f].max;
      }
      if (keep) candidates.push_back({static_cast<int>(k), e.name, static_cast<int>(i), &e.equilibria[i]});
    }
  }
  result.aligned = static_cast<int>(candidates.size());
  std::vector<DatasetHit> hits(candidates.size());
  parallel_for(candidates.size(), options.jobs, [&](size_t q) {
    DatasetHit& h = hits[q];
    h.knot = candidates[q].knot;
    h.equilibrium = candidates[q].equilibrium;
    h.alignment = align_curves(query, *candidates[q].curve, options.alignment);
    h.distance = h.alignment.distance;
  });
  std::vector<size_t> order(hits.size());
  for (size_t q = 0; q < order.size(); ++q) order[q] = q;  // candidates are in knot order, then index
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return hits[a].distance < hits[b].distance; });
  if (options.max_results > 0 && order.size() > static_cast<size_t>(options.max_results))
    order.resize(static_cast<size_t>(options.max_results));
  for (size_t q : order) result.hits.push_back(hits[q]);
  return result;
}

}  // namespace ek
