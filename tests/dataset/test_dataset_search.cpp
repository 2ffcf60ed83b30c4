// Cross-topology search over a data set (ek::search_dataset) and the command
// `knots search` on a hand-made data set: torus knots T(2,3), T(2,5), T(3,4)
// of equal length (the data set's curves all have n unit edges), each stored
// as a few equilibria moved rigidly and re-indexed, with small deformations.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "cli_runner.hpp"
#include "metadata_testing.hpp"
#include "ek/analysis/attributes.hpp"
#include "ek/analysis/clustering.hpp"
#include "ek/dataset/dataset_search.hpp"
#include "ek/dataset/pipeline.hpp"
#include "ek/geometry/curve_io.hpp"
#include "ek/geometry/polyline.hpp"
#include "ek/geometry/resample.hpp"
#include "testing.hpp"

using namespace ek;
namespace fs = std::filesystem;

namespace {

constexpr int kN = 120;

/// T(p, q) with kN unit edges (scaled to length kN), deformed by `bump`
/// (a radial ripple of relative size bump), moved by `seed`, re-indexed by `shift`.
Points torus_curve(int p, int q, double bump, std::uint64_t seed, int shift) {
  Points T = fixtures::torus_knot(4 * kN, p, q);
  for (Eigen::Index i = 0; i < T.rows(); ++i) T.row(i) *= 1.0 + bump * std::sin(5.0 * 2.0 * M_PI * i / T.rows());
  Points U = resample_equilateral(T, kN).points;
  U *= 1.0 / edge_lengths(U).mean();
  return fixtures::rigid_copy(U, fixtures::random_rotation(seed), Vec3(static_cast<double>(seed), -2.0 * static_cast<double>(seed), 1.0), shift);
}

KnotEntry torus_entry(const std::string& name, int p, int q) {
  KnotEntry e;
  e.name = name;
  e.alexander = {1};  // not used by the search
  const auto& names = dataset_attribute_names();
  e.attribute_names = names;
  for (int k = 0; k < 3; ++k) e.equilibria.push_back(torus_curve(p, q, 0.02 * (k + 1), 10 * p + k, 7 * k));
  e.attributes = Eigen::MatrixXd::Zero(3, static_cast<Eigen::Index>(names.size()));
  for (int k = 0; k < 3; ++k) {
    const GeometricAttributes g = geometric_attributes(e.equilibria[static_cast<size_t>(k)]);
    e.attributes(k, e.attribute_column("threedim")) = g.threedim;
    e.attributes(k, e.attribute_column("diameter")) = g.diameter;
    e.attributes(k, e.attribute_column("energy")) = 1.0 + k;
  }
  e.similarity = Eigen::MatrixXd::Identity(3, 3);
  e.linkage = complete_linkage_from_similarity(e.similarity).linkage_matrix();
  return e;
}

/// The data set: T(2,3) as "3_1", T(2,5) as "5_1", T(3,4) as "8_19".
std::string write_dataset(const std::string& dir) {
  const std::string file = dir + "/torus.h5";
  DatasetWriter w(file, testing_metadata::complete_metadata());
  w.add(torus_entry("3_1", 2, 3));
  w.add(torus_entry("5_1", 2, 5));
  w.add(torus_entry("8_19", 3, 4));
  w.commit();
  return file;
}

}  // namespace

