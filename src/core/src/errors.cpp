#include "ek/core/errors.hpp"

namespace ek {

void require(bool condition, const std::string& message) {
  if (!condition) throw std::invalid_argument(message);
}

void require_input(bool condition, const std::string& message) {
  if (!condition) throw InputError(message);
}

}  // namespace ek
