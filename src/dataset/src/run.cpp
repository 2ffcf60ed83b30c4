#include "ek/dataset/run.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <map>

#include "ek/core/atomic_file.hpp"
#include "ek/core/errors.hpp"
#include "ek/core/paths.hpp"
#include "ek/core/stopwatch.hpp"
#include "ek/knots/table.hpp"

namespace ek {
namespace {

namespace fs = std::filesystem;

std::string hms(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return "--:--:--";
  const long s = static_cast<long>(seconds + 0.5);
  char buf[32];
  std::snprintf(buf, sizeof buf, "%02ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
  return buf;
}

/// Progress on stderr: a bar redrawn in place on a terminal, otherwise one
/// plain line at most every 30 seconds.
class Progress {
 public:
  Progress(bool enabled, int knots) : enabled_(enabled), tty_(::isatty(2) != 0), knots_(knots) {}
  void knot_started(const std::string& name) { current_ = name; }
  void run_finished(bool stable) {
    ++runs_;
    if (stable) ++equilibria_;
    show(false);
  }
  void knot_finished() {
    ++knots_done_;
    show(true);
  }
  void finish() {
    if (enabled_ && tty_) std::fprintf(stderr, "\n");
  }

 private:
  void show(bool knot_event) {
    if (!enabled_) return;
    const double elapsed = t0_.seconds();
    const double rate = elapsed > 0 ? runs_ / elapsed : 0.0;
    const double eta = knots_done_ > 0 ? elapsed / knots_done_ * (knots_ - knots_done_) : NAN;
    if (tty_) {
      const int width = 30;
      const int filled = knots_ > 0 ? width * knots_done_ / knots_ : width;
      std::string bar(static_cast<size_t>(filled), '=');
      bar.resize(static_cast<size_t>(width), ' ');
      std::fprintf(stderr, "\r[%s] %d/%d knots  %s  %d runs  %d equilibria  %.2f runs/s  ETA %s   ", bar.c_str(),
                   knots_done_, knots_, current_.c_str(), runs_, equilibria_, rate, hms(eta).c_str());
      std::fflush(stderr);
    } else if (knot_event || elapsed - last_line_ >= 30.0) {
      last_line_ = elapsed;
      std::fprintf(stderr, "progress: %d/%d knots, %d runs, %d equilibria, %.2f runs/s, elapsed %s, ETA %s (%s)\n",
                   knots_done_, knots_, runs_, equilibria_, rate, hms(elapsed).c_str(), hms(eta).c_str(),
                   current_.c_str());
    }
  }
  bool enabled_, tty_;
  int knots_, knots_done_ = 0, runs_ = 0, equilibria_ = 0;
  std::string current_;
  Stopwatch t0_;
  double last_line_ = -1e9;
};

/// The order of a data set's entries: knots in table order, then links in
/// link-table order.
int table_index(const std::string& name) {
  if (const KnotRecord* r = KnotTable::global().find(name)) return r->row;
  const auto& links = link_table();
  for (size_t k = 0; k < links.size(); ++k)
    if (links[k].name == name) return (1 << 29) + static_cast<int>(k);
  return 1 << 30;
}

/// One entry to compute: a knot or a link, by name.
struct Subject {
  std::string name;
  std::function<KnotEntry(const ExploreOptions&, const std::string&, const RunCallback&)> explore;
};

std::vector<Subject> subjects(const DatasetRunOptions& o) {
  std::vector<Subject> out;
  for (const KnotRecord* k : o.knots)
    out.push_back({k->name, [k](const ExploreOptions& e, const std::string& j, const RunCallback& cb) {
                     return explore_knot(*k, e, j, cb);
                   }});
  for (const LinkRecord* l : o.links)
    out.push_back({l->name, [l](const ExploreOptions& e, const std::string& j, const RunCallback& cb) {
                     return explore_link(*l, e, j, cb);
                   }});
  return out;
}

/// Every merge input exists, is named once and is finished: a `knots dataset`
/// run keeps its work folder "<output>.work/" until it has written its output,
/// so an input beside such a folder is a shard still running or interrupted
/// (an extended output's old version, or none at all).
void require_finished_inputs(const std::vector<std::string>& inputs) {
  std::map<std::string, std::string> seen;  // canonical path -> as given
  for (const auto& in : inputs) {
    if (fs::exists(in + ".work"))
      throw InputError("merge: '" + in + "' is unfinished: its run left '" + in +
                       ".work/' (running or interrupted); rerun the same knots dataset command to finish it");
    if (!fs::exists(in)) throw InputError("merge: '" + in + "' does not exist");
    std::error_code ec;
    const std::string key = fs::weakly_canonical(in, ec).string();
    if (seen.count(key))
      throw InputError("merge: '" + in + "' is given twice" + (seen[key] == in ? "" : " (also as '" + seen[key] + "')"));
    seen[key] = in;
  }
}

}  // namespace

std::pair<int, int> parse_shard(const std::string& text) {
  const auto slash = text.find('/');
  int i = 0, n = 0;
  try {
    if (slash == std::string::npos) throw std::invalid_argument("");
    size_t p1 = 0, p2 = 0;
    i = std::stoi(text.substr(0, slash), &p1);
    n = std::stoi(text.substr(slash + 1), &p2);
    if (p1 != slash || p2 != text.size() - slash - 1) throw std::invalid_argument("");
  } catch (const std::exception&) {
    throw InputError("--shard '" + text + "': expected I/N, for example 2/8");
  }
  if (n < 1 || i < 1 || i > n) throw InputError("--shard '" + text + "': need 1 <= I <= N");
  return {i - 1, n};
}

DatasetRunSummary run_dataset(const DatasetRunOptions& o) {
  o.explore.validate();
  require_input(o.shard_count >= 1 && o.shard_index >= 0 && o.shard_index < o.shard_count, "bad shard");
  check_writable(o.output);
  const Stopwatch t0;
  DatasetMetadata meta = dataset_metadata(o.explore);
  meta.created = now_iso8601();
  // An existing output must have the same parameters; its knots are kept.
  std::vector<std::string> existing;
  if (fs::exists(o.output)) {
    DatasetReader old(o.output);
    const std::string diff = old.metadata().difference(meta);
    if (!diff.empty())
      throw InputError("'" + o.output + "' exists with different parameters (" + diff +
                       "); choose another output or the same parameters");
    existing = old.knot_names();
    meta.created = old.metadata().created;
    meta.forget_unrecorded(old.metadata());  // its knots were computed at values it does not know
  }
  const std::vector<Subject> all = subjects(o);
  std::vector<const Subject*> mine;
  for (size_t k = 0; k < all.size(); ++k)
    if (static_cast<int>(k % static_cast<size_t>(o.shard_count)) == o.shard_index) mine.push_back(&all[k]);

  const std::string work = o.output + ".work";
  std::error_code ec;
  fs::create_directories(work, ec);
  if (ec) throw InputError("cannot create work folder '" + work + "': " + ec.message());
  remove_stale_temporaries(work, "");
  const fs::path output(o.output);
  remove_stale_temporaries(output.has_parent_path() ? output.parent_path().string() : std::string("."),
                           output.filename().string() + ".tmp.");

  DatasetRunSummary summary;
  summary.knots = static_cast<int>(mine.size());
  Progress progress(o.progress, summary.knots);
  std::vector<std::string> parts;
  for (const Subject* subject : mine) {
    if (std::find(existing.begin(), existing.end(), subject->name) != existing.end()) {
      // a part or journal left by a run killed after writing the output is not needed
      std::remove((work + "/" + subject->name + ".h5").c_str());
      std::remove((work + "/" + subject->name + ".journal").c_str());
      ++summary.knots_skipped;
      progress.knot_finished();
      continue;
    }
    const std::string part = work + "/" + subject->name + ".h5";
    if (fs::exists(part)) {
      try {
        DatasetReader check(part);
        // the same parameters as this run, or the part is recomputed
        if (check.has_knot(subject->name) && check.metadata().difference(meta).empty()) {
          parts.push_back(part);
          ++summary.knots_resumed;
          progress.knot_finished();
          continue;
        }
      } catch (const InputError&) {
        // unreadable part (cannot happen with rename, but be safe): recompute
      }
    }
    progress.knot_started(subject->name);
    const std::string journal = work + "/" + subject->name + ".journal";
    KnotEntry entry = subject->explore(o.explore, journal, [&](const RunRecord& r) {
      ++summary.runs;
      const bool stable = r.status == RunStatus::ConvergedStable;
      if (stable) ++summary.equilibria;
      progress.run_finished(stable);
    });
    {
      DatasetWriter w(part, meta);
      w.add(entry);
      w.commit();
    }
    std::remove(journal.c_str());
    parts.push_back(part);
    progress.knot_finished();
  }
  progress.finish();
  // Assemble: knots of the old output plus the parts, in table order.
  std::map<std::pair<int, std::string>, std::pair<std::string, std::string>> order;  // -> (file, name)
  for (const auto& name : existing) order[{table_index(name), name}] = {o.output, name};
  for (const auto& part : parts) {
    DatasetReader r(part);
    for (const auto& name : r.knot_names()) order[{table_index(name), name}] = {part, name};
  }
  {
    DatasetWriter w(o.output, meta);
    std::map<std::string, std::unique_ptr<DatasetReader>> readers;
    for (const auto& [key, src] : order) {
      auto& reader = readers[src.first];
      if (!reader) reader = std::make_unique<DatasetReader>(src.first);
      w.add(reader->read(src.second));
    }
    readers.clear();
    w.commit();
  }
  // Every knot of this run is in the output now: nothing in the work folder
  // is needed any more, whatever an earlier killed run left there (a part, a
  // journal or a temporary whose writer's PID the system has reused).
  fs::remove_all(work, ec);
  summary.seconds = t0.seconds();
  return summary;
}

void merge_datasets(const std::vector<std::string>& inputs, const std::string& output) {
  require_input(!inputs.empty(), "merge: no input data sets");
  check_writable(output);
  require_finished_inputs(inputs);
  std::vector<std::unique_ptr<DatasetReader>> readers;
  for (const auto& in : inputs) readers.push_back(std::make_unique<DatasetReader>(in));
  DatasetMetadata meta = readers.front()->metadata();
  std::map<std::pair<int, std::string>, size_t> order;
  for (size_t k = 0; k < readers.size(); ++k) {
    const auto& m = readers[k]->metadata();
    // every pair: a field that one input does not record must still agree between the others
    for (size_t j = 0; j < k; ++j) {
      const std::string diff = readers[j]->metadata().difference(m);
      if (!diff.empty())
        throw InputError("merge: '" + inputs[k] + "' has different parameters from '" + inputs[j] + "' (" + diff + ")");
    }
    if (m.created < meta.created) meta.created = m.created;
    meta.forget_unrecorded(m);  // not recorded by one input: unknown for the merge
    for (const auto& name : readers[k]->knot_names()) {
      const auto key = std::make_pair(table_index(name), name);
      if (order.count(key))
        throw InputError("merge: knot " + name + " is in both '" + inputs[order[key]] + "' and '" + inputs[k] + "'");
      order[key] = k;
    }
  }
  DatasetWriter w(output, meta);
  for (const auto& [key, k] : order) w.add(readers[k]->read(key.second));
  readers.clear();
  w.commit();
}

}  // namespace ek
