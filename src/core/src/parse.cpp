#include "ek/core/parse.hpp"

#include <charconv>
#include <cmath>

#include "ek/core/errors.hpp"

namespace ek {
namespace {

/// The text without one leading '+' (from_chars does not take it).
const char* skip_plus(const std::string& text) {
  const char* b = text.c_str();
  return (!text.empty() && *b == '+') ? b + 1 : b;
}

}  // namespace

double parse_number(const std::string& text, const std::string& what) {
  double v = 0.0;
  const char* e = text.c_str() + text.size();
  auto [p, ec] = std::from_chars(skip_plus(text), e, v);
  if (text.empty() || ec != std::errc() || p != e) throw InputError(what + ": '" + text + "' is not a number");
  if (!std::isfinite(v)) throw InputError(what + ": '" + text + "' is not a finite number");
  return v;
}

long long parse_integer(const std::string& text, const std::string& what) {
  long long v = 0;
  const char* e = text.c_str() + text.size();
  auto [p, ec] = std::from_chars(skip_plus(text), e, v);
  if (text.empty() || ec != std::errc() || p != e) throw InputError(what + ": '" + text + "' is not an integer");
  return v;
}

}  // namespace ek
