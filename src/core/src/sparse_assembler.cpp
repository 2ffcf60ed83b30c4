#include "ek/core/sparse_assembler.hpp"

#include <algorithm>
#include <stdexcept>

#include "ek/core/errors.hpp"

namespace ek {

void SparseAssembler::begin(Index dofs) {
  require(!in_pass_, "SparseAssembler::begin: previous pass not ended");
  require(dofs >= 0, "SparseAssembler::begin: negative size");
  in_pass_ = true;
  offset_ = 0;
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
  s.written = 0;
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
    // more entries than last time: the structure id lied; fall back to
    // recording (the adds so far are in their slots; end() keeps them)
    s.replay = false;
    s.written = s.slots.size();
    replay_ok_ = false;
  }
  s.recorded.emplace_back(i, j, v);
  ++s.cursor;
}

bool SparseAssembler::end() {
  require(in_pass_, "SparseAssembler::end: call begin() first");
  in_pass_ = false;
  if (all_replayed()) {
    changed_ = false;
    return false;
  }
  // Rebuild: a merge, column by column, of the old pattern's entries that
  // this pass wrote (the replayed segments' adds, summed in their slots; the
  // old matrix is sorted) with the recorded adds (sorted by column, row and
  // call). An entry's value is the old slot's sum, then the recorded adds in
  // call order: the left-to-right sum of every add in call order, as Eigen's
  // setFromTriplets gives. Cost O(nnz + n + recorded), no search.
  Matrix old;
  old.swap(H_);
  segments_.resize(static_cast<size_t>(used_segments_));
  mark_written_slots(static_cast<Index>(old.nonZeros()));
  const size_t recorded = bucket_recorded_by_column();
  sort_recorded_by_row();
  merge_patterns(old, recorded);
  assign_slots();
  ++version_;
  changed_ = true;
  return true;
}

bool SparseAssembler::all_replayed() const {
  bool all = replay_ok_ && used_segments_ == static_cast<int>(segments_.size());
  for (int k = 0; k < used_segments_ && all; ++k) {
    const Segment& s = segments_[static_cast<size_t>(k)];
    if (!s.replay || s.cursor != s.slots.size()) all = false;
  }
  return all;
}

void SparseAssembler::mark_written_slots(Index old_nnz) {
  std::vector<Index>& old_to_new = scratch_old_to_new_;  // -1: slot not written this pass
  old_to_new.assign(static_cast<size_t>(old_nnz), -1);
  for (const Segment& s : segments_)
    for (size_t k = 0; k < s.written_slots(); ++k) old_to_new[static_cast<size_t>(s.slots[k])] = 0;
}

size_t SparseAssembler::bucket_recorded_by_column() {
  size_t r = 0;
  for (const Segment& s : segments_)
    if (!s.replay) r += s.recorded.size();
  std::vector<Index>& rec_start = scratch_rec_start_;
  rec_start.assign(static_cast<size_t>(dofs_) + 1, 0);
  for (const Segment& s : segments_)
    if (!s.replay)
      for (const auto& t : s.recorded) ++rec_start[static_cast<size_t>(t.col()) + 1];
  for (Index c = 0; c < dofs_; ++c) rec_start[static_cast<size_t>(c) + 1] += rec_start[static_cast<size_t>(c)];
  std::vector<Index>& rec_row = scratch_rec_row_;    // by sorted position
  std::vector<Index>& rec_call = scratch_rec_call_;  // call number (over the recorded segments, in order)
  std::vector<double>& rec_val = scratch_rec_val_;
  rec_row.resize(r);
  rec_call.resize(r);
  rec_val.resize(r);
  std::vector<Index>& next = scratch_next_;
  next.assign(rec_start.begin(), rec_start.end() - 1);
  Index call = 0;
  for (const Segment& s : segments_)
    if (!s.replay)
      for (const auto& t : s.recorded) {
        const Index q = next[static_cast<size_t>(t.col())]++;
        rec_row[static_cast<size_t>(q)] = t.row();
        rec_call[static_cast<size_t>(q)] = call++;
        rec_val[static_cast<size_t>(q)] = t.value();
      }
  return r;
}

