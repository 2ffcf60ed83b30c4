#pragma once
// Shared by the journal fuzz target and the seed generator (fuzz_make_seeds).
namespace ek::fuzz {

/// The options text of the journals in the seed corpus (any fixed text).
inline constexpr const char* kJournalOptions = "knot=3_1 n=8 fuzz seed corpus";

}  // namespace ek::fuzz
