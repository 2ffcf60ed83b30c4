// OBJ curve files: "v x y z" and "l i j ..." lines (curve_io.hpp).
#include "fuzz_curve.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ek::fuzz::fuzz_curve(data, size, "obj");
  return 0;
}
