// The data files of the explorer site (ek/site/site.hpp), the crash-safe
// site folder, and the loopback server's answers (ek/site/server.hpp).
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "ek/analysis/clustering.hpp"
#include "ek/core/errors.hpp"
#include "ek/dataset/pipeline.hpp"
#include "ek/site/server.hpp"
#include "ek/site/site.hpp"
#include "testing.hpp"

using namespace ek;
using fixtures::read_at;
namespace fs = std::filesystem;

namespace {

/// A closed "hairpin": along y = 0 from x = 0 to 10 in unit edges, up to
/// y = gap, and back along y = gap: the two long sides are `gap` apart.
Points hairpin(double gap) {
  Points P(22, 3);
  for (int i = 0; i <= 10; ++i) P.row(i) << i, 0.0, 0.0;
  for (int i = 0; i <= 10; ++i) P.row(11 + i) << 10 - i, gap, 0.0;
  return P;
}

/// Four equilibria: 0 ~ 1 (similarity 0.99), 2 and 3 apart; energies 1.0,
/// 1.05, 1.1, 2.0. Clusters at 0.05: {0, 1}, {2}, {3}.
KnotEntry entry(const std::string& name) {
  KnotEntry e;
  e.name = name;
  e.crossing_number = 4;
  e.bridge_index = 2;
  e.braid_index = 3;
  e.alexander = {-1, 3, -1};
  for (int i = 0; i < 4; ++i) e.equilibria.push_back(fixtures::random_fourier_curve(40, 3, 20 + i, 5.0));
  e.attribute_names = dataset_attribute_names();
  e.attributes = Eigen::MatrixXd::Zero(4, static_cast<Eigen::Index>(e.attribute_names.size()));
  const double energy[] = {1.0, 1.05, 1.1, 2.0}, threedim[] = {0.05, 0.06, 0.3, 0.5};
  for (int i = 0; i < 4; ++i) {
    e.attributes(i, e.attribute_column("energy")) = energy[i];
    e.attributes(i, e.attribute_column("threedim")) = threedim[i];
    e.attributes(i, e.attribute_column("total_curvature")) = 4.5 * M_PI + i;
  }
  e.similarity = Eigen::MatrixXd::Constant(4, 4, 0.5);
  e.similarity.diagonal().setOnes();
  e.similarity(0, 1) = e.similarity(1, 0) = 0.99;
  e.linkage = complete_linkage_from_similarity(e.similarity).linkage_matrix();
  for (int s = 0; s < 5; ++s) {
    RunRecord r;
    r.sample = s;
    r.status = s < 4 ? RunStatus::ConvergedStable : RunStatus::Stalled;
    r.equilibrium = s < 4 ? s : -1;
    e.runs.push_back(r);
  }
  e.samples_used = 5;
  return e;
}

std::string dataset(const std::string& name) {
  const std::string path = ::testing::TempDir() + name;
  DatasetMetadata meta = dataset_metadata(ExploreOptions{});  // every parameter the writer needs
  meta.project_version = "test";
  meta.created = "2026-11-24T00:00:00Z";
  meta.sampling = "fixed:5";
  DatasetWriter w(path, meta);
  w.add(entry("4_1"));
  w.add(entry("3_1"));
  w.commit();
  return path;
}

std::string fresh_dir(const std::string& name) {
  const std::string dir = ::testing::TempDir() + "site_" + name;
  fs::remove_all(dir);
  return dir;
}

}  // namespace

// Turning angle 2π/n over the Voronoi length (the edge length L) at every vertex of a regular n-gon.
TEST(Site, CurvatureOfARegularPolygon) {
  const int n = 12;
  const double R = 3.0, L = 2.0 * R * std::sin(M_PI / n);
  Points P(n, 3);
  for (int i = 0; i < n; ++i) P.row(i) << R * std::cos(2 * M_PI * i / n), R * std::sin(2 * M_PI * i / n), 0.0;
  for (double k : vertex_curvature(P)) EXPECT_NEAR(k, (2 * M_PI / n) / L, 1e-12);
}

