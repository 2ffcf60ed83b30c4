#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "ek/core/atomic_file.hpp"
#include "ek/core/errors.hpp"

using namespace ek;

TEST(AtomicFile, CommitReplacesAndAbortKeepsOld) {
  const std::string path = ::testing::TempDir() + "atomic.txt";
  {
    std::ofstream(path) << "old\n";
  }
  {
    AtomicFile f(path);
    f.stream() << "new\n";
    // destroyed without commit: the old content stays, the temporary is removed
  }
  std::ifstream in(path);
  std::string s;
  in >> s;
  EXPECT_EQ(s, "old");
  for (const auto& e : std::filesystem::directory_iterator(::testing::TempDir()))
    EXPECT_EQ(e.path().string().find("atomic.txt.tmp"), std::string::npos);
  {
    AtomicFile f(path);
    f.stream() << "new\n";
    f.commit();
  }
  std::ifstream in2(path);
  in2 >> s;
  EXPECT_EQ(s, "new");
  std::remove(path.c_str());
}

TEST(AtomicFile, UnwritableDestinations) {
  EXPECT_THROW(AtomicFile("/nonexistent-dir/x.txt"), InputError);
  EXPECT_THROW(check_writable(::testing::TempDir()), InputError);  // a folder
  EXPECT_THROW(check_writable(""), InputError);
}
