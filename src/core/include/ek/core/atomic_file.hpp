#pragma once
/// \file
/// Crash-safe file output: nothing a user had is lost or overwritten by a
/// failed or interrupted run.
///
/// AtomicFile writes to a temporary file in the destination's folder and
/// renames it over the destination only in commit(). If the writer is
/// destroyed without commit() (an exception, a signal that unwinds), the
/// temporary is removed and the destination is untouched. rename(2) within a
/// file system is atomic, so readers see either the old or the new file.
#include <fstream>
#include <string>

namespace ek {

/// A file written under a temporary name and renamed onto its destination by
/// commit(), so that the destination holds either its previous contents or the
/// complete new ones (see the file's description).
class AtomicFile {
 public:
  /// Opens "<path>.tmp.<pid>.<counter>" for writing. Throws InputError when the
  /// destination folder does not exist or is not writable.
  explicit AtomicFile(std::string path, bool binary = false);
  ~AtomicFile();  ///< Without commit(): closes and removes the temporary; the destination is untouched.
  /// Not copyable: one writer owns its temporary file.
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;  ///< Not copyable.

  std::ostream& stream() { return out_; }                     ///< The stream that writes the temporary file.
  /// "<path>.tmp.<pid>.<counter>", renamed onto the destination by commit().
  const std::string& temporary_path() const { return tmp_; }
  /// Flushes, fsyncs and renames the temporary onto the destination.
  /// Throws InputError if any write failed.
  void commit();

 private:
  std::string path_;
  std::string tmp_;
  std::ofstream out_;
  bool committed_ = false;
};

/// Throws InputError unless `path` can be created or replaced: its folder
/// exists and is writable, and `path` is not a folder. Call before long runs so
/// that an unwritable output fails at once, not after hours.
void check_writable(const std::string& path);

/// Renames `from` onto `to` atomically after fsync; throws InputError on failure.
void atomic_replace(const std::string& from, const std::string& to);

/// A fresh temporary name next to `path`: "<path>.tmp.<pid>.<n>", n
/// counting up in this process (thread-safe). The writers of this project
/// write there and rename onto `path`; remove_stale_temporaries() knows the
/// pattern.
std::string temporary_path(const std::string& path);

/// Removes the temporaries "<prefix>*.tmp.<pid>.<n>" in `folder` that a
/// killed run left behind (their process is gone): writers remove their own,
/// except after SIGKILL. Errors are ignored (a leftover temporary is harmless).
void remove_stale_temporaries(const std::string& folder, const std::string& prefix);

}  // namespace ek
