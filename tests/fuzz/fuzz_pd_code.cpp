// PD codes (KnotInfo's "PD Notation" column, LinkInfo's for links):
// parse_pd and parse_pd_link, and what is computed from an accepted code
// (its Gauss diagram, its link diagram, the Alexander polynomials).
// A knot's code that parse_pd accepts reads as one component with the same
// crossing signs.
#include "ek/knots/alexander.hpp"
#include "ek/knots/codes.hpp"
#include "ek/knots/conway.hpp"
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
    const ek::PDLinkCode link = ek::parse_pd_link(text);
    EK_FUZZ_CHECK(link.components.size() == 1);
    for (int i = 0; i < code.size(); ++i)
      EK_FUZZ_CHECK(code.size() == 1 || link.sign(i) == code.crossings[static_cast<size_t>(i)].sign(2 * code.size()));
  });
  ek::fuzz::expect_result_or_input_error([&] {
    const ek::PDLinkCode code = ek::parse_pd_link(text);
    const ek::PDLinkCode again = ek::parse_pd_link(ek::to_string(code.code));
    EK_FUZZ_CHECK(again.components == code.components && again.over_in == code.over_in);
    const ek::LinkDiagram d = ek::link_diagram_from_pd(code);
    size_t visits = 0;
    for (const auto& c : d.components) visits += c.size();
    EK_FUZZ_CHECK(d.components.size() == code.components.size() && visits == 2 * code.over_in.size());
    if (code.code.size() <= 16) ek::alexander_coefficients(d);  // ∇ needs a planar code; the Fox minor does not
  });
  return 0;
}
