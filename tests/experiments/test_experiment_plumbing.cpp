// Reruns of an experiment (experiments/common/experiment.hpp): a finished run
// is recomputed, never extended (its data sets would keep the old equilibria
// of every knot they hold); an unfinished run is resumed; the finished run's
// folder survives until the rerun finishes.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "ek/core/errors.hpp"
#include "experiment.hpp"
#include "testing.hpp"

namespace fs = std::filesystem;
using namespace ek::exp;

namespace {

struct Folder {
  fs::path root;
  Folder() {
    root = fs::temp_directory_path() /
           ("ek_experiment_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(root);
    fs::create_directories(root);
  }
  ~Folder() { fs::remove_all(root); }
};

void touch(const fs::path& p, const std::string& text) {
  std::ofstream(p) << text;
}

// A folder holding a finished run of a data-set experiment.
fs::path finished_run(const Folder& f) {
  const fs::path out = f.root / "dataset";
  fs::create_directories(out);
  touch(out / "dataset.h5", "old equilibria");
  touch(out / "summary.json", "{}");
  return out;
}

int run(const fs::path& out, const std::function<void(const Args&)>& body) {
  std::vector<std::string> args = {"exp_test", "--scale", "ci", "--out", out.string()};
  std::vector<char*> argv;
  for (auto& s : args) argv.push_back(s.data());
  return run_experiment(static_cast<int>(argv.size()), argv.data(), "exp_test", "test", body);
}

}  // namespace

TEST(ExperimentReruns, AFinishedRunIsRecomputedFromAnEmptyFolder) {
  Folder f;
  const fs::path out = finished_run(f);
  bool saw_old_files = true, saw_previous = false;
  const int status = run(out, [&](const Args& a) {
    saw_old_files = fs::exists(fs::path(a.out) / "dataset.h5") || fs::exists(fs::path(a.out) / "summary.json");
    saw_previous = ek::fixtures::read_bytes(previous_folder(a.out) / "dataset.h5") == "old equilibria";
    touch(fs::path(a.out) / "summary.json", "{\"new\": 1}");
  });
  EXPECT_EQ(status, 0);
  EXPECT_FALSE(saw_old_files) << "the rerun must start from an empty folder";
  EXPECT_TRUE(saw_previous) << "the finished run is kept as DIR.previous while the rerun runs";
  EXPECT_FALSE(fs::exists(previous_folder(out.string()))) << "DIR.previous is removed once the rerun finished";
  EXPECT_EQ(ek::fixtures::read_bytes(out / "summary.json"), "{\"new\": 1}");
}

TEST(ExperimentReruns, AFailedRerunKeepsTheFinishedRunAndTheNextRunResumesIt) {
  Folder f;
  const fs::path out = finished_run(f);
  // The rerun fails (bad input) after writing part of its work.
  const int failed = run(out, [&](const Args& a) {
    touch(fs::path(a.out) / "journal", "half the runs");
    throw ek::InputError("unwritable output");
  });
  EXPECT_EQ(failed, 2);
  EXPECT_EQ(ek::fixtures::read_bytes(previous_folder(out.string()) / "dataset.h5"), "old equilibria");
  EXPECT_EQ(ek::fixtures::read_bytes(out / "journal"), "half the runs");
  // No summary.json: the next run resumes the unfinished folder as it is.
  std::string journal_seen;
  const int resumed = run(out, [&](const Args& a) {
    journal_seen = ek::fixtures::read_bytes(fs::path(a.out) / "journal");
    touch(fs::path(a.out) / "summary.json", "{}");
  });
  EXPECT_EQ(resumed, 0);
  EXPECT_EQ(journal_seen, "half the runs");
  EXPECT_FALSE(fs::exists(previous_folder(out.string())));
}

TEST(ExperimentReruns, ATrailingSlashNamesTheSameFolder) {
  Folder f;
  const fs::path out = f.root / "milnor";
  fs::create_directories(out);
  touch(out / "summary.json", "{}");
  EXPECT_EQ(previous_folder(out.string() + "/"), previous_folder(out.string()));
  bool empty = false;
  EXPECT_EQ(run(out.string() + "/", [&](const Args& a) { empty = fs::is_empty(a.out); }), 0);
  EXPECT_TRUE(empty);
  EXPECT_FALSE(fs::exists(f.root / "milnor.previous"));
}
