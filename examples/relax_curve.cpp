// Relaxes a closed curve as an elastic rod with self-contact (paper Sections
// 4-6) and writes the equilibrium. With a file argument the curve is read
// from it (OBJ, or a text file of one "x y z" row per vertex); without one,
// the figure-eight knot 4_1 is embedded from its table braid.
//
//   relax_curve [CURVE] [-o OUT.obj]
#include <iostream>
#include <string>

#include "ek/embedding/embedding.hpp"
#include "ek/geometry/curve_io.hpp"
#include "ek/knots/table.hpp"
#include "ek/solver/relax.hpp"

int main(int argc, char** argv) {
  std::string in, out;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "-o" && i + 1 < argc)
      out = argv[++i];
    else
      in = a;
  }
  ek::EmbeddingOptions embedding;
  embedding.vertices = 120;
  const ek::Points start = in.empty()
                               ? ek::embed_knot(ek::KnotTable::global().at("4_1"), ek::EmbeddingSource::Braid, embedding).points
                               : ek::read_curve(in);
  const ek::RelaxResult r = ek::relax(start);  // the default material and method (docs/models.md)
  const ek::EnergyParts& e = r.energy;
  std::cout << "status " << r.status() << "\nenergy " << e.total << " (stretch " << e.stretch << ", bend " << e.bend
            << ", contact " << e.contact << ")\n";
  if (!out.empty()) ek::write_curve(out, r.positions);
  return r.stable() ? 0 : 1;
}
