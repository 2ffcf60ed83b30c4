// The explorer site of ledgers (site.hpp: build_site of a ledger file or a
// folder of ledgers), against the site of the data set the ledger was
// written from: the same knot table and attribute table; each knot's files
// hold the states whose curve the ledger keeps; `knots site` refuses a
// damaged ledger.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "ek/dataset/dataset_file.hpp"
#include "ek/dataset/ledger.hpp"
#include "ek/site/site.hpp"
#include "testing.hpp"

using ek::clitest::run;
using ek::clitest::temp_dir;
using namespace ek;
using fixtures::read_at;
namespace fs = std::filesystem;
using PlainJson = nlohmann::json;  // key order ignored in comparisons

namespace {

/// A data set of 3_1 (one state) and 5_2 (three states) and its ledger,
/// which keeps the curves of two states per knot.
struct SmallRun {
  std::string dir, data, ledger;
};

SmallRun small_run(const std::string& name) {
  SmallRun r;
  r.dir = temp_dir(name);
  r.data = r.dir + "/d.h5";
  r.ledger = r.dir + "/d.ledger.h5";
  const auto out = run("dataset --names 3_1,5_2 --samples 6 -n 100 --no-stiffness --novelty-distance 0.05 --quiet "
                       "--jobs 2 -o " + r.data + " --ledger " + r.ledger + " --ledger-curves 2");
  EXPECT_EQ(out.status, 0) << out.err;
  return r;
}

PlainJson site_json(const SiteFiles& files) { return PlainJson::parse(files.at("data/site.json")); }

SiteOptions at_cut(double cut) {
  SiteOptions o;
  o.cut = cut;
  return o;
}

/// The knot table's fields computed from every stored equilibrium.
const char* const kTableFields[] = {"name",       "file",          "crossing_number", "bridge_index",
                                    "braid_index", "bb",           "two_bridge",      "alternating",
                                    "samples",     "runs",         "equilibria",      "distinct",
                                    "lowest_energy", "largest_threedim", "min_total_curvature", "milnor_ratio",
                                    "adaptive",    "complete",     "offset"};

void expect_same_table(const PlainJson& a, const PlainJson& b, const std::string& what) {
  ASSERT_EQ(a["knots"].size(), b["knots"].size()) << what;
  for (size_t i = 0; i < a["knots"].size(); ++i)
    for (const char* f : kTableFields) EXPECT_EQ(a["knots"][i][f], b["knots"][i][f]) << what << ": knot " << i << " " << f;
  EXPECT_EQ(a["attributes"], b["attributes"]) << what;
  EXPECT_EQ(a["attribute_names"], b["attribute_names"]) << what;
}

}  // namespace

// The ledger's site has the data set's knot table (every field computed from
// all stored equilibria, distinct states at the ledger's cut and at a coarser
// one from the ledger's dendrogram of all of them) and the same attribute
// table, byte for byte; site.json says where it came from.
TEST(SiteLedger, KnotTableEqualsTheDataSetsSite) {
  const SmallRun r = small_run("site_ledger_table");
  const Ledger ledger = read_ledger(r.ledger);
  for (double cut : {0.05, 0.3}) {
    const SiteFiles from_data = build_site(r.data, at_cut(cut)), from_ledger = build_site(r.ledger, at_cut(cut));
    const PlainJson a = site_json(from_data), b = site_json(from_ledger);
    expect_same_table(a, b, "cut " + std::to_string(cut));
    EXPECT_EQ(from_ledger.at("data/attributes.bin"), from_data.at("data/attributes.bin"));
    EXPECT_EQ(a["dataset"]["source"], "dataset");
    EXPECT_EQ(b["dataset"]["source"], "ledger");
    EXPECT_EQ(b["dataset"]["ledger_cut"], 0.05);
    EXPECT_EQ(b["dataset"]["curves_per_knot"], 2);
    EXPECT_FALSE(a["knots"][0].contains("shown_rows"));
  }
  const PlainJson b = site_json(build_site(r.ledger, at_cut(0.05)));
  ASSERT_EQ(b["knots"].size(), 2u);
  EXPECT_EQ(b["knots"][1]["name"], "5_2");
  EXPECT_EQ(b["knots"][1]["distinct"], ledger.entries[1].states.size());
  EXPECT_EQ(b["knots"][1]["distinct"], 3);  // more states than kept curves
  EXPECT_EQ(b["knots"][1]["equilibria"], 6);
}

