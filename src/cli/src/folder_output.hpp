#pragma once
// An output folder written as a whole (`knots saddles`, `knots transition`):
// its files go into a temporary folder beside it, renamed into place once
// every file is there; an existing folder is replaced (with --overwrite)
// only after the new one is complete.
#include <filesystem>
#include <functional>
#include <string>
#include <unistd.h>

#include "ek/core/atomic_file.hpp"
#include "ek/core/errors.hpp"
#include "ek/core/json.hpp"

namespace ek::cli {

/// Refuses an output folder that exists (without `overwrite`) or whose
/// parent cannot take the temporary folder, before any work.
inline void check_output_folder(const std::string& out, bool overwrite) {
  namespace fs = std::filesystem;
  if (out.empty()) throw InputError("-o DIR is required");
  const fs::path p = fs::absolute(out);
  if (fs::exists(p) && !overwrite) throw InputError("output folder " + out + " exists (use --overwrite to replace it)");
  if (fs::exists(p) && !fs::is_directory(p)) throw InputError("output " + out + " exists and is not a folder");
  check_writable((p.parent_path() / ".knots-output-probe").string());
}

/// Calls `fill` with a temporary folder, then renames it onto `out`.
inline void write_folder(const std::string& out, const std::function<void(const std::filesystem::path&)>& fill) {
  namespace fs = std::filesystem;
  const fs::path p = fs::absolute(out);
  const fs::path tmp = p.parent_path() / (p.filename().string() + ".tmp." + std::to_string(::getpid()));
  fs::remove_all(tmp);
  fs::create_directories(tmp);
  try {
    fill(tmp);
    const fs::path old = p.parent_path() / (p.filename().string() + ".old." + std::to_string(::getpid()));
    const bool replace = fs::exists(p);
    if (replace) fs::rename(p, old);
    fs::rename(tmp, p);
    if (replace) fs::remove_all(old);
  } catch (...) {
    std::error_code ec;
    fs::remove_all(tmp, ec);
    throw;
  }
}

/// A folder command's summary: `input` first, then the library's
/// description, with `output` before its last key `seconds`.
inline Json framed_summary(const std::string& input, const Json& description, const std::string& out) {
  Json j;
  j["input"] = input;
  j.update(description);
  const Json seconds = j["seconds"];
  j.erase("seconds");
  j["output"] = out;
  j["seconds"] = seconds;
  return j;
}

/// Writes `summary` as FOLDER/summary.json (indented), atomically.
inline void write_summary_json(const std::filesystem::path& folder, const Json& summary) {
  AtomicFile f((folder / "summary.json").string());
  f.stream() << summary.dump(2) << "\n";
  f.commit();
}

}  // namespace ek::cli
