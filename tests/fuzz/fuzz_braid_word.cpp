// Braid words and lists (KnotInfo's "Braid Notation" column): parse_braid,
// parse_braid_list, and the Alexander polynomial of an accepted word, which
// the Burau representation and the closure's diagram must agree on.
#include "ek/knots/alexander.hpp"
#include "ek/knots/codes.hpp"
#include "fuzz_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = ek::fuzz::text(data, size);
  ek::fuzz::expect_result_or_input_error([&] {
    const std::vector<ek::BraidWord> words = ek::parse_braid_list(text);
    EK_FUZZ_CHECK(!words.empty());
    for (const auto& w : words) {
      EK_FUZZ_CHECK(w.length() > 0 && ek::closure_components(w) == 1);
      for (int letter : w.letters) EK_FUZZ_CHECK(letter != 0 && std::abs(letter) < w.strands);
      const ek::BraidWord again = ek::parse_braid(ek::to_string(w), w.strands);
      EK_FUZZ_CHECK(again.letters == w.letters && again.strands == w.strands);
      if (w.length() <= 24 && w.strands <= 8) {
        const auto burau = ek::alexander(w);
        const auto diagram = ek::alexander(ek::diagram_from_braid(w));
        EK_FUZZ_CHECK(burau.coefficients == diagram.coefficients);
      }
    }
  });
  return 0;
}
