// The journal of finished runs (src/dataset/src/journal.cpp): what a resumed
// run reads back from a journal that is intact, torn or damaged.
#include <gtest/gtest.h>
#include <zlib.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "ek/core/errors.hpp"
#include "first_layout.hpp"
#include "journal.hpp"
#include "testing.hpp"

using namespace ek;

namespace {

const std::string kOptions = "knot=3_1 n=4 test";

JournalRun journal_run(int sample, bool stable) {
  JournalRun r;
  r.record.sample = sample;
  r.record.status = stable ? RunStatus::ConvergedStable : RunStatus::Stalled;
  if (stable) r.positions = fixtures::circle(4, 1.0);
  r.energy.total = 2.5 + sample;
  return r;
}

/// A journal with three runs (samples 0, 1, 2; sample 1 without a curve).
std::string three_runs() {
  const std::string path = ::testing::TempDir() + "three.journal";
  std::filesystem::remove(path);
  {
    Journal j(path, kOptions);
    j.append(journal_run(0, true));
    j.append(journal_run(1, false));
    j.append(journal_run(2, true));
  }
  std::string bytes = fixtures::read_bytes(path);
  std::filesystem::remove(path);
  return bytes;
}

/// Offsets where the records start (after the header), and the end.
std::vector<size_t> record_starts(const std::string& bytes) {
  std::vector<size_t> starts;
  for (size_t pos = journal_head(kOptions).size(); pos + 8 <= bytes.size();) {
    starts.push_back(pos);
    std::uint32_t len;
    std::memcpy(&len, bytes.data() + pos + 4, 4);
    pos += 12 + len;
  }
  starts.push_back(bytes.size());
  return starts;
}

}  // namespace

// Cut anywhere, a journal gives back exactly the records that are complete
// before the cut, and the length to truncate to before appending.
TEST(Journal, EveryCutKeepsTheCompleteRecords) {
  const std::string bytes = three_runs();
  const std::string head = journal_head(kOptions);
  const auto starts = record_starts(bytes);
  ASSERT_EQ(starts.size(), 4u);
  for (size_t cut = 0; cut <= bytes.size(); ++cut) {
    const JournalContents c = parse_journal(bytes.substr(0, cut), head, "j");
    size_t complete = 0;
    while (complete < 3 && starts[complete + 1] <= cut) ++complete;
    ASSERT_EQ(c.runs.size(), cut < head.size() ? 0u : complete) << "cut at " << cut;
    EXPECT_EQ(c.good, cut < head.size() ? 0u : starts[complete]) << "cut at " << cut;
  }
  const JournalContents all = parse_journal(bytes, head, "j");
  EXPECT_EQ(all.runs.at(2).positions, fixtures::circle(4, 1.0));
  EXPECT_EQ(all.runs.at(1).positions.rows(), 0);
  EXPECT_EQ(all.runs.at(1).record.status, RunStatus::Stalled);
}

// A flipped byte in a record ends the journal there (CRC); a record whose
// CRC matches but whose curve length exceeds its bytes is refused without
// allocating for it (it used to reserve up to 240 MB first).
TEST(Journal, DamagedRecordsEndTheJournal) {
  const std::string bytes = three_runs();
  const std::string head = journal_head(kOptions);
  const auto starts = record_starts(bytes);
  std::string flipped = bytes;
  flipped[starts[1] + 20] ^= 0x04;
  EXPECT_EQ(parse_journal(flipped, head, "j").runs.size(), 1u);
  // sample 2's record: payload ends with int32 rows and rows * 3 doubles
  std::string forged = bytes;
  std::uint32_t len;
  std::memcpy(&len, forged.data() + starts[2] + 4, 4);
  const size_t payload = starts[2] + 8, rows_at = payload + len - 4 * 3 * sizeof(double) - 4;
  const std::int32_t huge = 10000000;
  std::memcpy(&forged[rows_at], &huge, 4);
  const auto crc = static_cast<std::uint32_t>(::crc32(0L, reinterpret_cast<const Bytef*>(&forged[payload]), len));
  std::memcpy(&forged[payload + len], &crc, 4);
  const JournalContents c = parse_journal(forged, head, "j");
  EXPECT_EQ(c.runs.size(), 2u);
  EXPECT_EQ(c.good, starts[2]);
}

// A run keeps its link and min_distance through the journal; a record of
// the first layout (magic "RUN1", without min_distance) is read with its
// slot as `link`, min_distance NaN and first_layout set, the rest the same.
TEST(Journal, RecordsOfTheFirstLayoutAreRead) {
  const std::string path = ::testing::TempDir() + "layouts.journal";
  std::filesystem::remove(path);
  JournalRun a = journal_run(0, true);
  a.link = 1.5;
  a.min_distance = 0.25;
  a.energy.contact = 0.125;
  {
    Journal j(path, kOptions);
    j.append(a);
  }
  const std::string bytes = fixtures::read_bytes(path);
  std::filesystem::remove(path);
  const std::string head = journal_head(kOptions);
  const JournalRun now = parse_journal(bytes, head, path).runs.at(0);
  EXPECT_EQ(now.link, 1.5);
  EXPECT_EQ(now.min_distance, 0.25);
  EXPECT_FALSE(now.first_layout);
  const std::string old = testing_journal::to_first_layout(bytes, head.size(), false);
  const JournalRun first = parse_journal(old, head, path).runs.at(0);
  EXPECT_TRUE(first.first_layout);
  EXPECT_EQ(first.link, 1.5);
  EXPECT_TRUE(std::isnan(first.min_distance));
  EXPECT_EQ(first.energy.total, a.energy.total);
  EXPECT_EQ(first.energy.contact, a.energy.contact);
  EXPECT_TRUE(first.positions == a.positions);
  EXPECT_EQ(first.record.status, a.record.status);
}

// A header cut short (killed while creating the journal) is an empty journal;
// another run's journal, or another file, is refused with one line.
TEST(Journal, HeaderChecks) {
  const std::string head = journal_head(kOptions);
  EXPECT_EQ(parse_journal(head.substr(0, 10), head, "j").good, 0u);
  fixtures::expect_input_error([&] { parse_journal(journal_head("knot=4_1") + "xx", head, "j.journal"); },
                               "journal 'j.journal' belongs to a run with different options");
  fixtures::expect_input_error([&] { parse_journal("PK\x03\x04", head, "j.journal"); },
                               "'j.journal' is not a journal of this program");
}
