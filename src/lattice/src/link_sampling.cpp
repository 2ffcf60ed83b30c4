#include "ek/lattice/link_sampling.hpp"

#include <cmath>
#include <numeric>

#include "ek/core/errors.hpp"
#include "ek/embedding/embedding.hpp"
#include "ek/knots/alexander.hpp"
#include "ek/knots/table.hpp"
#include "schedule.hpp"

namespace ek {
namespace {

/// Every component translated by one integer vector: the centroid of all
/// vertices in [-1/2, 1/2]³.
std::vector<LatticePoints> centered(std::vector<LatticePoints> link) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  double count = 0.0;
  for (const LatticePoints& L : link) {
    sum += L.cast<double>().colwise().sum().transpose();
    count += static_cast<double>(L.rows());
  }
  for (LatticePoints& L : link)
    for (int k = 0; k < 3; ++k) L.col(k).array() -= static_cast<std::int32_t>(std::floor(sum[k] / count + 0.5));
  return link;
}

/// Component c's share of `total` in proportion to the start's lengths.
std::vector<int> component_targets(const std::vector<LatticePoints>& start, int total, const LinkType& type) {
  double all = 0.0;
  for (const LatticePoints& L : start) all += static_cast<double>(L.rows());
  std::vector<int> n;
  for (size_t c = 0; c < start.size(); ++c) {
    const bool knotted = type.alexander[c] != AlexanderPolynomial{};
    const int share = schedule::even_floor(total * static_cast<double>(start[c].rows()) / all + 1.0);
    n.push_back(std::max(share, knotted ? 24 : 4));
  }
  return n;
}

void check_reached(const BfacfRunReport& r, const std::string& what, size_t c, const char* phase, int target) {
  if (!r.reached)
    throw InputError("sampling " + what + ": component " + std::to_string(c + 1) + " did not " + phase + " to " +
                     std::to_string(target) + " vertices within " + std::to_string(r.attempts) +
                     " attempted moves (lengths reached " + std::to_string(r.min_length) + " to " +
                     std::to_string(r.max_length) + "; use a larger vertex count)");
}

}  // namespace

Link to_link(const std::vector<LatticePoints>& polygons) {
  Link link;
  for (const LatticePoints& L : polygons) link.push_back(to_points(L));
  return link;
}

LinkSampleBatch sample_lattice_link(const std::vector<LatticePoints>& start, const SampleOptions& o,
                                    const LinkType& expected, const std::string& what) {
  schedule::validate(o);
  require_input(start.size() == expected.alexander.size(),
                "sampling " + what + ": the start has " + std::to_string(start.size()) + " components, the link " +
                    std::to_string(expected.alexander.size()));
  BfacfWalk walk(start, o.seed);
  LinkSampleBatch batch;
  batch.component_vertices = component_targets(start, o.vertices, expected);
  for (int k = 0; k < o.count; ++k) {
    for (size_t c = 0; c < start.size(); ++c) {
      const int n = batch.component_vertices[c];
      const int peak = std::max(n, schedule::even_floor(o.growth_factor * n));
      const int comp = static_cast<int>(c);
      if (walk.component_length(comp) < peak) {
        const BfacfRunReport grow = walk.run_to_length(peak, o.grow_fugacity, schedule::budget(o, peak), comp);
        check_reached(grow, what, c, "grow", peak);
        batch.attempted_moves += grow.attempts;
      }
    }
    for (size_t c = 0; c < start.size(); ++c) {
      const int n = batch.component_vertices[c];
      const int peak = std::max(n, schedule::even_floor(o.growth_factor * n));
      const BfacfRunReport shrink =
          walk.run_to_length(n, o.shrink_fugacity, schedule::budget(o, peak), static_cast<int>(c));
      check_reached(shrink, what, c, "shrink", n);
      batch.attempted_moves += shrink.attempts;
    }
    std::vector<LatticePoints> sample = centered(walk.polygons());
    if (o.verify) {
      const LinkType got = link_type(to_link(sample));
      if (got != expected)
        throw TopologyError("sampling " + what + ": sample " + std::to_string(k) + " has " + got.to_string() +
                            " instead of " + expected.to_string());
    }
    batch.samples.push_back(std::move(sample));
  }
  return batch;
}

LatticeLinkStart lattice_link_start(const Link& link, const RoundingOptions& rounding) {
  LatticeLinkStart start;
  start.type = link_type(link);
  bool on_lattice = true;
  for (const Points& P : link) {
    LatticePoints L;
    on_lattice = on_lattice && as_lattice_polygon(P, &L);
    if (on_lattice) start.components.push_back(L);
  }
  if (!on_lattice) {
    start.components.clear();
    for (RoundingResult& r : round_link_to_lattice(link, rounding)) {
      start.scale = r.scale;
      start.components.push_back(std::move(r.points));
    }
  }
  const LinkType got = link_type(to_link(start.components));
  if (got != start.type)
    throw TopologyError("lattice rounding of a link: " + got.to_string() + " differs from the curves' " +
                        start.type.to_string());
  return start;
}

LatticeLinkStart lattice_link_start(const LinkRecord& record, const RoundingOptions& rounding) {
  EmbeddingOptions eo;
  eo.vertices = 100 * record.components();
  const LinkEmbedding e = embed_braid_link(record.braid, eo);
  LatticeLinkStart start = lattice_link_start(e.components, rounding);
  if (start.type.conway != record.conway)
    throw TopologyError("lattice start of " + record.name + ": Conway polynomial " + start.type.conway.to_string() +
                        " differs from the table's " + record.conway.to_string());
  return start;
}

}  // namespace ek