// The hairpin's long sides are 0.3 apart: every long edge is in contact at
// d̂ = 0.4 and none at d̂ = 0.2; the two short end edges are never (their
// neighbours share a vertex, the other edges are at least 1 away).
TEST(Site, ContactFlagsOfAHairpin) {
  const Points P = hairpin(0.3);
  const auto on = contact_edges(P, 0.4), off = contact_edges(P, 0.2);
  for (int i = 0; i < 22; ++i) {
    const bool end = i == 10 || i == 21;
    EXPECT_EQ(on[static_cast<size_t>(i)], end ? 0 : 1) << "edge " << i;
    EXPECT_EQ(off[static_cast<size_t>(i)], 0) << "edge " << i;
  }
}

// Two rings of 12 and 16 vertices in one plane, 0.3 apart where they pass: a link entry's
// files carry its components and its own columns; the curvature is each
// ring's (a regular polygon's, no kink where the components meet in the
// array); only the two edges that pass each other are in contact at d̂ = 0.4,
// and none at d̂ = 0.2.
TEST(Site, LinkDataFiles) {
  const Points a = fixtures::circle(12, Vec3::Zero(), 3.0, Vec3::UnitX(), Vec3::UnitY());
  const Points b = fixtures::circle(16, Vec3(3.3 + 4.0, 0.0, 0.0), 4.0, -Vec3::UnitX(), Vec3::UnitY());
  KnotEntry e;
  e.name = "two_rings";
  e.components = {12, 16};
  Points both(28, 3);
  both << a, b;
  e.equilibria = {both};
  e.attribute_names = link_attribute_names();
  e.attributes = Eigen::MatrixXd::Zero(1, static_cast<Eigen::Index>(e.attribute_names.size()));
  e.similarity = Eigen::MatrixXd::Ones(1, 1);
  e.linkage.resize(0, 4);
  const KnotSiteData d = knot_site_data(e, "two_rings", 0.4, 0.002);
  const auto j = nlohmann::json::parse(d.json);
  EXPECT_EQ(j["components"], nlohmann::json::array({12, 16}));
  EXPECT_EQ(j["attribute_names"].get<std::vector<std::string>>(), link_attribute_names());
  const auto& buf = j["buffers"];
  const double La = 2.0 * 3.0 * std::sin(M_PI / 12), Lb = 2.0 * 4.0 * std::sin(M_PI / 16);
  for (int v = 0; v < 28; ++v) {
    const float k = read_at<float>(d.binary, buf["curvature"]["offset"].get<size_t>() + static_cast<size_t>(v) * 4);
    EXPECT_NEAR(k, v < 12 ? (2 * M_PI / 12) / La : (2 * M_PI / 16) / Lb, 1e-5) << "vertex " << v;
  }
  const auto on = contact_edges(both, CurveTopology::from_sizes({12, 16}), 0.4);
  const auto off = contact_edges(both, CurveTopology::from_sizes({12, 16}), 0.2);
  for (int i = 0; i < 28; ++i) {
    // a's edges 11 and 0 meet at (3, 0, 0), b's edges 15 and 0 at (3.3, 0, 0)
    const bool near = i == 0 || i == 11 || i == 12 + 0 || i == 12 + 15;
    EXPECT_EQ(on[static_cast<size_t>(i)], near ? 1 : 0) << "edge " << i;
    EXPECT_EQ(off[static_cast<size_t>(i)], 0) << "edge " << i;
  }
}

TEST(Site, KnotFileNamesStayInTheirFolder) {
  EXPECT_EQ(knot_file_name("12a_1019"), "12a_1019");
  EXPECT_EQ(knot_file_name("0_1"), "0_1");
  EXPECT_EQ(knot_file_name("../x"), "~2E.~2Fx");
  EXPECT_EQ(knot_file_name("a b"), "a~20b");
  EXPECT_EQ(knot_file_name(""), "~");
}

