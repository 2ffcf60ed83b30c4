// The journal of finished runs (src/dataset journal): parse_journal. Every
// accepted prefix must read the same again on its own (what resuming does
// after truncating the file to the intact prefix).
#include "fuzz_common.hpp"
#include "fuzz_seeds.hpp"
#include "journal.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes = ek::fuzz::text(data, size);
  const std::string head = ek::journal_head(ek::fuzz::kJournalOptions);
  ek::fuzz::expect_result_or_input_error([&] {
    const ek::JournalContents c = ek::parse_journal(bytes, head, "fuzz.journal");
    EK_FUZZ_CHECK(c.good <= bytes.size());
    EK_FUZZ_CHECK(c.good == 0 || c.good >= head.size());
    for (const auto& [sample, run] : c.runs) EK_FUZZ_CHECK(run.record.sample == sample && run.positions.rows() >= 0);
    const ek::JournalContents again = ek::parse_journal(bytes.substr(0, c.good), head, "fuzz.journal");
    EK_FUZZ_CHECK(again.good == c.good && again.runs.size() == c.runs.size());
  });
  return 0;
}
