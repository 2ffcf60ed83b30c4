// The knot-table CSV reader (KnotInfo exports): KnotTable::parse, which also
// parses every row's DT, PD and braid codes.
#include "ek/knots/table.hpp"
#include "fuzz_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = ek::fuzz::text(data, size);
  ek::fuzz::expect_result_or_input_error([&] {
    const ek::KnotTable table = ek::KnotTable::parse(text, "fuzz.csv");
    EK_FUZZ_CHECK(table.size() > 0);
    for (const auto& r : table.records()) {
      EK_FUZZ_CHECK(table.find(r.name) == &r);
      EK_FUZZ_CHECK(r.crossing_number >= 0);
      if (r.crossing_number > 0) EK_FUZZ_CHECK(r.pd && r.pd->size() == r.crossing_number);
      if (r.braid) EK_FUZZ_CHECK(!r.braids.empty());
    }
  });
  return 0;
}
