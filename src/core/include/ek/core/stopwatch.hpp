#pragma once
/// \file
/// Wall time of a computation (the `seconds` fields of reports and results).
#include <chrono>

namespace ek {

/// Seconds of wall time (the steady clock) since construction or the last restart().
class Stopwatch {
 public:
  Stopwatch() : start_(std::chrono::steady_clock::now()) {}  ///< Starts now.
  void restart() { start_ = std::chrono::steady_clock::now(); }  ///< Starts again now.
  /// [s] since the start.
  double seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }

 private:
  std::chrono::steady_clock::time_point start_;
};

}  // namespace ek
