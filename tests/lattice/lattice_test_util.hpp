#pragma once
// Helpers shared by the lattice tests.
#include "ek/lattice/lattice_polygon.hpp"

namespace ek::latticetest {

/// The unit square in the plane z = 0, counterclockwise from the origin (4 by 3).
inline LatticePoints unit_square() {
  LatticePoints L(4, 3);
  L << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0;
  return L;
}

}  // namespace ek::latticetest
