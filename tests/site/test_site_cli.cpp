// knots site and knots serve end to end: bad input is one line and exit
// status 2 with nothing written; a written site holds the data files.
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "cli_runner.hpp"
#include "ek/analysis/clustering.hpp"
#include "ek/dataset/dataset_file.hpp"
#include "ek/dataset/pipeline.hpp"
#include "testing.hpp"

using ek::clitest::run;
using ek::clitest::temp_dir;
namespace fs = std::filesystem;

namespace {

std::string small_dataset(const std::string& dir) {
  ek::KnotEntry e;
  e.name = "3_1";
  e.crossing_number = 3;
  e.bridge_index = 2;
  e.braid_index = 2;
  e.alexander = {1, -1, 1};
  for (int i = 0; i < 3; ++i) e.equilibria.push_back(ek::fixtures::random_fourier_curve(30, 3, 5 + i, 5.0));
  e.attribute_names = ek::dataset_attribute_names();
  e.attributes = Eigen::MatrixXd::Ones(3, static_cast<Eigen::Index>(e.attribute_names.size()));
  e.similarity = Eigen::MatrixXd::Constant(3, 3, 0.5);
  e.similarity.diagonal().setOnes();
  e.linkage = ek::complete_linkage_from_similarity(e.similarity).linkage_matrix();
  ek::DatasetMetadata meta = ek::dataset_metadata(ek::ExploreOptions{});  // every parameter the writer needs
  meta.sampling = "fixed:3";
  meta.created = "2026-11-24T00:00:00Z";
  meta.project_version = "test";
  const std::string path = dir + "/ds.h5";
  ek::DatasetWriter w(path, meta);
  w.add(e);
  w.commit();
  return path;
}

void expect_one_line_error(const ek::clitest::Result& r) {
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
}

}  // namespace

TEST(SiteCli, WritesTheSite) {
  const std::string dir = temp_dir("site_ok");
  const auto r = run("site " + small_dataset(dir) + " -o " + dir + "/site --json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.json()["knots"], 1);
  for (const char* f : {"index.html", "js/main.js", "data/site.json", "data/attributes.bin", "data/knots/3_1.bin",
                        "three/build/three.module.js"})
    EXPECT_TRUE(fs::exists(fs::path(dir) / "site" / f)) << f;
  // again: refused without --overwrite, replaced with it
  expect_one_line_error(run("site " + dir + "/ds.h5 -o " + dir + "/site"));
  EXPECT_EQ(run("site " + dir + "/ds.h5 -o " + dir + "/site --overwrite").status, 0);
}

TEST(SiteCli, BadInputWritesNothing) {
  const std::string dir = temp_dir("site_bad");
  std::ofstream(dir + "/text.h5") << "not a data set\n";
  expect_one_line_error(run("site " + dir + "/text.h5 -o " + dir + "/out"));
  expect_one_line_error(run("site " + dir + "/missing.h5 -o " + dir + "/out"));
  expect_one_line_error(run("site " + dir + "/text.h5"));
  expect_one_line_error(run("site " + small_dataset(dir) + " -o " + dir + "/out --cut 2"));
  EXPECT_FALSE(fs::exists(dir + "/out"));
  fs::create_directories(dir + "/mine");
  std::ofstream(dir + "/mine/notes.txt") << "keep\n";
  expect_one_line_error(run("site " + dir + "/ds.h5 -o " + dir + "/mine"));
  expect_one_line_error(run("site " + dir + "/ds.h5 -o " + dir + "/mine --overwrite"));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir + "/mine"), fs::directory_iterator{}), 1);
  for (const auto& e : fs::directory_iterator(dir))
    EXPECT_EQ(e.path().filename().string().find(".tmp."), std::string::npos) << e.path();
  expect_one_line_error(run("serve " + dir + "/text.h5 --port 0"));
  expect_one_line_error(run("serve " + dir + "/ds.h5 --port 70000"));
}

TEST(SiteCli, ServeRefusesATakenPort) {
  const std::string dir = temp_dir("site_port");
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ASSERT_EQ(::bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof a), 0);
  ASSERT_EQ(::listen(fd, 1), 0);
  socklen_t len = sizeof a;
  ::getsockname(fd, reinterpret_cast<sockaddr*>(&a), &len);
  const auto r = run("serve " + small_dataset(dir) + " --port " + std::to_string(ntohs(a.sin_port)));
  ::close(fd);
  expect_one_line_error(r);
  EXPECT_NE(r.err.find("cannot listen on 127.0.0.1"), std::string::npos) << r.err;
}
