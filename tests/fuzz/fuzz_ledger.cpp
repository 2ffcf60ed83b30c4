// The ledger reader's checks (ledger.cpp), structure-aware: the input builds
// a small valid ledger (knots, equilibria, states, runs), writes it with
// write_ledger, then replaces some of its integer tables, row attributes,
// real values and the cut with values and lengths of its choosing, through
// the HDF5 library (so the library only ever reads a file it wrote itself),
// and seals the file again. read_ledger must return a ledger whose indices
// all hold, or refuse the file with an InputError.
#include <fuzzer/FuzzedDataProvider.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "ek/dataset/h5.hpp"
#include "ek/dataset/ledger.hpp"
#include "fuzz_common.hpp"
#include "metadata_testing.hpp"

namespace {

std::string scratch_path() {
  const char* dir = std::getenv("TMPDIR");
  return std::string(dir && *dir ? dir : "/tmp") + "/ek-fuzz-ledger-" + std::to_string(::getpid()) + ".ledger.h5";
}

const std::string& path() {
  static const std::string p = scratch_path();
  return p;
}

/// A valid ledger of up to 3 knots of up to 4 equilibria each.
ek::Ledger valid_ledger(FuzzedDataProvider& in) {
  ek::Ledger l;
  l.parameters = ek::testing_metadata::complete_metadata();
  l.provenance.source = "fuzz";
  const int knots = in.ConsumeIntegralInRange<int>(0, 3);
  for (int k = 0; k < knots; ++k) {
    ek::LedgerEntry e;
    e.name = "k" + std::to_string(k);
    e.alexander = {1, -1, 1};
    e.attribute_names = {"energy", "threedim"};
    const int m = in.ConsumeIntegralInRange<int>(0, 4), states = m == 0 ? 0 : in.ConsumeIntegralInRange<int>(1, m);
    e.attributes = Eigen::MatrixXd::Constant(m, 2, 1.0);
    e.linkage = Eigen::MatrixXd::Zero(std::max(m - 1, 0), 4);
    for (int i = 0; i < m; ++i) e.state.push_back(i < states ? i : in.ConsumeIntegralInRange<int>(0, states - 1));
    for (int s = 0; s < states; ++s) e.states.push_back({s, static_cast<int>(e.members(s).size()), ek::Points::Ones(6, 3)});
    for (int r = 0; r <= m; ++r)
      e.runs.push_back({r, r < m ? ek::RunStatus::ConvergedStable : ek::RunStatus::Stalled, r < m ? r : -1, 3, 0.1, true});
    l.entries.push_back(e);
  }
  return l;
}

/// Replaces the int64 dataset `name` of `group` with values and a length of the input's choosing.
void replace_ints(FuzzedDataProvider& in, hid_t file, const char* group, const char* name) {
  ek::h5::Handle g = ek::h5::open_group(file, group);
  H5Ldelete(g.id(), name, H5P_DEFAULT);
  std::vector<std::int64_t> v(in.ConsumeIntegralInRange<size_t>(0, 8));
  for (auto& x : v) x = in.ConsumeIntegralInRange<std::int64_t>(-2, 6);
  ek::h5::write_int64(g.id(), name, {v.size()}, v.data());
}

void mutate(FuzzedDataProvider& in, hid_t f, const ek::Ledger& l) {
  static const char* const tables[][2] = {{"runs", "status"},        {"runs", "equilibrium"},
                                          {"runs", "sample"},        {"equilibria", "state"},
                                          {"states", "representative"}, {"states", "members"}};
  const int count = in.ConsumeIntegralInRange<int>(0, 3);
  for (int c = 0; c < count; ++c) {
    switch (in.ConsumeIntegralInRange<int>(0, 4)) {
      case 0: {
        const auto* t = tables[in.ConsumeIntegralInRange<size_t>(0, 5)];
        replace_ints(in, f, t[0], t[1]);
        break;
      }
      case 1:
      case 2: {  // a knot's rows or attribute columns
        if (l.entries.empty()) break;
        ek::h5::Handle knots = ek::h5::open_group(f, "knots");
        ek::h5::Handle g = ek::h5::open_group(knots.id(), l.entries[in.ConsumeIntegralInRange<size_t>(0, l.entries.size() - 1)].name);
        std::vector<std::int64_t> v(in.ConsumeIntegralInRange<size_t>(0, 8));
        for (auto& x : v) x = in.ConsumeIntegralInRange<std::int64_t>(-1, 8);
        ek::h5::set_attr(g.id(), in.ConsumeBool() ? "rows" : "attribute_columns", v);
        break;
      }
      case 3: ek::h5::set_attr(f, "cut", in.ConsumeFloatingPoint<double>()); break;
      case 4: ek::h5::set_attr(f, "format_version", in.ConsumeIntegralInRange<std::int64_t>(0, 2)); break;
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  std::atexit([] { std::remove(path().c_str()); });
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  const ek::Ledger l = valid_ledger(in);
  ek::write_ledger(path(), l);
  {
    ek::h5::Handle f = ek::h5::open_file(path(), true);
    mutate(in, f.id(), l);
  }
  ek::h5::seal(path());
  ek::fuzz::expect_result_or_input_error([&] {
    const ek::Ledger r = ek::read_ledger(path());
    EK_FUZZ_CHECK(r.provenance.cut > 0.0 && r.provenance.cut < 1.0);
    for (const ek::LedgerEntry& e : r.entries) {
      EK_FUZZ_CHECK(static_cast<Eigen::Index>(e.state.size()) == e.attributes.rows());
      EK_FUZZ_CHECK(e.attributes.cols() == static_cast<Eigen::Index>(e.attribute_names.size()));
      for (int s : e.state) EK_FUZZ_CHECK(s >= 0 && s < static_cast<int>(e.states.size()));
      for (const auto& s : e.states) EK_FUZZ_CHECK(s.representative >= 0 && s.representative < e.attributes.rows());
      for (const auto& run : e.runs) EK_FUZZ_CHECK(run.equilibrium >= -1 && run.equilibrium < e.attributes.rows());
      for (size_t s = 0; s < e.states.size(); ++s)
        EK_FUZZ_CHECK(static_cast<int>(e.members(static_cast<int>(s)).size()) == e.states[s].members);
    }
  });
  return 0;
}