void SparseAssembler::sort_recorded_by_row() {
  const std::vector<Index>& rec_start = scratch_rec_start_;
  std::vector<Index>& rec_row = scratch_rec_row_;
  std::vector<Index>& rec_call = scratch_rec_call_;
  std::vector<double>& rec_val = scratch_rec_val_;
  for (Index c = 0; c < dofs_; ++c) {
    // stable by call already (filled in call order): sort by row, keeping it
    const Index lo = rec_start[static_cast<size_t>(c)], hi = rec_start[static_cast<size_t>(c) + 1];
    for (Index q = lo + 1; q < hi; ++q) {
      const Index rr = rec_row[static_cast<size_t>(q)], cc = rec_call[static_cast<size_t>(q)];
      const double vv = rec_val[static_cast<size_t>(q)];
      Index z = q;
      for (; z > lo && rec_row[static_cast<size_t>(z) - 1] > rr; --z) {
        rec_row[static_cast<size_t>(z)] = rec_row[static_cast<size_t>(z) - 1];
        rec_call[static_cast<size_t>(z)] = rec_call[static_cast<size_t>(z) - 1];
        rec_val[static_cast<size_t>(z)] = rec_val[static_cast<size_t>(z) - 1];
      }
      rec_row[static_cast<size_t>(z)] = rr;
      rec_call[static_cast<size_t>(z)] = cc;
      rec_val[static_cast<size_t>(z)] = vv;
    }
  }
}

void SparseAssembler::merge_patterns(const Matrix& old, size_t recorded) {
  const Index* old_outer = old.outerIndexPtr();
  const Index* old_inner = old.innerIndexPtr();
  const double* old_value = old.valuePtr();
  const Index old_nnz = static_cast<Index>(old.nonZeros());
  std::vector<Index>& old_to_new = scratch_old_to_new_;
  const std::vector<Index>& rec_start = scratch_rec_start_;
  const std::vector<Index>& rec_row = scratch_rec_row_;
  const std::vector<Index>& rec_call = scratch_rec_call_;
  const std::vector<double>& rec_val = scratch_rec_val_;
  std::vector<Index>& call_pos = scratch_call_pos_;  // new position of each recorded call
  call_pos.resize(recorded);
  std::vector<Index>& outer = scratch_outer_;
  std::vector<Index>& inner = scratch_inner_;
  std::vector<double>& values = scratch_values_;
  outer.assign(static_cast<size_t>(dofs_) + 1, 0);
  inner.clear();
  values.clear();
  inner.reserve(static_cast<size_t>(old_nnz) + recorded);
  values.reserve(static_cast<size_t>(old_nnz) + recorded);
  const Index old_cols = static_cast<Index>(old.outerSize());
  for (Index c = 0; c < dofs_; ++c) {
    Index p = c < old_cols ? old_outer[c] : 0, p_end = c < old_cols ? old_outer[c + 1] : 0;
    Index q = rec_start[static_cast<size_t>(c)];
    const Index q_end = rec_start[static_cast<size_t>(c) + 1];
    for (;;) {
      while (p < p_end && old_to_new[static_cast<size_t>(p)] < 0) ++p;  // slot not written: dropped
      const bool has_old = p < p_end, has_rec = q < q_end;
      if (!has_old && !has_rec) break;
      const Index row = !has_rec || (has_old && old_inner[p] <= rec_row[static_cast<size_t>(q)])
                            ? old_inner[p]
                            : rec_row[static_cast<size_t>(q)];
      const Index pos = static_cast<Index>(inner.size());
      double v;  // the first add's value, then the others added in call order
      if (has_old && old_inner[p] == row) {
        v = old_value[p];
        old_to_new[static_cast<size_t>(p++)] = pos;
      } else {
        v = rec_val[static_cast<size_t>(q)];
        call_pos[static_cast<size_t>(rec_call[static_cast<size_t>(q++)])] = pos;
      }
      for (; q < q_end && rec_row[static_cast<size_t>(q)] == row; ++q) {
        v += rec_val[static_cast<size_t>(q)];
        call_pos[static_cast<size_t>(rec_call[static_cast<size_t>(q)])] = pos;
      }
      inner.push_back(row);
      values.push_back(v);
    }
    outer[static_cast<size_t>(c) + 1] = static_cast<Index>(inner.size());
  }
  H_.resize(dofs_, dofs_);
  H_.resizeNonZeros(static_cast<Index>(inner.size()));
  std::copy(outer.begin(), outer.end(), H_.outerIndexPtr());
  std::copy(inner.begin(), inner.end(), H_.innerIndexPtr());
  std::copy(values.begin(), values.end(), H_.valuePtr());
}

void SparseAssembler::assign_slots() {
  const std::vector<Index>& old_to_new = scratch_old_to_new_;
  const std::vector<Index>& call_pos = scratch_call_pos_;
  Index call = 0;
  for (Segment& s : segments_) {
    const size_t w = s.written_slots();
    if (!s.replay) s.slots.resize(w + s.recorded.size());
    for (size_t k = 0; k < w; ++k) s.slots[k] = old_to_new[static_cast<size_t>(s.slots[k])];
    if (!s.replay) {
      for (size_t k = 0; k < s.recorded.size(); ++k) s.slots[w + k] = call_pos[static_cast<size_t>(call++)];
      s.recorded.clear();
      s.recorded.shrink_to_fit();
    } else {
      s.slots.resize(w);
    }
    s.has_slots = true;
    s.replay = false;
  }
}

}  // namespace ek
