#pragma once
// Helpers for the tests of the data-set parameter table (metadata.hpp).
#include <string>

#include "ek/dataset/metadata.hpp"

namespace ek::testing_metadata {

/// Another value of the same kind: numbers change by far more than the
/// comparison tolerance, flags flip, text and lists get longer.
inline FieldValue changed(const FieldValue& v) {
  struct {
    FieldValue operator()(std::monostate) const { return std::monostate{}; }
    FieldValue operator()(double x) const { return 1.5 * x + 0.25; }
    FieldValue operator()(std::int64_t x) const { return x == 1 ? std::int64_t{0} : x + 1; }
    FieldValue operator()(std::uint64_t x) const { return x + 1; }
    FieldValue operator()(const std::string& x) const { return x + "-other"; }
    FieldValue operator()(std::vector<double> x) const {
      x.push_back(0.5);
      return x;
    }
  } visitor;
  return std::visit(visitor, v);
}

/// Metadata with every field set, to values other than a default run's, some
/// of them awkward for a round trip (a seed >= 2^63, thirds).
inline DatasetMetadata complete_metadata() {
  DatasetMetadata m;
  m.young = 2100.5;
  m.poisson = 1.0 / 3.0;
  m.radius = 0.25;
  m.vertices = 120;
  m.edge_length = 1.0;
  m.tolerance = 1e-8 / 3.0;
  m.contact_stiffness = 1234.5678;
  m.dhat = 0.45;
  m.twist_model = "free-theta";
  m.relax_method = "multilevel";
  m.coarse_levels = 2;
  m.coarse_continuation = std::vector<double>{1e-2};
  m.coarsening = "either-parity,recheck-20x3";
  m.newton_hessian = "exact";
  m.remove_rigid_motions = false;
  m.contact_hessian = "gauss-newton";
  m.damp_short_steps = true;
  m.max_iterations = 3000;
  m.burn_in = 7;
  m.sampling = "fixed:3,burn-in=7";
  m.grow_fugacity = 0.41;
  m.shrink_fugacity = 0.09;
  m.growth_factor = 9.5;
  m.decorrelation_moves = 12345;
  m.seed = (std::uint64_t{1} << 63) + 5;
  m.compute_stiffness = false;
  m.contact_continuation = std::vector<double>{1e-3, 0.1 / 3.0};
  m.project_version = "test";
  m.knot_table = "/x/knotinfo.csv";
  m.created = "2026-11-22T00:00:00Z";
  return m;
}

}  // namespace ek::testing_metadata
