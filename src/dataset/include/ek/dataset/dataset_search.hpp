#pragma once
/// \file
/// Searching a data set by attribute (the filters of paper Section 7.3,
/// Fig.\ 7: attribute_extremes) and by shape (below).
///
/// Cross-topology search over a data set (paper Section 8.2, "Cross-topology
/// analysis", Fig. 10; also Fig. 15's retrieval of knots close to 9_35's
/// three-circle state): "we first filter according to geometric attributes.
/// Among this pre-filtered set, we find the most similar embeddings using ICP
/// alignment".
///
///  1. Pre-filter: an equilibrium is aligned only when each attribute in
///     `filter_attributes` (stored columns of the data set, e.g. threedim,
///     diameter) lies in [v - w, v + w] around the query's value v (computed
///     from the query curve, ek::compute_attributes), with
///     w = max(filter_relative_width·|v|, filter_absolute_width).
///  2. Every remaining equilibrium is aligned to the query
///     (ek::align_curves: rigid motion, cyclic shift and orientation, ICP) and
///     ranked by the alignment distance (symmetric RMS closest-point distance
///     [length]); ties by the data set's knot order, then equilibrium index.
/// The ranking does not depend on `jobs`. The command `knots search` calls
/// this function (docs/cli.md). The links of a data set are not searched:
/// the alignment is that of one closed polygon (naming a link in
/// `only_knots` is an InputError).
#include <string>
#include <vector>

#include "ek/analysis/search.hpp"
#include "ek/dataset/dataset_file.hpp"

namespace ek {

/// Options of search_dataset().
struct DatasetSearchOptions {
  std::vector<std::string> exclude_knots;  ///< knot types not searched (e.g. the query's own)
  std::vector<std::string> only_knots;     ///< when not empty: search only these knot types
  /// Stored attributes of the pre-filter (empty: no pre-filter; step 1).
  std::vector<std::string> filter_attributes = {"threedim", "diameter"};
  double filter_relative_width = 0.5;   ///< [1] half-width of each range relative to the query's value
  double filter_absolute_width = 0.05;  ///< [attribute's unit] smallest half-width
  int max_results = 10;                 ///< [1] hits returned (0: every aligned equilibrium)
  AlignmentOptions alignment;           ///< ICP alignment of each candidate
  int jobs = 1;                         ///< [1] alignments in parallel threads

  /// Throws InputError for a negative width or max_results, jobs < 1 (and the alignment's own checks).
  void validate() const;
};

/// One ranked equilibrium of the data set.
struct DatasetHit {
  std::string knot;        ///< knot type
  int equilibrium = -1;    ///< row of the knot's equilibria (the index of `knots query`/`knots export`)
  double distance = 0.0;   ///< [length] alignment distance to the query
  Alignment alignment;     ///< moves the equilibrium onto the query (ek::aligned_candidate)
};

/// Result of search_dataset().
struct DatasetSearchResult {
  std::vector<DatasetHit> hits;  ///< by increasing distance, at most max_results
  int searched = 0;              ///< [1] equilibria of the searched knot types
  int aligned = 0;               ///< [1] of them, those that passed the pre-filter
};

/// One equilibrium of a data set and the value of an attribute.
struct AttributeExtreme {
  std::string knot;      ///< knot type
  int equilibrium = -1;  ///< row of the knot's equilibria (the index of `knots query`)
  double value = 0.0;    ///< the attribute's stored value
};

/// The equilibria of the whole data set with the smallest and the largest
/// value of a stored attribute (NaN values are skipped; ties: the first in
/// the file's knot order, then by index, which is what `knots query --sort
/// ATTR` and `--sort ATTR:desc` list first). Unknown attribute: InputError;
/// no finite value: InputError.
std::pair<AttributeExtreme, AttributeExtreme> attribute_extremes(const DatasetReader& reader,
                                                                 const std::string& attribute);

/// Searches every knot of the data set (minus the excluded ones) for the
/// equilibria closest to `query` (closed polygon, n by 3). Unknown names in
/// only_knots and unknown filter attributes are InputErrors.
DatasetSearchResult search_dataset(const DatasetReader& reader, const Points& query,
                                   const DatasetSearchOptions& options = {});

}  // namespace ek
