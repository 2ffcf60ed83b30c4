#pragma once
// summary.json of exp_filters (docs/results.md, "filters"): for each
// attribute of the paper's filters (Section 7.3, Fig. 7) the equilibria of
// the data set with the smallest and the largest value.
#include <string>
#include <vector>

#include "json_fields.hpp"

namespace ek::results {

/// One drawn extreme.
struct FilterExtreme {
  std::string attribute;  ///< a stored attribute name (docs/dataset-format.md)
  std::string extreme;    ///< "min" or "max"
  std::string knot;
  int index = -1;         ///< equilibrium index (as `knots query` lists it)
  double value = 0.0;     ///< the stored value
  std::string curve;      ///< OBJ path relative to the folder
};
EK_JSON_FIELDS(FilterExtreme, attribute, extreme, knot, index, value, curve)

struct FiltersSummary {
  std::string scale;
  std::string dataset;                  ///< the data set read, relative to the results root ("dataset/dataset.h5")
  int knots = 0;                        ///< [1] knot types in it
  long equilibria = 0;                  ///< [1]
  std::vector<std::string> attributes;  ///< in the order of Section 7.3
  std::vector<FilterExtreme> extremes;  ///< min then max of each attribute, in that order
};
EK_JSON_FIELDS(FiltersSummary, scale, dataset, knots, equilibria, attributes, extremes)

}  // namespace ek::results
