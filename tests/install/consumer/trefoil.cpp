// Relaxes the trefoil from its table braid and prints its energy and the
// Alexander polynomial of the equilibrium: the library used from outside.
#include <iostream>

#include "ek/embedding/embedding.hpp"
#include "ek/knots/alexander.hpp"
#include "ek/knots/table.hpp"
#include "ek/solver/relax.hpp"

int main() {
  const ek::KnotRecord& trefoil = ek::KnotTable::global().at("3_1");
  ek::EmbeddingOptions embedding;
  embedding.vertices = 100;
  const ek::Embedding start = ek::embed_knot(trefoil, ek::EmbeddingSource::Braid, embedding);
  const ek::RelaxResult r = ek::relax(start.points);
  std::cout << "status " << r.status() << "\nenergy " << r.energy.total << "\nalexander "
            << ek::alexander(r.positions).to_string() << std::endl;
  return r.stable() ? 0 : 1;
}
