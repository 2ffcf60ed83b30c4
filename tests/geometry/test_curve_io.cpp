#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "ek/core/errors.hpp"
#include "ek/geometry/curve_io.hpp"
#include "ek/geometry/polyline.hpp"
#include "testing.hpp"

using namespace ek;

using ek::fixtures::expect_input_error;

TEST(CurveIO, ReadsPeerFilesAsTheyAre) {
  const std::string dir = fixtures::peer_dir();
  const Points a = read_curve(dir + "/4_1-smooth.obj");
  EXPECT_EQ(a.rows(), 272);
  const Points b = read_curve(dir + "/9_47-cubiclattice.txt");
  EXPECT_EQ(b.rows(), 208);
  // lattice curve: integer coordinates, unit edges
  EXPECT_LT((b.array() - b.array().round()).abs().maxCoeff(), 1e-12);
  EXPECT_NEAR(edge_lengths(b).minCoeff(), 1.0, 1e-12);
  EXPECT_NEAR(edge_lengths(b).maxCoeff(), 1.0, 1e-12);
  const Points c = read_curve(dir + "/12n_838-braid.obj");
  EXPECT_EQ(c.rows(), 360);
}

TEST(CurveIO, RoundTripIsExact) {
  const Points P = fixtures::random_fourier_curve(57, 4, 11);
  for (const char* ext : {".obj", ".txt"}) {
    const std::string path = ::testing::TempDir() + "roundtrip" + ext;
    write_curve(path, P);
    const Points Q = read_curve(path);
    EXPECT_EQ((P - Q).cwiseAbs().maxCoeff(), 0.0) << ext;
    std::remove(path.c_str());
  }
}

// Vectors (velocities) in a curve file: every row in file order, equal rows
// and a last row equal to the first kept; bad numbers are one-line errors.
TEST(CurveIO, VectorsKeepEveryRowInFileOrder) {
  Points V(4, 3);
  V << 1, 0, 0, 1, 0, 0, 0, 2, 0, 1, 0, 0;
  for (const char* ext : {".obj", ".txt"}) {
    const std::string path = ::testing::TempDir() + "vectors" + ext;
    write_curve(path, V);
    EXPECT_EQ(read_vectors(path), V) << ext;
    std::remove(path.c_str());
  }
  const std::string bad = ::testing::TempDir() + "vectors_bad.txt";
  std::ofstream(bad) << "1 2 3\n4 nan 6\n";
  fixtures::expect_input_error([&] { read_vectors(bad); }, "vectors_bad.txt:2");
  std::remove(bad.c_str());
}

TEST(CurveIO, ObjLineOrderDefinesVertexOrder) {
  const std::string text = "v 0 0 0\nv 1 1 0\nv 1 0 0\nv 0 1 0\nl 1 3\nl 3 2\nl 2 4\nl 4 1\n";
  const Points P = parse_curve(text, "obj", "test");
  Points expected(4, 3);
  expected << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0;
  EXPECT_EQ(P, expected);
  // polyline form "l 1 3 2 4 1" and explicit closing vertex
  EXPECT_EQ(parse_curve("v 0 0 0\nv 1 1 0\nv 1 0 0\nv 0 1 0\nl 1 3 2 4 1\n", "obj", "t"), expected);
  EXPECT_EQ(parse_curve("0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 0\n", "txt", "t"), expected);
}

TEST(CurveIO, MalformedInput) {
  expect_input_error([] { parse_curve("0 0 0\n1 0 0\n1 1\n0 1 0\n", "txt", "f.txt"); },
                     "f.txt:3: expected 3 coordinates");
  expect_input_error([] { parse_curve("0 0 0\n1 0 0\n1 1 nan\n0 1 0\n", "txt", "f.txt"); }, "not finite");
  expect_input_error([] { parse_curve("0 0 0\n1 0 0\n1 1 inf\n0 1 0\n", "txt", "f.txt"); }, "not finite");
  expect_input_error([] { parse_curve("0 0 0\n1 0 0\n1 1 x\n0 1 0\n", "txt", "f.txt"); }, "'x' is not a number");
  expect_input_error([] { parse_curve("0 0 0\n1 0 0\n1 1 0\n", "txt", "f.txt"); }, "at least 4 vertices, got 3");
  expect_input_error([] { parse_curve("0 0 0\n1 0 0\n1 0 0\n1 1 0\n0 1 0\n", "txt", "f.txt"); },
                     "vertices 2 and 3 coincide");
  expect_input_error([] { parse_curve("", "txt", "f.txt"); }, "no vertices");
  expect_input_error([] { parse_curve("v 0 0\n", "obj", "f.obj"); }, "f.obj:1: vertex line needs 3 coordinates");
  expect_input_error([] { parse_curve("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nl 1 9\n", "obj", "f.obj"); },
                     "out of range");
  expect_input_error([] { parse_curve("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nl 1 2\nl 3 4\n", "obj", "f.obj"); },
                     "several curves");
  expect_input_error(
      [] { parse_curve("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nl 1 2\nl 1 3\nl 1 4\n", "obj", "f.obj"); },
      "expected one closed curve");
  expect_input_error([] { parse_curve("v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\n", "obj", "f.obj"); }, "faces");
  expect_input_error([] { read_curve("/nonexistent/curve.obj"); }, "cannot open");
  expect_input_error([] { read_curve("curve.xyz"); }, "unknown curve format");
}

TEST(CurveIO, FailedWriteLeavesExistingFileIntact) {
  const std::string path = ::testing::TempDir() + "keep.txt";
  {
    std::ofstream(path) << "precious\n";
  }
  // an unwritable destination folder: the error comes before anything is touched
  expect_input_error([] { write_curve("/nonexistent-folder/x.obj", fixtures::circle(8, 1)); }, "does not exist");
  expect_input_error([&] { write_curve(path.substr(0, path.size() - 4) + ".bad", fixtures::circle(8, 1)); },
                     "unknown curve format");
  std::ifstream in(path);
  std::string s;
  std::getline(in, s);
  EXPECT_EQ(s, "precious");
  std::remove(path.c_str());
}