// Each knot's files hold exactly its kept states, in energy order: their
// representatives' curves (the ledger's, as float32), attribute rows, samples
// and member counts; the similarity of the shown curves is the data set's
// comparison of those equilibria (recomputed from the quantised curves).
TEST(SiteLedger, KnotFilesHoldTheKeptStates) {
  const SmallRun r = small_run("site_ledger_knots");
  const Ledger ledger = read_ledger(r.ledger);
  const DatasetReader data(r.data);
  const SiteFiles files = build_site(r.ledger, SiteOptions());
  const PlainJson site = site_json(files);
  for (size_t k = 0; k < ledger.entries.size(); ++k) {
    const LedgerEntry& e = ledger.entries[k];
    const KnotEntry d = data.read(e.name);
    const PlainJson j = PlainJson::parse(files.at("data/knots/" + e.name + ".json"));
    const std::string& bin = files.at("data/knots/" + e.name + ".bin");
    std::vector<int> rows, members;
    for (const LedgerState& s : e.states) {
      if (s.curve.rows() == 0) continue;
      rows.push_back(s.representative);
      members.push_back(s.members);
    }
    ASSERT_EQ(rows.size(), std::min<size_t>(e.states.size(), 2)) << e.name;
    const int m = static_cast<int>(rows.size()), n = 100, cols = static_cast<int>(e.attributes.cols());
    EXPECT_EQ(j["equilibria"], m);
    EXPECT_EQ(j["members"].get<std::vector<int>>(), members);
    EXPECT_EQ(j["states"], e.states.size());
    EXPECT_EQ(site["knots"][k]["shown_rows"].get<std::vector<int>>(), rows);
    const PlainJson& buf = j["buffers"];
    const int energy = e.attribute_column("energy");
    for (int i = 0; i < m; ++i) {
      const LedgerState& s = e.states[static_cast<size_t>(i)];
      EXPECT_EQ(j["sample"][i], e.representative_sample(i));
      for (int c = 0; c < cols; ++c) {
        const double x = read_at<double>(bin, static_cast<size_t>((i * cols + c) * 8)), y = e.attributes(rows[i], c);
        EXPECT_TRUE(x == y || (std::isnan(x) && std::isnan(y))) << e.name << " state " << i << " column " << c;
      }
      if (i > 0) {
        EXPECT_LT(e.attributes(rows[i - 1], energy), e.attributes(rows[i], energy));
      }
      for (int v = 0; v < n; ++v)
        for (int c = 0; c < 3; ++c)
          ASSERT_EQ(read_at<float>(bin, buf["positions"]["offset"].get<size_t>() + static_cast<size_t>((i * n + v) * 3 + c) * 4),
                    static_cast<float>(s.curve(v, c)))
              << e.name << " state " << i << " vertex " << v;
      for (int q = 0; q < m; ++q) {
        const float sim = read_at<float>(bin, buf["similarity"]["offset"].get<size_t>() + static_cast<size_t>(i * m + q) * 4);
        EXPECT_NEAR(sim, d.similarity(rows[i], rows[q]), 1e-4) << e.name << " states " << i << ", " << q;
      }
    }
    EXPECT_EQ(bin.size(), static_cast<size_t>(m * cols * 8 + m * n * 12 + m * n * 4 + m * m * 4 + m * n));
  }
}

