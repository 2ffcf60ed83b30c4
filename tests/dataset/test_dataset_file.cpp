#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>

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
  // the iteration cap counts only when both files record it
  b = a;
  a.max_iterations = 5000;
  EXPECT_EQ(a.difference(b), "");
  b.max_iterations = 2000;
  EXPECT_EQ(a.difference(b), "max_iterations 5000 vs 2000");
  // the continuation always counts (it changes which equilibria a walk reaches)
  b = a;
  b.contact_continuation = {1e-3};
  EXPECT_EQ(a.difference(b), "contact_continuation off vs 0.001");
  a.contact_continuation = {1e-3, 0.1};
  EXPECT_EQ(a.difference(b), "contact_continuation 0.001,0.10000000000000001 vs 0.001");
}

// The solver's iteration cap and continuation factors are file attributes;
// files written before they existed read as "not recorded" and "off", and a
// malformed continuation attribute is an input error.
TEST(DatasetFile, SolverCapAndContinuationAttributes) {
  const std::string path = ::testing::TempDir() + "solver_meta.h5";
  DatasetMetadata meta;
  meta.sampling = "fixed:1";
  meta.max_iterations = 3000;
  meta.contact_continuation = {1e-3, 0.1 / 3.0};
  {
    DatasetWriter w(path, meta);
    w.add(sample_entry("3_1", 1, 40));
    w.commit();
  }
  {
    DatasetReader r(path);
    EXPECT_EQ(r.metadata().max_iterations, 3000);
    EXPECT_EQ(r.metadata().contact_continuation, meta.contact_continuation);  // bit for bit (17 digits)
    EXPECT_EQ(r.metadata().difference(meta), "");
  }
  auto edit_attributes = [&](const std::function<void(hid_t)>& f) {
    const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(file, 0);
    f(file);
    H5Fclose(file);
  };
  edit_attributes([](hid_t f) {
    ASSERT_GE(H5Adelete(f, "max_iterations"), 0);
    ASSERT_GE(H5Adelete(f, "contact_continuation"), 0);
  });
  {
    DatasetReader r(path);
    EXPECT_EQ(r.metadata().max_iterations, -1);
    EXPECT_TRUE(r.metadata().contact_continuation.empty());
  }
  edit_attributes([](hid_t f) {
    const char* bad = "0.5,,2";  // a variable-length string, as the writer stores text
    const hid_t type = H5Tcopy(H5T_C_S1);
    H5Tset_size(type, H5T_VARIABLE);
    const hid_t space = H5Screate(H5S_SCALAR);
    const hid_t a = H5Acreate2(f, "contact_continuation", type, space, H5P_DEFAULT, H5P_DEFAULT);
    ASSERT_GE(a, 0);
    H5Awrite(a, type, &bad);
    H5Aclose(a);
    H5Sclose(space);
    H5Tclose(type);
  });
  try {
    DatasetReader r(path);
    ADD_FAILURE() << "a malformed contact_continuation attribute was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("malformed contact_continuation attribute '0.5,,2'"), std::string::npos)
        << e.what();
  }
  std::remove(path.c_str());
}
