#pragma once
/// \file
/// Local-to-global assembly of sparse symmetric Hessians with a cached
/// sparsity pattern (conventions 5 and 7: one shared helper; the pattern is
/// built once per structure and then only filled with values).
///
/// Usage, once per Hessian evaluation:
/// ~~~{.cpp}
///   A.begin(dofs);
///   A.segment(0, rod_structure_id);      rod.add_hessian(A);
///   A.segment(1, contact_structure_id);  contact.add_hessian(A);
///   bool pattern_changed = A.end();
///   const auto& H = A.matrix();          // upper triangle, compressed
/// ~~~
///
/// A segment whose (id, structure) pair and sequence of add() calls is the
/// same as in the previous pass is replayed: each add() writes straight into
/// the stored value slot, with no allocation and no search. When a segment's
/// structure id changes (for example the contact set changed) the pattern is
/// rebuilt in end() and pattern_changed() is true, so that the solver redoes
/// its symbolic factorisation.
///
/// Only the upper triangle (row <= col) is stored, as CHOLMOD's stype = 1
/// expects; add() folds lower-triangle entries onto it, so local matrices are
/// passed whole.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <cstdint>
#include <vector>

namespace ek {

/// Assembles a sparse symmetric matrix (upper triangle) from local
/// contributions, replaying the cached sparsity pattern when the structure of
/// every segment is unchanged (see the file's description for the usage).
class SparseAssembler {
 public:
  using Index = int;  ///< Row and column index type of the assembled matrix.

  /// Starts a pass for a dofs-by-dofs matrix.
  void begin(Index dofs);
  /// Subsequent add() calls belong to segment `id` (0, 1, 2, ... in the same
  /// order every pass) whose sequence of positions is identified by `structure`.
  void segment(int id, std::uint64_t structure);
  /// Subsequent add() calls are shifted by `offset` rows and columns (a
  /// term over a block of the dofs, such as one component of a link, adds
  /// at its own indices); 0 by default and after begin().
  void set_offset(Index offset) { offset_ = offset; }
  /// Adds v at (i, j); stored at (min, max). Inline: the replay path (the
  /// common case) is one store into the cached value slot.
  void add(Index i, Index j, double v) {
    if (current_ >= 0) {
      Segment& s = segments_[static_cast<size_t>(current_)];
      if (s.replay && s.cursor < s.slots.size()) {
        ++total_;
        H_.valuePtr()[s.slots[s.cursor++]] += v;
        return;
      }
    }
    add_slow(i + offset_, j + offset_, v);
  }
  /// Adds a dense symmetric local matrix H at global indices idx (H is k by k,
  /// idx has k entries; negative indices are skipped).
  template <class Derived, class IndexArray>
  void add_local(const IndexArray& idx, const Eigen::MatrixBase<Derived>& H) {
    const Index k = static_cast<Index>(H.rows());
    for (Index a = 0; a < k; ++a) {
      if (idx[a] < 0) continue;
      for (Index b = a; b < k; ++b) {
        if (idx[b] < 0) continue;
        // off-diagonal local pairs appear twice in H; fold both onto one global entry
        const double v = (a == b) ? H(a, a) : H(a, b);
        if (idx[a] == idx[b] && a != b)
          add(idx[a], idx[b], 2.0 * v);
        else
          add(idx[a], idx[b], v);
      }
    }
  }
  /// Ends the pass; returns true when the sparsity pattern changed.
  bool end();

  /// The assembled matrix (upper triangle, compressed, column-major).
  const Eigen::SparseMatrix<double, Eigen::ColMajor, Index>& matrix() const { return H_; }
  /// Increases whenever the pattern changes.
  std::uint64_t pattern_version() const { return version_; }
  bool pattern_changed() const { return changed_; }  ///< Whether the last end() rebuilt the sparsity pattern.
  /// Number of entries added in the last pass (before folding duplicates).
  size_t entries() const { return total_; }

 private:
  struct Segment {
    int id = -1;
    std::uint64_t structure = 0;
    std::vector<Index> slots;                  // value slot of each add() (replay)
    std::vector<Eigen::Triplet<double, Index>> recorded;  // positions+values (record)
    size_t cursor = 0;
    size_t written = 0;  // adds written into slots before falling back to recording
    bool replay = false;
    bool has_slots = false;  // slots describe the current pattern (possibly empty)
    // adds written into slots this pass: a replayed segment's all, a segment
    // that fell back to recording those before it did
    size_t written_slots() const { return replay ? cursor : written; }
  };
  Index offset_ = 0;
  using Matrix = Eigen::SparseMatrix<double, Eigen::ColMajor, Index>;
  void add_slow(Index i, Index j, double v);
  // The steps of end(): whether every segment replayed its pattern whole; and
  // the rebuild of the pattern from the old one (`old`, H_ before the pass).
  bool all_replayed() const;
  // scratch_old_to_new_: 0 for the old slots written this pass, -1 for the others
  void mark_written_slots(Index old_nnz);
  // the recorded adds in the scratch_rec_* buffers, by column (counting sort); returns their count
  size_t bucket_recorded_by_column();
  // within each column by row, keeping call order (insertion sort: columns hold few adds)
  void sort_recorded_by_row();
  // H_ = the written old entries merged with the recorded adds; the new
  // position of each old slot (scratch_old_to_new_) and recorded call (scratch_call_pos_)
  void merge_patterns(const Matrix& old, size_t recorded);
  // every segment's slots in the new pattern; the recorded adds are dropped
  void assign_slots();
  Matrix H_;
  // end()'s rebuild buffers, kept between rebuilds (no allocation once grown)
  std::vector<Index> scratch_old_to_new_, scratch_rec_start_, scratch_next_, scratch_rec_row_, scratch_rec_call_,
      scratch_call_pos_, scratch_outer_, scratch_inner_;
  std::vector<double> scratch_rec_val_, scratch_values_;
  std::vector<Segment> segments_;
  int current_ = -1;
  int used_segments_ = 0;
  Index dofs_ = 0;
  std::uint64_t version_ = 0;
  bool changed_ = false;
  bool in_pass_ = false;
  bool replay_ok_ = true;
  size_t total_ = 0;
};

}  // namespace ek
