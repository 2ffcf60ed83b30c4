#include "ek/core/commit.hpp"

namespace ek {
namespace detail {
extern const char* const kSourceCommit;  // generated/commit.cpp (cmake/ek_commit.cmake)
}

std::string source_commit() { return detail::kSourceCommit; }

}  // namespace ek