// The JSON and the binary arrays of one knot: the clusters as clusters_at_cut,
// the MDS of the similarity, and the arrays' layout and values.
TEST(Site, KnotDataFiles) {
  const KnotEntry e = entry("4_1");
  const KnotSiteData d = knot_site_data(e, "4_1", 0.4, 0.05);
  const auto j = nlohmann::json::parse(d.json);
  EXPECT_EQ(j["format"], "elastic-knots-site-knot");
  EXPECT_EQ(j["format_version"], kSiteFormatVersion);
  EXPECT_EQ(d.distinct, 3);
  EXPECT_EQ(j["distinct"], 3);
  std::vector<int> rank;
  EXPECT_EQ(clusters_at_cut(e, 0.05, &rank).size(), 3u);
  EXPECT_EQ(j["cluster_rank"].get<std::vector<int>>(), rank);
  EXPECT_EQ(j["sample"].get<std::vector<int>>(), (std::vector<int>{0, 1, 2, 3}));
  ASSERT_EQ(j["mds"].size(), 4u);
  // 0 and 1 nearly coincide in the MDS map (distance 0.01), 2 and 3 are ~0.5 from them
  const auto p = j["mds"];
  const double d01 = std::hypot(p[0][0].get<double>() - p[1][0].get<double>(), p[0][1].get<double>() - p[1][1].get<double>());
  const double d02 = std::hypot(p[0][0].get<double>() - p[2][0].get<double>(), p[0][1].get<double>() - p[2][1].get<double>());
  EXPECT_LT(d01, 0.05);
  EXPECT_GT(d02, 0.3);
  ASSERT_EQ(j["linkage"].size(), 3u);
  EXPECT_EQ(j["linkage"][0][2].get<double>(), e.linkage(0, 2));  // exact round trip of the heights
  const int m = 4, n = 40, c = static_cast<int>(e.attributes.cols()), a = m * c * 8;
  const auto& b = j["buffers"];
  // the knot's attributes first (8-byte aligned float64), then the float32 arrays
  EXPECT_EQ(b["attributes"]["offset"], 0);
  EXPECT_EQ(b["attributes"]["shape"], nlohmann::json::array({m, c}));
  EXPECT_EQ(b["positions"]["offset"], a);
  EXPECT_EQ(b["curvature"]["offset"], a + m * n * 3 * 4);
  EXPECT_EQ(b["similarity"]["offset"], a + m * n * 3 * 4 + m * n * 4);
  EXPECT_EQ(b["contact"]["offset"], a + m * n * 3 * 4 + m * n * 4 + m * m * 4);
  ASSERT_EQ(d.binary.size(), static_cast<size_t>(a + m * n * 3 * 4 + m * n * 4 + m * m * 4 + m * n));
  EXPECT_EQ(j["binary_bytes"], d.binary.size());
  EXPECT_EQ(read_at<double>(d.binary, (3 * c + 0) * 8), e.attributes(3, 0));
  EXPECT_EQ(read_at<float>(d.binary, a + (2 * n * 3 + 5 * 3 + 1) * 4), static_cast<float>(e.equilibria[2](5, 1)));
  EXPECT_EQ(read_at<float>(d.binary, b["curvature"]["offset"].get<size_t>() + (3 * n + 7) * 4),
            static_cast<float>(vertex_curvature(e.equilibria[3])[7]));
  EXPECT_EQ(read_at<float>(d.binary, b["similarity"]["offset"].get<size_t>() + (0 * m + 1) * 4), 0.99f);
}

TEST(Site, OneAndNoEquilibrium) {
  KnotEntry e = entry("x");
  e.equilibria.resize(1);
  e.attributes.conservativeResize(1, Eigen::NoChange);
  for (RunRecord& r : e.runs) r.equilibrium = r.equilibrium == 0 ? 0 : -1;
  e.similarity = Eigen::MatrixXd::Ones(1, 1);
  e.linkage.resize(0, 4);
  auto j = nlohmann::json::parse(knot_site_data(e, "x", 0.4, 0.05).json);
  EXPECT_EQ(j["distinct"], 1);
  EXPECT_EQ(j["leaf_order"], nlohmann::json::array({0}));
  e.equilibria.clear();
  e.attributes.resize(0, e.attributes.cols());
  e.similarity.resize(0, 0);
  for (RunRecord& r : e.runs) r.equilibrium = -1;
  j = nlohmann::json::parse(knot_site_data(e, "x", 0.4, 0.05).json);
  EXPECT_EQ(j["distinct"], 0);
  EXPECT_EQ(j["mds"].size(), 0u);
}

