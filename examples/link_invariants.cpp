// The invariants of a link of the link table, laid out from its braid: each
// component's Alexander polynomial and writhe, the linking numbers (exact
// Gauss sums), the Conway polynomial, and Milnor's triple linking number
// where it is defined; checked against the table's values.
//
//   link_invariants [LINK]      (default borromean; knots info lists the links)
#include <iostream>
#include <stdexcept>
#include <string>

#include "ek/embedding/embedding.hpp"
#include "ek/knots/invariants.hpp"
#include "ek/knots/link_table.hpp"

int main(int argc, char** argv) {
  const std::string name = argc > 1 ? argv[1] : "borromean";
  const ek::LinkRecord* link = ek::find_link(name);
  if (!link) {
    std::cerr << "link_invariants: no link '" << name << "' in the link table\n";
    return 2;
  }
  ek::EmbeddingOptions embedding;
  embedding.vertices = 240;
  const ek::LinkEmbedding drawn = ek::embed_braid_link(link->braid, embedding);
  const ek::LinkInvariants inv = ek::link_invariants(drawn.components);
  std::cout << link->description << " (" << name << "), " << inv.components.size() << " components\n";
  for (size_t c = 0; c < inv.components.size(); ++c)
    std::cout << "  component " << c << ": Alexander " << inv.components[c].alexander.to_string() << ", writhe "
              << inv.components[c].writhe << "\n";
  std::cout << "  linking numbers\n" << inv.linking_numbers << "\n  Conway " << inv.conway.to_string() << "\n";
  if (inv.milnor_triple) std::cout << "  Milnor triple linking number " << *inv.milnor_triple << "\n";
  const bool as_tabled = inv.linking_numbers == link->linking_matrix() && inv.conway == link->conway &&
                         inv.milnor_triple == link->milnor_triple();
  std::cout << (as_tabled ? "  as the link table says\n" : "  DIFFERS from the link table\n");
  return as_tabled ? 0 : 1;
}