// A knot whose ledger keeps no curve stays in the table with its record
// unchanged, and its files show no state.
TEST(SiteLedger, KnotWithoutCurvesStaysInTheTable) {
  const SmallRun r = small_run("site_ledger_nocurve");
  Ledger ledger = read_ledger(r.ledger);
  for (LedgerState& s : ledger.entries[1].states) s.curve = Points(0, 3);
  const std::string bare = r.dir + "/bare.ledger.h5";
  write_ledger(bare, ledger);
  const SiteFiles full = build_site(r.ledger, SiteOptions()), files = build_site(bare, SiteOptions());
  expect_same_table(site_json(full), site_json(files), "without 5_2's curves");
  const PlainJson rec = site_json(files)["knots"][1];
  EXPECT_EQ(rec["equilibria"], 6);
  EXPECT_EQ(rec["distinct"], 3);
  EXPECT_TRUE(rec["shown_rows"].empty());
  const PlainJson j = PlainJson::parse(files.at("data/knots/5_2.json"));
  EXPECT_EQ(j["equilibria"], 0);
  EXPECT_EQ(j["states"], 3);
  EXPECT_TRUE(j["members"].empty());
  EXPECT_EQ(files.at("data/knots/5_2.bin").size(), 0u);
  EXPECT_EQ(PlainJson::parse(files.at("data/knots/3_1.json")), PlainJson::parse(full.at("data/knots/3_1.json")));
}

// A folder of two ledgers (one knot each) gives one site, the same as the
// ledger of both knots; `knots site FOLDER` writes it.
TEST(SiteLedger, FolderOfTwoLedgersIsOneSite) {
  const SmallRun r = small_run("site_ledger_folder");
  const Ledger both = read_ledger(r.ledger);
  const std::string folder = r.dir + "/ledgers";
  fs::create_directories(folder);
  for (size_t k = 0; k < 2; ++k) {
    Ledger one = both;
    one.entries = {both.entries[k]};
    write_ledger(folder + "/part-" + std::to_string(k) + ".ledger.h5", one);
  }
  const SiteFiles a = build_site(r.ledger, SiteOptions()), b = build_site(folder, SiteOptions());
  expect_same_table(site_json(a), site_json(b), "folder");
  for (const char* f : {"data/attributes.bin", "data/knots/3_1.json", "data/knots/3_1.bin", "data/knots/5_2.json",
                        "data/knots/5_2.bin"})
    EXPECT_EQ(a.at(f), b.at(f)) << f;
  EXPECT_EQ(site_json(b)["dataset"]["title"], fs::path(r.dir).filename().string() + "/ledgers");
  const auto out = run("site " + folder + "/ -o " + r.dir + "/site --json");
  ASSERT_EQ(out.status, 0) << out.err;
  EXPECT_EQ(out.json()["knots"], 2);
  EXPECT_EQ(PlainJson::parse(std::ifstream(r.dir + "/site/data/site.json"))["knots"].size(), 2u);
}

// `knots site` refuses a damaged ledger, alone or in a folder, with one line
// and exit status 2, and writes nothing.
TEST(SiteLedger, DamagedLedgerIsRefused) {
  const SmallRun r = small_run("site_ledger_damaged");
  std::string bytes = fixtures::read_bytes(r.ledger);
  bytes[bytes.size() / 2] = static_cast<char>(bytes[bytes.size() / 2] ^ 1);
  fs::create_directories(r.dir + "/folder");
  std::ofstream(r.dir + "/folder/bad.ledger.h5", std::ios::binary) << bytes;
  for (const std::string& in : {r.dir + "/folder/bad.ledger.h5", r.dir + "/folder"}) {
    const auto out = run("site " + in + " -o " + r.dir + "/site");
    EXPECT_EQ(out.status, 2) << in;
    EXPECT_EQ(std::count(out.err.begin(), out.err.end(), '\n'), 1) << out.err;
    EXPECT_NE(out.err.find("bad.ledger.h5' is damaged"), std::string::npos) << out.err;
    EXPECT_TRUE(out.out.empty()) << out.out;
    EXPECT_FALSE(fs::exists(r.dir + "/site")) << in;
  }
  const auto serve = run("serve " + r.dir + "/folder --port 0", 20);
  EXPECT_EQ(serve.status, 2) << serve.err;
}
