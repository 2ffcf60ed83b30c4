#include "ek/core/atomic_file.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include "ek/core/errors.hpp"

namespace ek {
namespace {

std::string parent_folder(const std::string& path) {
  std::filesystem::path p(path);
  auto parent = p.parent_path();
  return parent.empty() ? std::string(".") : parent.string();
}

void fsync_path(const std::string& path) {
  int fd = ::open(path.c_str(), O_RDONLY);
  if (fd >= 0) {
    ::fsync(fd);
    ::close(fd);
  }
}

}  // namespace

void check_writable(const std::string& path) {
  require_input(!path.empty(), "output path is empty");
  std::string folder = parent_folder(path);
  struct stat st {};
  if (::stat(folder.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
    throw InputError("cannot write '" + path + "': folder '" + folder + "' does not exist");
  if (::access(folder.c_str(), W_OK) != 0)
    throw InputError("cannot write '" + path + "': folder '" + folder + "' is not writable");
  if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
    throw InputError("cannot write '" + path + "': it is a folder");
}

void atomic_replace(const std::string& from, const std::string& to) {
  fsync_path(from);
  if (std::rename(from.c_str(), to.c_str()) != 0)
    throw InputError("cannot write '" + to + "': " + std::strerror(errno));
  fsync_path(parent_folder(to));
}

AtomicFile::AtomicFile(std::string path, bool binary) : path_(std::move(path)) {
  check_writable(path_);
  tmp_ = ek::temporary_path(path_);
  out_.open(tmp_, binary ? std::ios::out | std::ios::binary | std::ios::trunc
                         : std::ios::out | std::ios::trunc);
  if (!out_) throw InputError("cannot write '" + path_ + "': " + std::strerror(errno));
}

AtomicFile::~AtomicFile() {
  if (!committed_) {
    out_.close();
    std::remove(tmp_.c_str());
  }
}

void AtomicFile::commit() {
  out_.flush();
  bool ok = static_cast<bool>(out_);
  out_.close();
  if (!ok || out_.fail()) {
    std::remove(tmp_.c_str());
    committed_ = true;
    throw InputError("cannot write '" + path_ + "': write failed");
  }
  atomic_replace(tmp_, path_);
  committed_ = true;
}

std::string temporary_path(const std::string& path) {
  static std::atomic<unsigned> counter{0};
  return path + ".tmp." + std::to_string(::getpid()) + "." + std::to_string(counter++);
}

void remove_stale_temporaries(const std::string& folder, const std::string& prefix) {
  namespace fs = std::filesystem;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    const std::string name = entry.path().filename().string();
    const auto tmp = name.rfind(".tmp.");
    if (name.rfind(prefix, 0) != 0 || tmp == std::string::npos) continue;
    char* end = nullptr;
    const long pid = std::strtol(name.c_str() + tmp + 5, &end, 10);
    if (pid <= 0 || *end != '.' || pid == ::getpid() || ::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH)
      continue;
    fs::remove(entry.path(), ec);
  }
}

}  // namespace ek
