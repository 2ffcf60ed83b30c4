#pragma once
/// \file
/// Polygons on the simple cubic lattice Z³ (paper Section 5, Fig.\ 4).
///
/// A lattice polygon with n vertices is an n by 3 array of integers, one site
/// per row; edge i joins site i to site (i + 1) mod n and has length 1 (the
/// two sites differ by ±1 in exactly one coordinate). It is self-avoiding when
/// no site occurs twice. Lattice polygons have an even number of vertices
/// (every coordinate returns to its start) and at least 4.
#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "ek/geometry/types.hpp"

namespace ek {

/// n by 3 integer sites, row-major (same layout as Points).
using LatticePoints = Eigen::Matrix<std::int32_t, Eigen::Dynamic, 3, Eigen::RowMajor>;

/// The sites as doubles (exact), for curve files and the other modules.
Points to_points(const LatticePoints& L);

/// Result of check_lattice_polygon().
struct LatticePolygonCheck {
  bool ok = false;      ///< Whether L is a closed self-avoiding lattice polygon.
  std::string problem;  ///< empty when ok, otherwise one line naming the first defect
};

/// Whether L is a closed self-avoiding lattice polygon: n >= 4, every edge
/// (including the closing one) a unit lattice step, no repeated site.
/// O(n) expected time (hash set).
LatticePolygonCheck check_lattice_polygon(const LatticePoints& L);

/// The sites of P when P is exactly a lattice polygon (integer coordinates
/// within 1e-9, unit steps, self-avoiding); returns false and leaves `out`
/// untouched otherwise.
bool as_lattice_polygon(const Points& P, LatticePoints* out);

/// Packs a site into 63 bits: each coordinate modulo 2^21 in its own 21-bit
/// field. Two sites of one polygon of fewer than 2^21 vertices never share a
/// key (their coordinates differ by less than 2^20), so the key identifies
/// the site without any bound on the coordinates themselves.
inline std::uint64_t site_key(std::int64_t x, std::int64_t y, std::int64_t z) {
  constexpr std::uint64_t mask = (std::uint64_t{1} << 21) - 1;
  return (static_cast<std::uint64_t>(x) & mask) | ((static_cast<std::uint64_t>(y) & mask) << 21) |
         ((static_cast<std::uint64_t>(z) & mask) << 42);
}

/// Largest polygon length for which site_key() is collision free.
constexpr int kMaxLatticeLength = 1 << 21;

/// Open-addressing hash set of site keys (linear probing, backward-shift
/// deletion, no tombstones; Fibonacci hashing of the key). insert, erase and
/// contains are O(1) expected at the load factor <= 1/2 kept by rehashing.
class SiteSet {
 public:
  explicit SiteSet(std::size_t expected_size = 64);  ///< Empty set with room for `expected_size` keys before a rehash.
  /// Inserts `key`; returns false if it was already present.
  bool insert(std::uint64_t key);
  /// Removes `key`; returns false if it was absent.
  bool erase(std::uint64_t key);
  /// Whether `key` is in the set.
  bool contains(std::uint64_t key) const {
    for (std::size_t i = slot(key);; i = (i + 1) & mask_) {
      const std::uint64_t k = table_[i];
      if (k == key) return true;
      if (k == kEmpty) return false;
    }
  }
  std::size_t size() const { return size_; }  ///< Number of keys in the set.
  /// Number of slots of the table (a power of two, at least twice size()).
  std::size_t capacity() const { return table_.size(); }
  void clear();  ///< Removes every key (the capacity is kept).

 private:
  static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};  // never a site key (keys use 63 bits)
  std::size_t slot(std::uint64_t key) const {
    return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> shift_);
  }
  void rehash(std::size_t capacity);
  std::vector<std::uint64_t> table_;
  std::size_t mask_ = 0;
  int shift_ = 64;
  std::size_t size_ = 0;
};

}  // namespace ek
