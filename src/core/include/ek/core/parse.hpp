#pragma once
/// \file
/// Strict parsing of one number from user text (command-line values, query
/// conditions): the whole text must be the number (an optional leading '+',
/// no spaces, nothing after it), else InputError with one line that names
/// where the text came from.
#include <string>

namespace ek {

/// A finite double: InputError("<what>: '<text>' is not a number") or
/// "... is not a finite number" (inf, nan).
double parse_number(const std::string& text, const std::string& what);

/// An integer: InputError("<what>: '<text>' is not an integer").
long long parse_integer(const std::string& text, const std::string& what);

}  // namespace ek
