#pragma once
// summary.json of exp_cross_topology (docs/results.md, "cross_topology"):
// for each query state, the equilibria of other knot types in the data set
// closest to it in shape (paper Section 8.2, Fig. 10).
#include <string>
#include <vector>

#include "json_fields.hpp"

namespace ek::results {

/// One ranked equilibrium of the data set.
struct CrossTopologyHit {
  int rank = 0;            ///< [1] 1-based
  std::string knot;
  int index = -1;          ///< equilibrium index in the data set (as `knots search` lists it)
  double distance = 0.0;   ///< [length] alignment distance to the query
  double energy = 0.0;     ///< [energy]
  double threedim = 0.0;   ///< [1]
  std::string curve;       ///< OBJ path relative to the folder, aligned onto the query
};
EK_JSON_FIELDS(CrossTopologyHit, rank, knot, index, distance, energy, threedim, curve)

/// One query state and its ranking.
struct CrossTopologyQuery {
  std::string knot;        ///< the query's knot type (excluded from its search)
  int equilibrium = -1;    ///< index in multistability.h5
  double energy = 0.0;     ///< [energy]
  double threedim = 0.0;   ///< [1]
  std::string curve;       ///< OBJ path relative to the folder (the stored curve)
  int searched = 0;        ///< [1] equilibria of the other knot types
  int aligned = 0;         ///< [1] of them, those that passed the pre-filter
  std::vector<CrossTopologyHit> hits;
};
EK_JSON_FIELDS(CrossTopologyQuery, knot, equilibrium, energy, threedim, curve, searched, aligned, hits)

struct CrossTopologySummary {
  std::string scale;
  std::string dataset;     ///< searched data set, relative to the results root ("dataset/dataset.h5")
  int limit = 0;           ///< [1] hits per query (`knots search --limit`)
  std::vector<std::string> filter_attributes;  ///< the pre-filter (ek::DatasetSearchOptions)
  double filter_relative_width = 0.0;          ///< [1]
  double filter_absolute_width = 0.0;
  std::vector<CrossTopologyQuery> queries;
};
EK_JSON_FIELDS(CrossTopologySummary, scale, dataset, limit, filter_attributes, filter_relative_width,
               filter_absolute_width, queries)

}  // namespace ek::results
