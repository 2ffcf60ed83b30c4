#pragma once
/// \file
/// Error types shared by all modules.
///
/// Conventions (docs/cli.md, "Common behaviour"):
///  - InputError: bad user input (malformed code, unreadable or degenerate
///    file, unknown knot, impossible parameter, unwritable output). The command
///    line prints its message on one line and exits with status 2.
///  - std::invalid_argument / std::logic_error: misuse of the library API by a
///    programmer (wrong array shape, ...). Also exit status 2 from the CLI, but
///    these indicate a bug in the caller.
///  - Numerical outcomes (non-convergence, ...) are never exceptions: they are
///    status enums in reports.
///  - TopologyError: a computed curve changed knot type. Always an error.
#include <stdexcept>
#include <string>

/// Everything of the library: the modules (core, geometry, knots, embedding,
/// lattice, rod, contact, solver, analysis, mechanics, dataset, site,
/// transitions) share this one namespace; their headers are `ek/<module>/`.
namespace ek {

/// `text` on one line: control characters (a newline in a quoted input, ...)
/// are written as escapes: a newline as the two characters `\n`, a tab as
/// `\t`, a carriage return as `\r`, other control bytes as `\xNN`.
std::string one_line(const std::string& text);

/// Bad input from a user or a file. `what()` is one line, suitable for stderr
/// (the message is passed through one_line(): it may quote the input).
class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(one_line(message)) {}  ///< `message` made one line by one_line().
};

/// A result whose knot type differs from its input (Alexander polynomial mismatch).
class TopologyError : public std::runtime_error {
 public:
  explicit TopologyError(const std::string& message) : std::runtime_error(message) {}  ///< `message` as given.
};

/// Throws std::invalid_argument(message) unless `condition` holds.
/// Used for parameter validation that must survive Release builds.
void require(bool condition, const std::string& message);

/// Throws InputError(message) unless `condition` holds.
void require_input(bool condition, const std::string& message);

}  // namespace ek
