#pragma once
/// \file
/// Many knot types into one data-set file: resumable, shardable, with
/// progress reports (`knots explore` and `knots dataset`).
///
/// Crash safety. Work goes to the folder "<output>.work/": each finished run
/// is appended to "<knot>.journal" (fsync per record, CRC-checked, a torn last
/// record is ignored); a finished knot is written to "<knot>.h5" by
/// write-then-rename and its journal removed; at the end the output file is
/// assembled from the knots it already had and the finished parts, written to
/// a temporary name and renamed over the output, and the work folder removed.
/// Killing the process at any moment (SIGINT, SIGKILL) therefore loses at most
/// the runs in progress, never a completed equilibrium, and never leaves the
/// output unreadable; running the same command again resumes.
#include <functional>
#include <string>
#include <vector>

#include "ek/dataset/pipeline.hpp"

namespace ek {

/// What run_dataset() computes and where: the options of each entry, the
/// knots and links, the output file and the shard.
struct DatasetRunOptions {
  ExploreOptions explore;                ///< the options of every entry (explore_knot(), explore_link())
  std::vector<const KnotRecord*> knots;  ///< knot types in table order
  std::vector<const LinkRecord*> links;  ///< links (explore_link), after the knots in link-table order
  std::string output;                    ///< data-set file
  int shard_index = 0;                   ///< this shard, 0-based (--shard I/N uses I = 1..N)
  int shard_count = 1;                   ///< number of shards: entry k (knots, then links) belongs to shard k mod N
  bool progress = true;                  ///< progress on stderr (a bar on a terminal, lines otherwise)
};

/// What one run_dataset() call did.
struct DatasetRunSummary {
  int knots = 0;          ///< knots of this shard
  int knots_skipped = 0;  ///< already in the output
  int knots_resumed = 0;  ///< finished parts found in the work folder
  int runs = 0;           ///< relaxations performed by this invocation
  int equilibria = 0;     ///< stable equilibria found by this invocation
  double seconds = 0.0;   ///< [s] wall time
};

/// Runs (or resumes) the data set. Throws InputError for an unwritable
/// output, an existing output with different parameters, or bad options;
/// nothing the user had is overwritten in that case.
DatasetRunSummary run_dataset(const DatasetRunOptions& options);

/// Merges data sets (for example shards) into `output`: parameters must
/// agree, a knot may appear in one input only; knots are written in table
/// order. Throws InputError otherwise (the output is not touched), also for
/// an input that does not exist, is given twice, or is unfinished (its
/// "<input>.work/" folder exists: its `knots dataset` run is still running or
/// was interrupted).
void merge_datasets(const std::vector<std::string>& inputs, const std::string& output);

/// Parses "I/N" (1 <= I <= N) into a 0-based index and a count.
std::pair<int, int> parse_shard(const std::string& text);

}  // namespace ek
