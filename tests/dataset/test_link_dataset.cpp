// Data sets of links: explore_link on the link table's Hopf link and
// Borromean rings (every stored equilibrium of the link type, the file's
// link fields read back, the clustering on the link state distance), the
// options a link does not have, and the command line end to end (explore,
// describe order, cluster, export of a link file whose invariants are the
// table's, query, search skipping links, an existing knot data set with
// other parameters refused).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "cli_runner.hpp"
#include "ek/dataset/dataset_file.hpp"
#include "ek/dataset/pipeline.hpp"
#include "ek/knots/invariants.hpp"
#include "ek/knots/link_table.hpp"
#include "first_layout.hpp"
#include "testing.hpp"

using namespace ek;
using ek::clitest::run;
using ek::clitest::temp_dir;
namespace fs = std::filesystem;

namespace {

ExploreOptions link_options(int samples, int vertices) {
  ExploreOptions o;
  o.relax = with_method(o.relax, "hybrid");  // the direct method, as the link model relaxes
  o.stiffness = false;
  o.samples = samples;
  o.sampling.vertices = vertices;
  return o;
}

}  // namespace

TEST(LinkDataset, BorromeanEntryHoldsTheLinkTypeAndReadsBack) {
  const LinkRecord& b = *find_link("borromean");
  const KnotEntry e = explore_link(b, link_options(4, 180));
  ASSERT_EQ(e.components.size(), 3u);
  EXPECT_EQ(e.components[0] + e.components[1] + e.components[2], 180);
  EXPECT_EQ(e.conway, b.conway.coefficients);
  EXPECT_EQ(e.linking_numbers, std::vector<std::int64_t>(9, 0));
  EXPECT_EQ(e.attribute_names, link_attribute_names());
  ASSERT_EQ(e.runs.size(), 4u);
  ASSERT_GE(e.equilibria.size(), 3u);  // measured: 4 of 4 converged-stable
  for (const RunRecord& r : e.runs) EXPECT_TRUE(r.topology_preserved) << r.status;
  for (int i = 0; i < static_cast<int>(e.equilibria.size()); ++i) {
    const LinkType t = link_type(e.equilibrium_link(i));  // an independent check of the stored curve
    EXPECT_EQ(t.conway.coefficients, b.conway.coefficients) << i;
    EXPECT_EQ(t.linking_numbers, b.linking_matrix()) << i;
  }
  // the energy column is the total E_rod + ω E_contact, as a knot's
  const int ec = e.attribute_column("energy"), sc = e.attribute_column("energy_stretch"),
            bc = e.attribute_column("energy_bend"), cc = e.attribute_column("energy_contact");
  EXPECT_NEAR(e.attributes(0, ec), e.attributes(0, sc) + e.attributes(0, bc) + e.attributes(0, cc), 1e-12);
  EXPECT_EQ(e.runs[0].energy, e.attributes(0, ec));  // the run's energy is the same total
  EXPECT_GT(e.attributes(0, e.attribute_column("min_distance")), 0.0);
  // similarity: 1 on the diagonal, 1 − d off it, one cluster at the link cut
  const auto m = static_cast<Eigen::Index>(e.equilibria.size());
  for (Eigen::Index i = 0; i < m; ++i) EXPECT_EQ(e.similarity(i, i), 1.0);
  EXPECT_EQ(e.linkage.rows(), m - 1);

  const std::string dir = temp_dir("link_ds");
  {
    DatasetMetadata meta = dataset_metadata(link_options(4, 180));
    meta.created = "2026-12-03T00:00:00Z";
    DatasetWriter w(dir + "/b.h5", meta);
    w.add(e);
    w.commit();
  }
  const KnotEntry back = DatasetReader(dir + "/b.h5").read("borromean");
  EXPECT_EQ(back.components, e.components);
  EXPECT_EQ(back.conway, e.conway);
  EXPECT_EQ(back.linking_numbers, e.linking_numbers);
  EXPECT_TRUE(back.is_link());
  ASSERT_EQ(back.equilibrium_link(0).size(), 3u);
  EXPECT_EQ(back.equilibrium_link(0)[2], e.equilibrium_link(0)[2]);
  fs::remove_all(dir);
}