// The whole site of a two-knot data set: the table's fields, the attribute
// table's layout, the pages and three.js.
TEST(Site, BuildsEveryFile) {
  const SiteFiles files = build_site(dataset("site_build.h5"), SiteOptions());
  for (const char* f : {"index.html", "style.css", "js/main.js", "js/viewer.js", "three/build/three.module.js",
                        "three/examples/jsm/controls/OrbitControls.js", "data/site.json", "data/attributes.bin",
                        "data/knots/4_1.json", "data/knots/4_1.bin", "data/knots/3_1.json"})
    EXPECT_TRUE(files.count(f)) << f;
  const auto site = nlohmann::json::parse(files.at("data/site.json"));
  EXPECT_EQ(site["format"], kSiteFormat);
  EXPECT_EQ(site["format_version"], kSiteFormatVersion);
  ASSERT_EQ(site["knots"].size(), 2u);
  const auto& k = site["knots"][1];
  EXPECT_EQ(k["name"], "3_1");
  EXPECT_EQ(k["offset"], 4);
  EXPECT_EQ(k["distinct"], 3);
  EXPECT_EQ(k["equilibria"], 4);
  EXPECT_EQ(k["samples"], 5);
  EXPECT_EQ(k["bb"], false);
  EXPECT_EQ(k["two_bridge"], true);
  EXPECT_EQ(k["lowest_energy"], 1.0);
  EXPECT_EQ(k["largest_threedim"], 0.5);
  EXPECT_NEAR(k["milnor_ratio"].get<double>(), 4.5 * M_PI / (2 * 2 * M_PI), 1e-15);
  EXPECT_EQ(k["alternating"], true);  // 3_1 in the KnotInfo table
  const size_t cols = dataset_attribute_names().size();
  EXPECT_EQ(site["attributes"]["rows"], 8);
  EXPECT_EQ(files.at("data/attributes.bin").size(), 8 * cols * 8);
  EXPECT_EQ(read_at<double>(files.at("data/attributes.bin"), (4 + 3) * cols * 8), 2.0);  // 3_1 #3 energy (column 0)
}

TEST(Site, RejectsWhatIsNotADataSet) {
  const std::string bad = ::testing::TempDir() + "not_a_dataset.h5";
  std::ofstream(bad) << "hello\n";
  EXPECT_THROW(build_site(bad, SiteOptions()), InputError);
  EXPECT_THROW(build_site(::testing::TempDir() + "missing.h5", SiteOptions()), InputError);
  SiteOptions o;
  o.three_dir = "/nonexistent";
  EXPECT_THROW(build_site(dataset("site_three.h5"), o), InputError);
  o = SiteOptions();
  o.cut = 1.5;
  EXPECT_THROW(o.validate(), InputError);
}

// write_site: a new folder; an existing site only with overwrite; a folder
// with other files never (its files stay); nothing else is left behind.
TEST(Site, FolderIsWrittenSafely) {
  const SiteFiles files = {{"index.html", "a"}, {"data/site.json", R"({"format": "elastic-knots-site"})"}};
  const std::string dir = fresh_dir("write");
  write_site(files, dir, false);
  EXPECT_EQ(fixtures::read_bytes(fs::path(dir) / "index.html"), "a");
  EXPECT_THROW(write_site(files, dir, false), InputError);
  SiteFiles second = files;
  second["index.html"] = "b";
  write_site(second, dir + "/", true);
  EXPECT_EQ(fixtures::read_bytes(fs::path(dir) / "index.html"), "b");
  const std::string other = fresh_dir("other");
  fs::create_directories(other);
  std::ofstream(other + "/notes.txt") << "mine\n";
  EXPECT_THROW(write_site(files, other, false), InputError);
  EXPECT_THROW(write_site(files, other, true), InputError);
  EXPECT_EQ(fixtures::read_bytes(fs::path(other) / "notes.txt"), "mine\n");
  EXPECT_FALSE(fs::exists(fs::path(other) / "index.html"));
  const std::string empty = fresh_dir("empty");
  fs::create_directories(empty);
  write_site(files, empty, false);
  EXPECT_TRUE(fs::exists(fs::path(empty) / "data/site.json"));
  EXPECT_THROW(write_site({{"../escape", "x"}}, fresh_dir("escape"), false), std::logic_error);
  EXPECT_FALSE(fs::exists(::testing::TempDir() + "escape"));
  // no temporary of this test's folders is left (other tests' folders, written meanwhile, are theirs)
  for (const auto& entry : fs::directory_iterator(::testing::TempDir())) {
    const std::string name = entry.path().filename().string();
    for (const char* mine : {"site_write", "site_other", "site_empty", "site_escape"})
      if (name.rfind(mine, 0) == 0) {
        EXPECT_EQ(name.find(".tmp."), std::string::npos) << entry.path();
      }
  }
  EXPECT_THROW(check_site_folder(::testing::TempDir() + "no/such/parent", false), InputError);
}

