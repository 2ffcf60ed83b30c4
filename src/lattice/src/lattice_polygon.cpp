#include "ek/lattice/lattice_polygon.hpp"

#include <cmath>

#include "ek/core/errors.hpp"

namespace ek {

Points to_points(const LatticePoints& L) { return L.cast<double>(); }

LatticePolygonCheck check_lattice_polygon(const LatticePoints& L) {
  LatticePolygonCheck r;
  const Eigen::Index n = L.rows();
  if (n < 4) {
    r.problem = "a lattice polygon needs at least 4 vertices, got " + std::to_string(n);
    return r;
  }
  if (n >= kMaxLatticeLength) {
    r.problem = "lattice polygon too long (" + std::to_string(n) + " vertices)";
    return r;
  }
  SiteSet seen(static_cast<std::size_t>(n));
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::Index j = (i + 1) % n;
    const std::int64_t step = std::abs(std::int64_t{L(j, 0)} - L(i, 0)) + std::abs(std::int64_t{L(j, 1)} - L(i, 1)) +
                              std::abs(std::int64_t{L(j, 2)} - L(i, 2));
    if (step != 1) {
      r.problem = "edge " + std::to_string(i) + " is not a unit lattice step";
      return r;
    }
    if (!seen.insert(site_key(L(i, 0), L(i, 1), L(i, 2)))) {
      r.problem = "site of vertex " + std::to_string(i) + " (" + std::to_string(L(i, 0)) + ", " +
                  std::to_string(L(i, 1)) + ", " + std::to_string(L(i, 2)) + ") is repeated";
      return r;
    }
  }
  r.ok = true;
  return r;
}

bool as_lattice_polygon(const Points& P, LatticePoints* out) {
  require(out != nullptr, "as_lattice_polygon: null output");
  LatticePoints L(P.rows(), 3);
  for (Eigen::Index i = 0; i < P.rows(); ++i)
    for (int k = 0; k < 3; ++k) {
      const double v = P(i, k);
      if (!std::isfinite(v) || std::abs(v) > 1e9) return false;
      const double r = std::round(v);
      if (std::abs(v - r) > 1e-9) return false;
      L(i, k) = static_cast<std::int32_t>(r);
    }
  if (!check_lattice_polygon(L).ok) return false;
  *out = std::move(L);
  return true;
}

SiteSet::SiteSet(std::size_t expected_size) {
  std::size_t cap = 16;
  while (cap < 2 * expected_size) cap *= 2;
  rehash(cap);
}

void SiteSet::clear() {
  std::fill(table_.begin(), table_.end(), kEmpty);
  size_ = 0;
}

void SiteSet::rehash(std::size_t capacity) {
  std::vector<std::uint64_t> old;
  old.swap(table_);
  table_.assign(capacity, kEmpty);
  mask_ = capacity - 1;
  shift_ = 64;
  for (std::size_t c = capacity; c > 1; c >>= 1) --shift_;
  size_ = 0;
  for (std::uint64_t k : old)
    if (k != kEmpty) insert(k);
}

bool SiteSet::insert(std::uint64_t key) {
  if (2 * (size_ + 1) > table_.size()) rehash(2 * table_.size());
  std::size_t i = slot(key);
  for (;; i = (i + 1) & mask_) {
    const std::uint64_t k = table_[i];
    if (k == key) return false;
    if (k == kEmpty) break;
  }
  table_[i] = key;
  ++size_;
  return true;
}

bool SiteSet::erase(std::uint64_t key) {
  std::size_t i = slot(key);
  for (;; i = (i + 1) & mask_) {
    const std::uint64_t k = table_[i];
    if (k == key) break;
    if (k == kEmpty) return false;
  }
  // Backward-shift deletion: move later members of the probe run into the
  // hole whenever their home slot does not lie cyclically in (hole, j].
  std::size_t hole = i;
  for (std::size_t j = (i + 1) & mask_;; j = (j + 1) & mask_) {
    const std::uint64_t k = table_[j];
    if (k == kEmpty) break;
    const std::size_t home = slot(k);
    const bool home_in_range = hole <= j ? (home > hole && home <= j) : (home > hole || home <= j);
    if (!home_in_range) {
      table_[hole] = k;
      hole = j;
    }
  }
  table_[hole] = kEmpty;
  --size_;
  return true;
}

}  // namespace ek
