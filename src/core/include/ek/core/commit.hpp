#pragma once
/// \file
/// The commit a program was built from (library ek_commit: only what reports
/// it links it, so that a new commit relinks those alone).
#include <string>

namespace ek {

/// `git describe --always --dirty --abbrev=12` of the source tree at build
/// time ("…-dirty" when the tree had uncommitted changes), "unknown" when it
/// was built outside a git checkout. Stamped at every build
/// (cmake/ek_commit.cmake).
std::string source_commit();

}  // namespace ek
