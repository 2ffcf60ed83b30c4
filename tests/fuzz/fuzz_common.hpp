#pragma once
// Shared by the fuzz targets. A reader given any bytes either returns a
// result or throws ek::InputError (bad input: one clear message line). Any
// other exception escapes LLVMFuzzerTestOneInput and libFuzzer reports it as a
// crash, as it does the sanitizers' findings and failed EK_FUZZ_CHECKs (a
// property every accepted input must have, e.g. that it prints back to itself).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "ek/core/errors.hpp"

#define EK_FUZZ_CHECK(condition) \
  ((condition) ? static_cast<void>(0) : ::ek::fuzz::check_failed(#condition, __FILE__, __LINE__))

namespace ek::fuzz {

[[noreturn]] inline void check_failed(const char* what, const char* file, int line) {
  std::fprintf(stderr, "fuzz check failed: %s (%s:%d)\n", what, file, line);
  std::abort();
}

inline std::string text(const std::uint8_t* data, std::size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

/// Runs `read`; an InputError must carry a one-line, non-empty message.
template <class F>
void expect_result_or_input_error(F&& read) {
  try {
    read();
  } catch (const InputError& e) {
    const std::string message = e.what();
    EK_FUZZ_CHECK(!message.empty());
    EK_FUZZ_CHECK(message.find('\n') == std::string::npos);
  }
}

}  // namespace ek::fuzz