// A stored equilibrium, moved rigidly, re-indexed and reversed, is found
// first at distance ~0; the other equilibria of its type follow before the
// other types; excluding its type returns only other types.
TEST(DatasetSearch, FindsItselfFirstThenItsType) {
  const std::string dir = ek::clitest::temp_dir("search_lib");
  const std::string file = write_dataset(dir);
  const DatasetReader reader(file);
  const Points stored = reader.read("5_1").equilibria[1];
  const Points query = fixtures::rigid_copy(Points(stored.colwise().reverse()), fixtures::random_rotation(99),
                                            Vec3(3.0, 4.0, 5.0), 41);
  DatasetSearchOptions o;
  o.filter_attributes.clear();
  o.max_results = 0;
  const DatasetSearchResult r = search_dataset(reader, query, o);
  EXPECT_EQ(r.searched, 9);
  EXPECT_EQ(r.aligned, 9);
  ASSERT_EQ(r.hits.size(), 9u);
  EXPECT_EQ(r.hits[0].knot, "5_1");
  EXPECT_EQ(r.hits[0].equilibrium, 1);
  EXPECT_LT(r.hits[0].distance, 1e-6);
  EXPECT_TRUE(r.hits[0].alignment.reversed);
  EXPECT_EQ(r.hits[1].knot, "5_1");
  EXPECT_EQ(r.hits[2].knot, "5_1");
  for (size_t k = 1; k < r.hits.size(); ++k) EXPECT_GE(r.hits[k].distance, r.hits[k - 1].distance);
  // the same ranking with 2 jobs
  o.jobs = 2;
  const DatasetSearchResult r2 = search_dataset(reader, query, o);
  for (size_t k = 0; k < r.hits.size(); ++k) {
    EXPECT_EQ(r2.hits[k].knot, r.hits[k].knot);
    EXPECT_EQ(r2.hits[k].equilibrium, r.hits[k].equilibrium);
    EXPECT_EQ(r2.hits[k].distance, r.hits[k].distance);
  }
  o.exclude_knots = {"5_1"};
  o.max_results = 2;
  const DatasetSearchResult other = search_dataset(reader, query, o);
  EXPECT_EQ(other.searched, 6);
  ASSERT_EQ(other.hits.size(), 2u);
  for (const auto& h : other.hits) EXPECT_NE(h.knot, "5_1");
  o.exclude_knots.clear();
  o.only_knots = {"nope"};
  EXPECT_THROW(search_dataset(reader, query, o), InputError);
  fs::remove_all(dir);
}

// The pre-filter keeps the equilibria whose 3D-ness and diameter are within
// the widths of the query's; with zero width only exact matches remain.
TEST(DatasetSearch, PreFilterOnStoredAttributes) {
  const std::string dir = ek::clitest::temp_dir("search_filter");
  const std::string file = write_dataset(dir);
  const DatasetReader reader(file);
  const Points query = reader.read("3_1").equilibria[0];
  DatasetSearchOptions o;
  o.max_results = 0;
  o.filter_relative_width = 0.0;
  o.filter_absolute_width = 1e-9;
  const DatasetSearchResult r = search_dataset(reader, query, o);
  EXPECT_EQ(r.searched, 9);
  EXPECT_EQ(r.aligned, 1);  // the stored curve itself
  ASSERT_EQ(r.hits.size(), 1u);
  EXPECT_EQ(r.hits[0].knot, "3_1");
  EXPECT_EQ(r.hits[0].equilibrium, 0);
  o.filter_attributes = {"energy"};  // not computable from the query curve
  EXPECT_THROW(search_dataset(reader, query, o), InputError);
  fs::remove_all(dir);
}

