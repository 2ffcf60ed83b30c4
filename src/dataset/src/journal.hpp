#pragma once
// Private: the append-only journal of finished runs of one knot, so that an
// interrupted run loses no completed equilibrium (crash safety).
//
// File: the header line "elastic-knots-journal 1\n", the options text and
// '\n', then records: u32 magic 0x324E5552 ("RUN2"), u32 payload length,
// payload, u32 CRC-32 (zlib) of the payload. Records of the first layout
// (magic "RUN1", without min_distance) are read too, so that a journal
// begun before is resumed (JournalRun::first_layout). Each record is written with one
// write(2) and fsync(2). A torn record at the end (killed mid-write) fails its
// length or CRC check and is ignored, and the file is truncated to the last
// good record before appending.
#include <map>
#include <mutex>
#include <string>

#include "ek/dataset/dataset_file.hpp"
#include "ek/solver/relax.hpp"

namespace ek {

struct JournalRun {
  RunRecord record;
  Points positions;            // empty when no equilibrium is stored
  EnergyParts energy;          // [energy] total = stretch + bend + twist + contact + slab
  double stiffness = 0.0;      // NaN when not computed
  double link = 0.0;           // [1] Lk of a knot's result; NaN for a link
  double min_distance = 0.0;   // [length] closest approach of two edges sharing no vertex
  /// Decoded from a record of the first layout (magic "RUN1"), which had one
  /// slot for `link` and min_distance: a knot's Lk or a link's closest
  /// approach, and a link's energy.total without the contact part.
  bool first_layout = false;
};

/// What a journal file holds: the runs of its intact records, by sample, and
/// the length of the intact prefix (header and records; 0 when the file is
/// empty or its header torn).
struct JournalContents {
  std::map<int, JournalRun> runs;
  size_t good = 0;
};

/// The header line and the options text: the first bytes of a journal.
std::string journal_head(const std::string& options_text);

/// Reads a journal's bytes `data` for the header `head` (journal_head()).
/// Records are read up to the first torn or damaged one (bad magic, length
/// past the end, CRC mismatch, malformed payload). A journal of a run with
/// other options, or a file that is not a journal, is an InputError naming
/// `path`.
JournalContents parse_journal(const std::string& data, const std::string& head, const std::string& path);

class Journal {
 public:
  /// Opens or creates the journal. `options_text` identifies the run's
  /// options; an existing journal with other options is an InputError.
  Journal(std::string path, const std::string& options_text);
  ~Journal();
  Journal(const Journal&) = delete;
  Journal& operator=(const Journal&) = delete;

  const std::map<int, JournalRun>& runs() const { return runs_; }
  /// Appends durably (thread-safe).
  void append(const JournalRun& run);
  /// Deletes the journal file (after its knot was committed elsewhere).
  void remove();

 private:
  std::string path_;
  int fd_ = -1;
  std::map<int, JournalRun> runs_;
  std::mutex mutex_;
};

}  // namespace ek
