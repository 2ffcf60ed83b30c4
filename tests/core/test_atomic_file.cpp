#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sys/wait.h>
#include <unistd.h>

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

// Temporaries of a process that is gone are removed; those of a live one
// (this process), of another prefix, and other files are kept.
TEST(AtomicFile, StaleTemporariesOfDeadProcessesAreRemoved) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::path(::testing::TempDir()) / "stale_temporaries";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) _exit(0);
  waitpid(child, nullptr, 0);  // reaped: its pid names no process
  const std::string dead = std::to_string(child), alive = std::to_string(::getpid());
  for (const std::string& name : {"a.h5.tmp." + dead + ".0", "a.h5.tmp." + alive + ".0", "b.h5.tmp." + dead + ".1",
                                 std::string("a.h5"), std::string("a.h5.tmp.x.0")})
    std::ofstream((dir / name).string()) << "x";
  remove_stale_temporaries(dir.string(), "a.h5");
  EXPECT_FALSE(fs::exists(dir / ("a.h5.tmp." + dead + ".0")));
  EXPECT_TRUE(fs::exists(dir / ("a.h5.tmp." + alive + ".0")));
  EXPECT_TRUE(fs::exists(dir / ("b.h5.tmp." + dead + ".1")));
  EXPECT_TRUE(fs::exists(dir / "a.h5"));
  EXPECT_TRUE(fs::exists(dir / "a.h5.tmp.x.0"));
  remove_stale_temporaries(dir.string(), "");
  EXPECT_FALSE(fs::exists(dir / ("b.h5.tmp." + dead + ".1")));
  remove_stale_temporaries((dir / "missing").string(), "");  // no folder: nothing to do, no error
  fs::remove_all(dir);
}
