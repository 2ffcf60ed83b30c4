#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "ek/core/errors.hpp"
#include "ek/dataset/dataset_file.hpp"
#include "testing.hpp"

using namespace ek;

namespace {

KnotEntry sample_entry(const std::string& name, int m, int n) {
  KnotEntry k;
  k.name = name;
  k.crossing_number = 4;
  k.bridge_index = 2;
  k.braid_index = 3;
  k.alexander = {-1, 3, -1};
  for (int e = 0; e < m; ++e) k.equilibria.push_back(fixtures::random_fourier_curve(n, 3, 10 + e));
  k.attribute_names = {"energy", "writhe"};
  k.attributes.resize(m, 2);
  for (int e = 0; e < m; ++e) k.attributes.row(e) << 0.1 * e - 0.7, std::sqrt(2.0) * e;
  for (int r = 0; r < m + 1; ++r) {
    RunRecord run;
    run.sample = r;
    run.seed = 1000 + r;
    run.status = r < m ? "converged-stable" : "stalled";
    run.equilibrium = r < m ? r : -1;
    run.iterations = 10 + r;
    run.seconds = 0.5 * r;
    run.energy = 1.0 / (r + 1);
    run.gradient_norm = 1e-9;
    run.contacts = r;
    run.message = r < m ? "" : "line search cannot progress";
    k.runs.push_back(run);
  }
  k.similarity = Eigen::MatrixXd::Identity(m, m);
  k.linkage = Eigen::MatrixXd::Zero(std::max(m - 1, 0), 4);
  k.samples_used = m + 1;
  k.adaptive = true;
  k.score_history = {0.9, 0.5, 0.05};
  return k;
}

}  // namespace

TEST(DatasetFile, RoundTrip) {
  const std::string path = ::testing::TempDir() + "round.h5";
  DatasetMetadata meta;
  meta.project_version = "test";
  meta.created = "2026-11-22T00:00:00Z";
  meta.knot_table = "/x/knotinfo.csv";
  meta.sampling = "fixed:3";
  {
    DatasetWriter w(path, meta);
    w.add(sample_entry("4_1", 3, 40));
    w.add(sample_entry("3_1", 2, 40));
    w.commit();
  }
  DatasetReader r(path);
  EXPECT_EQ(r.metadata().difference(meta), "");
  EXPECT_EQ(r.metadata().sampling, "fixed:3");
  EXPECT_EQ(r.knot_names(), (std::vector<std::string>{"4_1", "3_1"}));
  const KnotEntry a = r.read("4_1"), b = sample_entry("4_1", 3, 40);
  ASSERT_EQ(a.equilibria.size(), 3u);
  for (int e = 0; e < 3; ++e) EXPECT_EQ(a.equilibria[e], b.equilibria[e]);
  EXPECT_EQ(a.attributes, b.attributes);
  EXPECT_EQ(a.attribute_names, b.attribute_names);
  EXPECT_EQ(a.alexander, b.alexander);
  ASSERT_EQ(a.runs.size(), 4u);
  EXPECT_EQ(a.runs[3].status, "stalled");
  EXPECT_EQ(a.runs[3].equilibrium, -1);
  EXPECT_EQ(a.runs[3].message, "line search cannot progress");
  EXPECT_EQ(a.runs[2].seed, 1002u);
  EXPECT_EQ(a.score_history, b.score_history);
  EXPECT_EQ(a.similarity, b.similarity);
  EXPECT_TRUE(a.adaptive);
  EXPECT_EQ(a.attribute_column("writhe"), 1);
  EXPECT_THROW(a.attribute_column("colour"), InputError);
  EXPECT_THROW(r.read("5_1"), InputError);
  std::remove(path.c_str());
}

TEST(DatasetFile, UncommittedWriterLeavesExistingFileAlone) {
  const std::string path = ::testing::TempDir() + "keep.h5";
  { std::ofstream(path) << "precious"; }
  {
    DatasetWriter w(path, DatasetMetadata{});
    w.add(sample_entry("4_1", 2, 20));
    // destroyed without commit
  }
  std::ifstream in(path);
  std::string s;
  in >> s;
  EXPECT_EQ(s, "precious");
  for (const auto& e : std::filesystem::directory_iterator(::testing::TempDir()))
    EXPECT_EQ(e.path().filename().string().find("keep.h5.tmp"), std::string::npos);
  std::remove(path.c_str());
}

TEST(DatasetFile, BadFilesAreInputErrors) {
  const std::string path = ::testing::TempDir() + "not.h5";
  { std::ofstream(path) << "not hdf5"; }
  EXPECT_THROW(DatasetReader{path}, InputError);
  EXPECT_THROW(DatasetReader{"/nonexistent/x.h5"}, InputError);
  EXPECT_THROW(DatasetWriter("/nonexistent-dir/x.h5", DatasetMetadata{}), InputError);
  std::remove(path.c_str());
}

TEST(DatasetFile, MetadataDifference) {
  DatasetMetadata a, b;
  EXPECT_EQ(a.difference(b), "");
  b.radius = 0.1;
  EXPECT_EQ(a.difference(b), "radius 0.2 vs 0.1");
  b = a;
  b.vertices = 200;
  EXPECT_EQ(a.difference(b), "vertices 400 vs 200");
}
