#pragma once
/// \file
/// 128-bit integers (a GCC/Clang extension) for exact arithmetic.
namespace ek {
__extension__ typedef __int128 int128;            ///< Signed 128-bit integer.
__extension__ typedef unsigned __int128 uint128;  ///< Unsigned 128-bit integer.
}  // namespace ek
