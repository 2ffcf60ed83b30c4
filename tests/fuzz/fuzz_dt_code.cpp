// DT codes (KnotInfo's "DT Notation" column): parse_dt.
#include <cstdlib>
#include <vector>

#include "ek/knots/codes.hpp"
#include "fuzz_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = ek::fuzz::text(data, size);
  ek::fuzz::expect_result_or_input_error([&] {
    const ek::DTCode code = ek::parse_dt(text);
    // the absolute values are exactly 2, 4, ..., 2c; the code prints back to itself
    const int c = code.crossings();
    std::vector<char> seen(static_cast<size_t>(2 * c + 1), 0);
    for (int label : code.labels) {
      const int a = std::abs(label);
      EK_FUZZ_CHECK(a % 2 == 0 && a >= 2 && a <= 2 * c && !seen[static_cast<size_t>(a)]);
      seen[static_cast<size_t>(a)] = 1;
    }
    EK_FUZZ_CHECK(ek::parse_dt(ek::to_string(code)).labels == code.labels);
  });
  return 0;
}
