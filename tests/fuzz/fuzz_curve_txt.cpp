// TXT curve files: one "x y z" vertex per line (curve_io.hpp).
#include "fuzz_curve.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ek::fuzz::fuzz_curve(data, size, "txt");
  return 0;
}