// A journal begun before its second record layout (one slot for a link's
// closest approach, the energy total without contact, contacts not counted)
// resumes to the entry a run from scratch gives: the same runs (but their
// contacts, which the old records lack) and, to the bit, the same
// attributes, none relaxed again.
TEST(LinkDataset, AJournalOfTheFirstLayoutResumesToTheSameEntry) {
  const std::string journal = ::testing::TempDir() + "borromean_first_layout.journal";
  fs::remove(journal);
  const ExploreOptions o = link_options(2, 180);
  const KnotEntry fresh = explore_link(*find_link("borromean"), o, journal);
  ASSERT_GT(fresh.attributes.col(fresh.attribute_column("energy_contact")).maxCoeff(), 0.0);  // in contact
  std::string bytes = fixtures::read_bytes(journal);
  const size_t head = bytes.find('\n', bytes.find('\n') + 1) + 1;  // the header line and the options line
  {
    std::ofstream out(journal, std::ios::binary | std::ios::trunc);
    out << testing_journal::to_first_layout(bytes, head, true);
  }
  int relaxed = 0;
  const KnotEntry resumed = explore_link(*find_link("borromean"), o, journal, [&](const RunRecord&) { ++relaxed; });
  EXPECT_EQ(relaxed, 0);
  ASSERT_EQ(resumed.runs.size(), fresh.runs.size());
  for (size_t k = 0; k < fresh.runs.size(); ++k) {
    const RunRecord &a = resumed.runs[k], &b = fresh.runs[k];
    EXPECT_TRUE(a.sample == b.sample && a.seed == b.seed && a.status == b.status && a.equilibrium == b.equilibrium &&
                a.iterations == b.iterations && a.energy == b.energy && a.gradient_norm == b.gradient_norm &&
                a.topology_preserved == b.topology_preserved && a.message == b.message)
        << k;
    EXPECT_EQ(a.contacts, 0) << k;
  }
  EXPECT_TRUE(resumed.attributes == fresh.attributes);
  fs::remove(journal);
}

TEST(LinkDataset, HopfLinkRingsAreOneState) {
  // Two rings that do not touch relax to free round circles: every placement
  // is the same state, d at the resampling floor.
  const KnotEntry e = explore_link(*find_link("hopf"), link_options(4, 160));
  ASSERT_GE(e.equilibria.size(), 3u);
  EXPECT_EQ(clusters_at_cut(e, 0.002).size(), 1u);
  EXPECT_GT(e.similarity.minCoeff(), 1.0 - 2e-4);
}

TEST(LinkDataset, OptionsALinkDoesNotHaveAreRefused) {
  const LinkRecord& h = *find_link("hopf");
  ExploreOptions o = link_options(2, 160);
  o.adaptive = true;
  fixtures::expect_input_error([&] { explore_link(h, o); }, "adaptive sampling");
  o = link_options(2, 160);
  o.relax.method = RelaxMethod::Multilevel;
  fixtures::expect_input_error([&] { explore_link(h, o); }, "direct method");
  o = link_options(2, 160);
  o.stiffness = true;
  fixtures::expect_input_error([&] { explore_link(h, o); }, "stiffness");
}

TEST(LinkDataset, CommandLineExploreClusterExportQuery) {
  const std::string dir = temp_dir("link_ds_cli");
  const std::string file = dir + "/links.h5";
  for (const char* name : {"borromean", "hopf"}) {
    const auto r = run(std::string("explore ") + name + " --samples 3 -n 180 --quiet -o " + file + " --json");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.json()["runs"], 3);
  }
  // links after the knots, in link-table order
  EXPECT_EQ(DatasetReader(file).knot_names(), (std::vector<std::string>{"hopf", "borromean"}));
  const auto c = run("cluster " + file + " borromean --cut 0.002 --json");
  ASSERT_EQ(c.status, 0) << c.err;
  const auto x = run("export " + file + " borromean 0 -o " + dir + "/b0.obj");
  ASSERT_EQ(x.status, 0) << x.err;
  const auto inv = run("invariants " + dir + "/b0.obj --json");
  ASSERT_EQ(inv.status, 0) << inv.err;
  EXPECT_EQ(inv.json()["components"], 3);
  EXPECT_EQ(inv.json()["milnor_triple"], 1);
  const auto q = run("query " + file + " --sort min_distance --json");
  ASSERT_EQ(q.status, 0) << q.err;
  EXPECT_EQ(q.json()["rows"].size(), 6u);
  // the search aligns one polygon: links are not searched, and naming one is refused
  ASSERT_EQ(run("embed 3_1 -n 120 -o " + dir + "/q.obj").status, 0);
  const auto none = run("search " + file + " " + dir + "/q.obj --json");
  ASSERT_EQ(none.status, 0) << none.err;
  EXPECT_EQ(none.json()["hits"].size(), 0u);
  const auto named = run("search " + file + " " + dir + "/q.obj --knot hopf");
  EXPECT_EQ(named.status, 2);
  EXPECT_NE(named.err.find("hopf is a link"), std::string::npos) << named.err;
  // a knot data set at the default (multilevel) parameters is not extended with a link
  ASSERT_EQ(run("explore 3_1 --samples 2 -n 100 --no-stiffness --quiet -o " + dir + "/k.h5").status, 0);
  const auto bad = run("explore hopf --samples 2 -n 100 --quiet -o " + dir + "/k.h5");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("relax_method"), std::string::npos) << bad.err;
  fs::remove_all(dir);
}
