// Writes the binary seeds of the fuzz corpus: small data sets (with and
// without the checksum header) and journals. The text seeds are written by
// hand. Regenerate with `make fuzz-seeds` (overwrites only these files).
//
//   fuzz_make_seeds CORPUS_DIR
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "ek/dataset/dataset_file.hpp"
#include "fuzz_seeds.hpp"
#include "journal.hpp"
#include "unsealed_copy.hpp"

namespace {

/// A small equilibrium: n points on a trefoil-like curve.
ek::Points curve(int n, double phase) {
  ek::Points P(n, 3);
  for (int i = 0; i < n; ++i) {
    const double t = 2 * M_PI * i / n + phase;
    P.row(i) << std::sin(t) + 2 * std::sin(2 * t), std::cos(t) - 2 * std::cos(2 * t), -std::sin(3 * t);
  }
  return P;
}

ek::KnotEntry knot(const std::string& name, int m, int n) {
  ek::KnotEntry k;
  k.name = name;
  k.crossing_number = 3;
  k.bridge_index = 2;
  k.braid_index = 2;
  k.alexander = {1, -1, 1};
  for (int e = 0; e < m; ++e) k.equilibria.push_back(curve(n, 0.1 * e));
  k.attribute_names = {"energy", "writhe"};
  k.attributes.resize(m, 2);
  for (int e = 0; e < m; ++e) k.attributes.row(e) << 10.0 + e, 3.3;
  for (int r = 0; r <= m; ++r) {
    ek::RunRecord run;
    run.sample = r;
    run.seed = 7 + static_cast<unsigned>(r);
    run.status = r < m ? ek::RunStatus::ConvergedStable : ek::RunStatus::Stalled;
    run.equilibrium = r < m ? r : -1;
    run.message = r < m ? "" : "line search";
    k.runs.push_back(run);
  }
  k.similarity = Eigen::MatrixXd::Identity(m, m);
  k.linkage = Eigen::MatrixXd::Zero(std::max(m - 1, 0), 4);
  k.samples_used = m + 1;
  k.score_history = {0.5};
  return k;
}

void write_dataset(const std::string& path, const std::vector<ek::KnotEntry>& knots) {
  // every parameter a run records (metadata.hpp); n = 6 for small seeds
  ek::DatasetMetadata meta;
  meta.young = 2000.0;
  meta.poisson = 0.3;
  meta.radius = 0.2;
  meta.vertices = 6;
  meta.edge_length = 1.0;
  meta.tolerance = 1e-8;
  meta.contact_stiffness = 100.0;
  meta.dhat = 0.5;
  meta.twist_model = "twist-free";
  meta.relax_method = "multilevel";
  meta.coarse_levels = 1;
  meta.coarse_continuation = std::vector<double>{0.01};
  meta.coarsening = "even";
  meta.newton_hessian = "exact";
  meta.remove_rigid_motions = true;
  meta.contact_hessian = "eigen-projected";
  meta.damp_short_steps = false;
  meta.max_iterations = 5000;
  meta.burn_in = 0;
  meta.sampling = "fixed:2";
  meta.grow_fugacity = 0.4;
  meta.shrink_fugacity = 0.1;
  meta.growth_factor = 10.0;
  meta.decorrelation_moves = 0;
  meta.seed = 1;
  meta.compute_stiffness = false;
  meta.contact_continuation = std::vector<double>{};
  meta.project_version = "seed";
  meta.knot_table = "knotinfo_table.csv";
  meta.created = "2000-01-01T00:00:00Z";
  ek::DatasetWriter w(path, meta);
  for (const auto& k : knots) w.add(k);
  w.commit();
}

ek::JournalRun journal_run(int sample, bool stable) {
  ek::JournalRun r;
  r.record.sample = sample;
  r.record.seed = 11;
  r.record.status = stable ? ek::RunStatus::ConvergedStable : ek::RunStatus::Stalled;
  r.record.iterations = 12;
  r.record.message = stable ? "" : "line search";
  if (stable) r.positions = curve(4, 0.0);
  r.energy.total = 1.5;
  r.stiffness = std::nan("");
  return r;
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

void write_journals(const std::string& dir) {
  const std::string path = dir + "/two-runs.journal";
  std::filesystem::remove(path);
  {
    ek::Journal j(path, ek::fuzz::kJournalOptions);
    j.append(journal_run(0, true));
    j.append(journal_run(1, false));
  }
  const std::string full = slurp(path);
  const std::string head = ek::journal_head(ek::fuzz::kJournalOptions);
  std::ofstream(dir + "/header-only.journal", std::ios::binary) << head;
  std::ofstream(dir + "/torn-tail.journal", std::ios::binary) << full.substr(0, full.size() - 9);
  std::ofstream(dir + "/other-options.journal", std::ios::binary) << ek::journal_head("knot=4_1") << full.substr(head.size());
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: fuzz_make_seeds CORPUS_DIR\n";
    return 2;
  }
  const std::string corpus = argv[1];
  std::filesystem::create_directories(corpus + "/dataset_h5");
  std::filesystem::create_directories(corpus + "/journal");
  write_dataset(corpus + "/dataset_h5/sealed-1knot.h5", {knot("3_1", 1, 4)});
  write_dataset(corpus + "/dataset_h5/sealed-2knots.h5", {knot("3_1", 2, 6), knot("4_1", 0, 6)});
  ek::fixtures::write_unsealed_copy(corpus + "/dataset_h5/sealed-1knot.h5", corpus + "/dataset_h5/unsealed-1knot.h5");
  ek::fixtures::write_unsealed_copy(corpus + "/dataset_h5/sealed-2knots.h5", corpus + "/dataset_h5/unsealed-2knots.h5");
  write_journals(corpus + "/journal");
  return 0;
}
