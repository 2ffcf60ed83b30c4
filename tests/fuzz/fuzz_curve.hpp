#pragma once
// Curve files (OBJ and TXT, src/geometry curve_io): parse_curve in one
// format, then what `knots invariants` computes from an accepted curve; the
// same text as a link (parse_link): every component a usable polygon, and a
// link of one component the curve parse_curve reads.
#include <cstdio>

#include "ek/geometry/curve_io.hpp"
#include "ek/geometry/link.hpp"
#include "ek/knots/alexander.hpp"
#include "fuzz_common.hpp"

namespace ek::fuzz {

inline void fuzz_curve(const std::uint8_t* data, std::size_t size, const std::string& format) {
  const std::string text = ek::fuzz::text(data, size);
  expect_result_or_input_error([&] {
    const Points P = parse_curve(text, format, "fuzz." + format);
    EK_FUZZ_CHECK(P.rows() >= 4 && P.allFinite());
    // written with 17 significant digits (as write_curve does), read back exactly
    std::string txt;
    char line[128];
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
      std::snprintf(line, sizeof line, "%.17g %.17g %.17g\n", P(i, 0), P(i, 1), P(i, 2));
      txt += line;
    }
    EK_FUZZ_CHECK(parse_curve(txt, "txt", "again.txt") == P);
    if (P.rows() <= 64) alexander(P);  // projection and invariant (InputError if the curve meets itself)
  });
  expect_result_or_input_error([&] {
    const Link link = parse_link(text, format, "fuzz." + format);
    EK_FUZZ_CHECK(!link.empty());
    for (const Points& P : link) EK_FUZZ_CHECK(P.rows() >= 4 && P.allFinite());
    if (link.size() == 1) EK_FUZZ_CHECK(parse_curve(text, format, "fuzz." + format) == link[0]);
  });
}

}  // namespace ek::fuzz
