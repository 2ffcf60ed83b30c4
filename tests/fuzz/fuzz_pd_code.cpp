// PD codes (KnotInfo's "PD Notation" column): parse_pd, and what is computed
// from an accepted code (its Gauss diagram and Alexander polynomial).
#include "ek/knots/alexander.hpp"
#include "ek/knots/codes.hpp"
#include "fuzz_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = ek::fuzz::text(data, size);
  ek::fuzz::expect_result_or_input_error([&] {
    const ek::PDCode code = ek::parse_pd(text);
    const ek::PDCode again = ek::parse_pd(ek::to_string(code));
    EK_FUZZ_CHECK(again.size() == code.size());
    for (int i = 0; i < code.size(); ++i)
      EK_FUZZ_CHECK(again.crossings[static_cast<size_t>(i)].e == code.crossings[static_cast<size_t>(i)].e);
    const ek::GaussDiagram g = ek::diagram_from_pd(code);
    EK_FUZZ_CHECK(g.crossings() == code.size() && static_cast<int>(g.visits.size()) == 2 * code.size());
    if (code.size() <= 24) ek::alexander(code);  // the table's codes have at most 12 crossings
  });
  return 0;
}