TEST(Site, ServerAnswersOnlyTheSitesFiles) {
  const SiteFiles files = {{"index.html", "<html>"}, {"js/main.js", "x"}, {"data/site.json", "{}"}};
  EXPECT_EQ(respond(files, "GET", "/").body, "<html>");
  EXPECT_EQ(respond(files, "GET", "/index.html").content_type, "text/html; charset=utf-8");
  EXPECT_EQ(respond(files, "GET", "/js/main.js").content_type, "text/javascript; charset=utf-8");
  EXPECT_EQ(respond(files, "GET", "/data/site.json?v=2#x").status, 200);
  EXPECT_EQ(respond(files, "GET", "/js/%6Dain.js").status, 200);
  EXPECT_EQ(respond(files, "HEAD", "/js/main.js").status, 200);
  for (const char* t : {"/../etc/passwd", "/js/../index.html", "/%2e%2e/x", "/js/%2E%2E/%2e%2e/etc/passwd", "/./index.html",
                        "/a%5C..%5Cb", "/x%00y"})
    EXPECT_EQ(respond(files, "GET", t).status, 403) << t;
  EXPECT_EQ(respond(files, "GET", "/etc/passwd").status, 404);
  EXPECT_EQ(respond(files, "GET", "/js/").status, 404);
  EXPECT_EQ(respond(files, "GET", "/a%zz").status, 400);
  EXPECT_EQ(respond(files, "GET", "/a%4").status, 400);
  EXPECT_EQ(respond(files, "GET", "index.html").status, 400);
  EXPECT_EQ(respond(files, "POST", "/").status, 405);
  EXPECT_EQ(respond(files, "DELETE", "/index.html").status, 405);
  EXPECT_EQ(http_message(respond(files, "HEAD", "/"), true).find("<html>"), std::string::npos);
}

namespace {

std::string http_get(int port, const std::string& request) {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(static_cast<uint16_t>(port));
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (::connect(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0) {
    ::close(fd);
    return "";
  }
  ::send(fd, request.data(), request.size(), 0);
  std::string out;
  char buf[4096];
  for (ssize_t k; (k = ::recv(fd, buf, sizeof buf, 0)) > 0;) out.append(buf, static_cast<size_t>(k));
  ::close(fd);
  return out;
}

}  // namespace

// The server on a free loopback port, over real sockets; a taken port is an input error.
TEST(Site, ServerOnLoopback) {
  ServeOptions o;
  o.port = 0;
  SiteServer server({{"index.html", "<html>hello"}}, o);
  std::atomic<bool> stop{false};
  std::thread t([&] { server.serve(stop); });
  const std::string ok = http_get(server.port(), "GET / HTTP/1.1\r\nHost: x\r\n\r\n");
  EXPECT_EQ(ok.rfind("HTTP/1.1 200 OK\r\n", 0), 0u) << ok;
  EXPECT_NE(ok.find("\r\n\r\n<html>hello"), std::string::npos);
  EXPECT_EQ(http_get(server.port(), "GET /../index.html HTTP/1.1\r\n\r\n").rfind("HTTP/1.1 403", 0), 0u);
  EXPECT_EQ(http_get(server.port(), "garbage\r\n\r\n").rfind("HTTP/1.1 400", 0), 0u);
  ServeOptions same = o;
  same.port = server.port();
  EXPECT_THROW(SiteServer({}, same), InputError);
  stop = true;
  t.join();
}