// `knots search` gives the library's ranking; bad input is one line, exit 2.
TEST(DatasetSearch, CommandLine) {
  const std::string dir = ek::clitest::temp_dir("search_cli");
  const std::string file = write_dataset(dir);
  const DatasetReader reader(file);
  const Points query = fixtures::rigid_copy(reader.read("8_19").equilibria[2], fixtures::random_rotation(5),
                                            Vec3(1.0, 0.0, 0.0), 13);
  write_curve(dir + "/q.obj", query);
  const auto r = ek::clitest::run("search " + file + " " + dir + "/q.obj --limit 4 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = r.json();
  DatasetSearchOptions o;
  o.max_results = 4;
  const DatasetSearchResult lib = search_dataset(reader, query, o);
  ASSERT_EQ(j["count"].get<size_t>(), lib.hits.size());
  EXPECT_EQ(j["searched"], lib.searched);
  EXPECT_EQ(j["aligned"], lib.aligned);
  for (size_t k = 0; k < lib.hits.size(); ++k) {
    EXPECT_EQ(j["hits"][k]["rank"], k + 1);
    EXPECT_EQ(j["hits"][k]["knot"], lib.hits[k].knot);
    EXPECT_EQ(j["hits"][k]["index"], lib.hits[k].equilibrium);
    EXPECT_NEAR(j["hits"][k]["distance"].get<double>(), lib.hits[k].distance, 1e-12);
  }
  EXPECT_EQ(j["hits"][0]["knot"], "8_19");
  EXPECT_EQ(j["hits"][0]["index"], 2);
  EXPECT_LT(j["hits"][0]["distance"].get<double>(), 1e-6);
  // --exclude-knot and the text output
  const auto t = ek::clitest::run("search " + file + " " + dir + "/q.obj --exclude-knot 8_19 --no-filter --limit 0");
  ASSERT_EQ(t.status, 0) << t.err;
  EXPECT_EQ(t.out.find("8_19"), std::string::npos) << t.out;
  EXPECT_NE(t.out.find("6 of 6 aligned equilibria (6 searched)"), std::string::npos) << t.out;
  for (const std::string& bad : {"search " + file + " " + dir + "/missing.obj", "search " + dir + "/none.h5 " + dir + "/q.obj",
                                 "search " + file + " " + dir + "/q.obj --limit -1",
                                 "search " + file + " " + dir + "/q.obj --jobs 0",
                                 "search " + file + " " + dir + "/q.obj --knot 9_99",
                                 "search " + file + " " + dir + "/q.obj --bogus", "search " + file}) {
    const auto b = ek::clitest::run(bad);
    EXPECT_EQ(b.status, 2) << bad;
    EXPECT_EQ(std::count(b.err.begin(), b.err.end(), '\n'), 1) << bad << ": " << b.err;
  }
  fs::remove_all(dir);
}

// attribute_extremes over the whole data set: the smallest and largest
// stored value (NaN skipped; ties to the first in file order), the rows
// `knots query --sort ATTR --limit 1` and `--sort ATTR:desc` print first.
TEST(DatasetSearch, AttributeExtremesAreTheQueryExtremes) {
  const std::string dir = ek::clitest::temp_dir("search_extremes");
  const std::string file = dir + "/extremes.h5";
  {
    DatasetWriter w(file, testing_metadata::complete_metadata());
    KnotEntry a = torus_entry("3_1", 2, 3), b = torus_entry("5_1", 2, 5);
    const int s = a.attribute_column("stiffness");
    a.attributes.col(s) << std::nan(""), 2.0, 5.0;  // a NaN (eigensolver failed) must not come first
    b.attributes.col(s) << 5.0, std::nan(""), 0.5;   // 5.0 ties with 3_1 #2: the first in file order wins
    w.add(a);
    w.add(b);
    w.commit();
  }
  const DatasetReader reader(file);
  const auto [lo, hi] = attribute_extremes(reader, "stiffness");
  EXPECT_EQ(lo.knot, "5_1");
  EXPECT_EQ(lo.equilibrium, 2);
  EXPECT_EQ(lo.value, 0.5);
  EXPECT_EQ(hi.knot, "3_1");
  EXPECT_EQ(hi.equilibrium, 2);
  EXPECT_EQ(hi.value, 5.0);
  for (const auto& [sort, x] : {std::pair{std::string("stiffness"), lo}, std::pair{std::string("stiffness:desc"), hi}}) {
    const auto r = ek::clitest::run("query " + file + " --sort " + sort + " --limit 1 --json");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto row = r.json()["rows"].at(0);
    EXPECT_EQ(row["knot"].get<std::string>(), x.knot) << sort;
    EXPECT_EQ(row["index"].get<int>(), x.equilibrium) << sort;
  }
  // NaN rows last in both directions
  for (const std::string sort : {"stiffness", "stiffness:desc"}) {
    const auto r = ek::clitest::run("query " + file + " --sort " + sort + " --json");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto rows = r.json()["rows"];
    ASSERT_EQ(rows.size(), 6u);
    for (size_t k = 0; k < 4; ++k) EXPECT_FALSE(rows[k]["stiffness"].is_null()) << sort << " row " << k;
    for (size_t k = 4; k < 6; ++k) EXPECT_TRUE(rows[k]["stiffness"].is_null()) << sort << " row " << k;
  }
  EXPECT_THROW(attribute_extremes(reader, "nope"), InputError);
  fs::remove_all(dir);
}
