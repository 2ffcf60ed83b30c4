#include "ek/core/sparse_assembler.hpp"

#include <algorithm>
#include <stdexcept>

#include "ek/core/errors.hpp"

namespace ek {

void SparseAssembler::begin(Index dofs) {
  require(!in_pass_, "SparseAssembler::begin: previous pass not ended");
  require(dofs >= 0, "SparseAssembler::begin: negative size");
  in_pass_ = true;
  replay_ok_ = (dofs == dofs_ && H_.rows() == dofs);
  dofs_ = dofs;
  current_ = -1;
  used_segments_ = 0;
  total_ = 0;
  if (replay_ok_) std::fill(H_.valuePtr(), H_.valuePtr() + H_.nonZeros(), 0.0);
}

void SparseAssembler::segment(int id, std::uint64_t structure) {
  require(in_pass_, "SparseAssembler::segment: call begin() first");
  require(id == used_segments_, "SparseAssembler::segment: segments must be numbered 0, 1, 2, ... in order");
  if (static_cast<int>(segments_.size()) <= id) segments_.resize(static_cast<size_t>(id) + 1);
  Segment& s = segments_[static_cast<size_t>(id)];
  const bool same = replay_ok_ && s.id == id && s.structure == structure && s.has_slots;
  s.id = id;
  s.structure = structure;
  s.cursor = 0;
  s.replay = same;
  if (!same) {
    replay_ok_ = false;
    s.recorded.clear();
  }
  current_ = id;
  ++used_segments_;
}

void SparseAssembler::add_slow(Index i, Index j, double v) {
  if (current_ < 0) segment(0, 0);
  if (i > j) std::swap(i, j);
  Segment& s = segments_[static_cast<size_t>(current_)];
  ++total_;
  if (s.replay) {
    if (s.cursor < s.slots.size()) {
      H_.valuePtr()[s.slots[s.cursor++]] += v;
      return;
    }
    // more entries than last time: the structure id lied; fall back to recording
    s.replay = false;
    replay_ok_ = false;
  }
  s.recorded.emplace_back(i, j, v);
  ++s.cursor;
}

bool SparseAssembler::end() {
  require(in_pass_, "SparseAssembler::end: call begin() first");
  in_pass_ = false;
  bool all_replayed = replay_ok_ && used_segments_ == static_cast<int>(segments_.size());
  for (int k = 0; k < used_segments_ && all_replayed; ++k) {
    const Segment& s = segments_[static_cast<size_t>(k)];
    if (!s.replay || s.cursor != s.slots.size()) all_replayed = false;
  }
  if (all_replayed) {
    changed_ = false;
    return false;
  }
  // Rebuild: every segment must be available as positions + values. Segments
  // that were replayed this pass are re-recorded from their slots.
  std::vector<Eigen::Triplet<double, Index>> all;
  const Eigen::SparseMatrix<double, Eigen::ColMajor, Index> old = H_;
  std::vector<Index> slot_row, slot_col;
  if (old.nonZeros() > 0) {
    slot_row.resize(static_cast<size_t>(old.nonZeros()));
    slot_col.resize(static_cast<size_t>(old.nonZeros()));
    for (Index c = 0; c < old.outerSize(); ++c)
      for (Index p = old.outerIndexPtr()[c]; p < old.outerIndexPtr()[c + 1]; ++p) {
        slot_row[static_cast<size_t>(p)] = old.innerIndexPtr()[p];
        slot_col[static_cast<size_t>(p)] = c;
      }
  }
  segments_.resize(static_cast<size_t>(used_segments_));
  // Values of replayed segments live in H_ (summed together). Collect them as
  // one block of triplets from the old matrix restricted to the slots used by
  // replayed segments, then add the recorded segments.
  std::vector<char> slot_used(static_cast<size_t>(old.nonZeros()), 0);
  for (const Segment& s : segments_)
    if (s.replay)
      for (size_t k = 0; k < s.cursor; ++k) slot_used[static_cast<size_t>(s.slots[k])] = 1;
  for (size_t p = 0; p < slot_used.size(); ++p)
    if (slot_used[p]) all.emplace_back(slot_row[p], slot_col[p], old.valuePtr()[p]);
  for (const Segment& s : segments_)
    if (!s.replay) all.insert(all.end(), s.recorded.begin(), s.recorded.end());
  H_.resize(dofs_, dofs_);
  H_.setFromTriplets(all.begin(), all.end());
  H_.makeCompressed();
  // Slots for every segment's positions in the new pattern.
  auto find_slot = [this](Index i, Index j) {
    const Index* begin = H_.innerIndexPtr() + H_.outerIndexPtr()[j];
    const Index* end = H_.innerIndexPtr() + H_.outerIndexPtr()[j + 1];
    const Index* it = std::lower_bound(begin, end, i);
    return static_cast<Index>(it - H_.innerIndexPtr());
  };
  for (Segment& s : segments_) {
    std::vector<Index> slots;
    if (s.replay) {
      slots.reserve(s.cursor);
      for (size_t k = 0; k < s.cursor; ++k) {
        const Index p = s.slots[k];
        slots.push_back(find_slot(slot_row[static_cast<size_t>(p)], slot_col[static_cast<size_t>(p)]));
      }
    } else {
      slots.reserve(s.recorded.size());
      for (const auto& t : s.recorded) slots.push_back(find_slot(t.row(), t.col()));
      s.recorded.clear();
      s.recorded.shrink_to_fit();
    }
    s.slots = std::move(slots);
    s.has_slots = true;
    s.replay = false;
  }
  ++version_;
  changed_ = true;
  return true;
}

}  // namespace ek
