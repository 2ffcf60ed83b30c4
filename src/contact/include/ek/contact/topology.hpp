#pragma once
/// \file
/// Closed polygonal components stored back to back in one Points array: a
/// knot has one component, a link several. Component c owns the vertices
/// starts[c] .. starts[c+1] − 1; edge v joins vertex v to next(v) (the
/// following vertex of its component, cyclically), so edges and vertices share
/// their indices, as for a single curve (types.hpp).
#include <vector>

namespace ek {

/// The components of curves stored back to back in one Points array (see the
/// file's description).
struct CurveTopology {
  /// Component offsets, size k + 1: starts.front() = 0, strictly increasing,
  /// starts.back() = number of vertices.
  std::vector<int> starts;

  /// One closed curve with n vertices.
  static CurveTopology single(int n);
  /// Components with the given vertex counts, in order.
  static CurveTopology from_sizes(const std::vector<int>& sizes);

  /// Number of vertices (= edges) of all components.
  int num_vertices() const { return starts.empty() ? 0 : starts.back(); }
  /// k, the number of components.
  int num_components() const { return starts.empty() ? 0 : static_cast<int>(starts.size()) - 1; }
  /// Component of vertex (or edge) v.
  int component(int v) const;
  /// Next and previous vertex of v within its component (cyclic).
  int next(int v) const;
  int prev(int v) const;  ///< Previous vertex of v within its component (cyclic).
  /// Whether edges i and j are excluded from contact with `neighbors`
  /// excluded neighbours: same component and cyclic index distance along it
  /// <= neighbors (i == j is always excluded). neighbors = 1 excludes exactly
  /// the edges that share a vertex. Edges of different components are never
  /// excluded.
  bool excluded(int i, int j, int neighbors) const;

  /// Throws std::invalid_argument unless starts is well formed and every
  /// component has at least 3 vertices.
  void validate() const;
};

}  // namespace ek
