#pragma once
/// \file
/// Broad phase for edge-edge contact: all pairs of non-excluded edges whose
/// axis-aligned boxes overlap, by a uniform spatial hash (no O(n²) scan).
///
/// Boxes. Static: the box of edge i = [x_i, x_next(i)], inflated by `inflation`
/// on every side; with inflation = d/2 every pair of segments closer than d
/// has overlapping boxes (per axis, the gap of the boxes is at most the
/// distance). Swept (for collision detection): the box of the four points
/// x_i, x_next(i), x_i + dx_i, x_next(i) + dx_next(i), inflated the same way;
/// it contains the segment at every time of the linear motion x + s dx,
/// s ∈ [0, 1], so two segments whose swept boxes are farther apart than
/// 2·inflation never come that close.
///
/// Grid. Cell size h = twice the mean largest box side; every box is hashed
/// into the cells it overlaps (1 or 2 per axis for a typical box); a box wider
/// than 8 h on some axis is kept aside and tested against every box (so one very
/// large motion cannot blow up the grid). Pairs sharing a cell are tested, and
/// a pair is reported only in the cell that holds the lower corner of the
/// intersection of its boxes, so never twice. Expected cost O(n + pairs) for
/// curves whose edges have similar lengths. Output sorted by (a, b).
#include <cstdint>
#include <vector>

#include "ek/contact/topology.hpp"
#include "ek/geometry/types.hpp"

namespace ek {

/// A pair of edges a < b (edge i joins vertex i to topology.next(i)).
struct EdgePair {
  int a = -1;  ///< The edge of lower index.
  int b = -1;  ///< The edge of higher index.
  /// Same two edges.
  friend bool operator==(const EdgePair& p, const EdgePair& q) { return p.a == q.a && p.b == q.b; }
  friend bool operator!=(const EdgePair& p, const EdgePair& q) { return !(p == q); }  ///< Not the same two edges.
  /// Lexicographic order by (a, b).
  friend bool operator<(const EdgePair& p, const EdgePair& q) { return p.a < q.a || (p.a == q.a && p.b < q.b); }
};

/// Reusable broad phase for one topology (keeps its buffers between calls; not
/// safe to use from two threads at once).
class EdgeBroadPhase {
 public:
  /// excluded_neighbors: edges within this cyclic index distance on the same
  /// component are never reported (CurveTopology::excluded).
  EdgeBroadPhase(CurveTopology topology, int excluded_neighbors);

  /// Non-excluded pairs whose static boxes overlap (x: n by 3, n = topology's
  /// vertex count). The result stays valid until the next call.
  const std::vector<EdgePair>& static_pairs(const Points& x, double inflation);
  /// Non-excluded pairs whose swept boxes overlap (x, dx: n by 3).
  const std::vector<EdgePair>& swept_pairs(const Points& x, const Points& dx, double inflation);
  /// The pairs of `candidates` whose swept boxes overlap, in their order: when
  /// `candidates` holds every pair of swept_pairs(x, dx, inflation) (for
  /// example swept_pairs(x, dx, r) for some r >= inflation), the same list as
  /// swept_pairs(x, dx, inflation), in O(n + candidates) without the grid.
  const std::vector<EdgePair>& swept_subset(const std::vector<EdgePair>& candidates, const Points& x,
                                            const Points& dx, double inflation);

  const CurveTopology& topology() const { return topology_; }  ///< The components of the curves the broad phase is for.
  int excluded_neighbors() const { return excluded_; }  ///< Edges within this cyclic index distance are never reported.
  /// Endpoint of edge i other than i (= topology().next(i)).
  int edge_end(int i) const { return next_[static_cast<size_t>(i)]; }
  /// Same as topology().excluded(i, j, excluded_neighbors()), from tables.
  bool excluded(int i, int j) const;

 private:
  /// The grid: cell (v - origin) / h per axis, h = 1 / inv_h.
  struct Grid {
    double origin[3] = {0.0, 0.0, 0.0};  // [length] lower corner of all boxes
    double inv_h = 1.0;  // [1/length]
    int cell(double v, int k) const;  // cell coordinate of v >= origin[k] on axis k
  };
  // All non-excluded pairs of overlapping boxes of box_ into pairs_, sorted, in the steps below.
  void find_pairs();
  Grid grid_of_boxes() const;  // cell size: kCellScale times the mean largest box side
  size_t assign_cells(const Grid& grid);  // cell_lo_, cell_hi_, large_; returns the (box, cell) entry count
  void hash_entries(size_t total);  // entries_ grouped by hash bucket (counting sort)
  void pairs_in_cells(const Grid& grid, size_t total);  // raw_ += pairs sharing a cell, reported once
  void pairs_with_large_boxes();  // raw_ += large boxes against every box (large-large pairs once)
  void sort_pairs();  // pairs_ = raw_ sorted by (a, b)

  CurveTopology topology_;
  int excluded_;
  std::vector<int> next_, comp_, local_, size_;
  // scratch
  std::vector<double> box_;  // 6 per edge: lo xyz, hi xyz
  std::vector<int> cell_lo_, cell_hi_;  // 3 per edge
  std::vector<int> large_;
  std::vector<std::uint32_t> bucket_start_;
  struct Entry {
    int edge;
    int cx, cy, cz;
    std::uint32_t bucket;
  };
  std::vector<Entry> entries_;
  std::vector<std::uint32_t> entry_bucket_;
  std::vector<EdgePair> raw_, pairs_;
  std::vector<int> count_;
};

/// Brute-force references (O(n²), for tests): every non-excluded pair whose
/// static / swept boxes overlap, sorted. This one: the static boxes, as
/// EdgeBroadPhase::static_pairs().
std::vector<EdgePair> static_pairs_brute_force(const Points& x, const CurveTopology& topology, int excluded_neighbors,
                                               double inflation);
/// The swept boxes by testing every pair, as EdgeBroadPhase::swept_pairs()
/// (O(n²), for tests); sorted.
std::vector<EdgePair> swept_pairs_brute_force(const Points& x, const Points& dx, const CurveTopology& topology,
                                              int excluded_neighbors, double inflation);

/// All non-excluded edge pairs whose segment distance is below `distance`,
/// sorted (broad phase + exact distance).
std::vector<EdgePair> edge_pairs_within(const Points& x, const CurveTopology& topology, int excluded_neighbors,
                                        double distance);
/// The same by testing every pair (for tests).
std::vector<EdgePair> edge_pairs_within_brute_force(const Points& x, const CurveTopology& topology,
                                                    int excluded_neighbors, double distance);

}  // namespace ek
