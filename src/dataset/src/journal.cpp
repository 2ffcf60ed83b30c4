#include "journal.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

#include "ek/core/errors.hpp"

namespace ek {
namespace {

constexpr std::uint32_t kMagic = 0x324E5552;       // "RUN2": records with link and min_distance
constexpr std::uint32_t kFirstMagic = 0x314E5552;  // "RUN1": read, never written (JournalRun::first_layout)
const std::string kHeader = "elastic-knots-journal 1\n";

class Writer {
 public:
  template <class T>
  void put(const T& v) {
    const char* p = reinterpret_cast<const char*>(&v);
    buf.insert(buf.end(), p, p + sizeof(T));
  }
  void str(const std::string& s) {
    put(static_cast<std::uint32_t>(s.size()));
    buf.insert(buf.end(), s.begin(), s.end());
  }
  std::vector<char> buf;
};

class Reader {
 public:
  Reader(const char* p, size_t n) : p_(p), n_(n) {}
  template <class T>
  T get() {
    if (sizeof(T) > n_ - pos_) throw std::runtime_error("short record");
    T v;
    std::memcpy(&v, p_ + pos_, sizeof(T));
    pos_ += sizeof(T);
    return v;
  }
  std::string str() {
    const auto len = get<std::uint32_t>();
    if (len > n_ - pos_) throw std::runtime_error("short record");
    std::string s(p_ + pos_, len);
    pos_ += len;
    return s;
  }
  bool done() const { return pos_ == n_; }
  size_t left() const { return n_ - pos_; }

 private:
  const char* p_;
  size_t n_;
  size_t pos_ = 0;
};

std::vector<char> encode(const JournalRun& r) {
  Writer w;
  w.put(static_cast<std::int32_t>(r.record.sample));
  w.put(static_cast<std::uint64_t>(r.record.seed));
  w.str(to_string(r.record.status));
  w.put(static_cast<std::int32_t>(r.record.equilibrium));
  w.put(static_cast<std::int32_t>(r.record.iterations));
  w.put(r.record.seconds);
  w.put(r.record.energy);
  w.put(r.record.gradient_norm);
  w.put(static_cast<std::int32_t>(r.record.contacts));
  w.put(static_cast<std::int32_t>(r.record.topology_preserved ? 1 : 0));
  w.str(r.record.message);
  for (double e : {r.energy.total, r.energy.stretch, r.energy.bend, r.energy.twist, r.energy.contact, r.energy.slab})
    w.put(e);
  w.put(r.stiffness);
  w.put(r.link);
  w.put(r.min_distance);
  w.put(static_cast<std::int32_t>(r.positions.rows()));
  for (Eigen::Index k = 0; k < r.positions.size(); ++k) w.put(r.positions.data()[k]);
  return w.buf;
}

JournalRun decode(const char* p, size_t n, bool first_layout) {
  Reader rd(p, n);
  JournalRun r;
  r.first_layout = first_layout;
  r.record.sample = rd.get<std::int32_t>();
  r.record.seed = rd.get<std::uint64_t>();
  try {
    r.record.status = parse_run_status(rd.str());
  } catch (const InputError&) {
    throw std::runtime_error("bad record");
  }
  r.record.equilibrium = rd.get<std::int32_t>();
  r.record.iterations = rd.get<std::int32_t>();
  r.record.seconds = rd.get<double>();
  r.record.energy = rd.get<double>();
  r.record.gradient_norm = rd.get<double>();
  r.record.contacts = rd.get<std::int32_t>();
  r.record.topology_preserved = rd.get<std::int32_t>() != 0;
  r.record.message = rd.str();
  r.energy.total = rd.get<double>();
  r.energy.stretch = rd.get<double>();
  r.energy.bend = rd.get<double>();
  r.energy.twist = rd.get<double>();
  r.energy.contact = rd.get<double>();
  r.energy.slab = rd.get<double>();
  r.stiffness = rd.get<double>();
  r.link = rd.get<double>();
  r.min_distance = first_layout ? std::nan("") : rd.get<double>();
  const auto rows = rd.get<std::int32_t>();
  if (rows < 0 || static_cast<size_t>(rows) > rd.left() / (3 * sizeof(double))) throw std::runtime_error("bad record");
  r.positions.resize(rows, 3);
  for (Eigen::Index k = 0; k < r.positions.size(); ++k) r.positions.data()[k] = rd.get<double>();
  if (!rd.done()) throw std::runtime_error("trailing bytes");
  return r;
}

void write_all(int fd, const char* p, size_t n, const std::string& path) {
  while (n > 0) {
    const ssize_t k = ::write(fd, p, n);
    if (k < 0) {
      if (errno == EINTR) continue;
      throw InputError("cannot write journal '" + path + "': " + std::strerror(errno));
    }
    p += k;
    n -= static_cast<size_t>(k);
  }
}

}  // namespace

std::string journal_head(const std::string& options_text) { return kHeader + options_text + "\n"; }

JournalContents parse_journal(const std::string& data, const std::string& head, const std::string& path) {
  JournalContents out;
  if (data.size() < head.size() && head.compare(0, data.size(), data) == 0) return out;  // empty or torn header
  if (data.compare(0, head.size(), head) != 0) {
    if (data.compare(0, kHeader.size(), kHeader) == 0)
      throw InputError("journal '" + path +
                       "' belongs to a run with different options; remove it (or its work folder) to start over");
    throw InputError("'" + path + "' is not a journal of this program");
  }
  size_t pos = head.size();
  out.good = pos;
  while (data.size() - pos >= 12) {
    std::uint32_t magic, len, crc;
    std::memcpy(&magic, data.data() + pos, 4);
    std::memcpy(&len, data.data() + pos + 4, 4);
    if ((magic != kMagic && magic != kFirstMagic) || len > data.size() - pos - 12) break;
    std::memcpy(&crc, data.data() + pos + 8 + len, 4);
    const auto actual = static_cast<std::uint32_t>(
        ::crc32(0L, reinterpret_cast<const Bytef*>(data.data() + pos + 8), static_cast<uInt>(len)));
    if (crc != actual) break;
    try {
      JournalRun r = decode(data.data() + pos + 8, len, magic == kFirstMagic);
      out.runs[r.record.sample] = std::move(r);
    } catch (const std::runtime_error&) {
      break;
    }
    pos += 12 + len;
    out.good = pos;
  }
  return out;
}

Journal::Journal(std::string path, const std::string& options_text) : path_(std::move(path)) {
  const std::string head = journal_head(options_text);
  off_t good = 0;
  {
    std::ifstream in(path_, std::ios::binary);
    if (in) {
      std::stringstream ss;
      ss << in.rdbuf();
      JournalContents contents = parse_journal(ss.str(), head, path_);
      runs_ = std::move(contents.runs);
      good = static_cast<off_t>(contents.good);
    }
  }
  fd_ = ::open(path_.c_str(), O_WRONLY | O_CREAT, 0644);
  if (fd_ < 0) throw InputError("cannot write journal '" + path_ + "': " + std::strerror(errno));
  if (good == 0) {
    if (::ftruncate(fd_, 0) != 0) throw InputError("cannot write journal '" + path_ + "'");
    write_all(fd_, head.data(), head.size(), path_);
    good = static_cast<off_t>(head.size());
  } else if (::ftruncate(fd_, good) != 0) {
    throw InputError("cannot truncate journal '" + path_ + "'");
  }
  ::lseek(fd_, good, SEEK_SET);
  ::fsync(fd_);
}

Journal::~Journal() {
  if (fd_ >= 0) ::close(fd_);
}

void Journal::append(const JournalRun& run) {
  const std::vector<char> payload = encode(run);
  std::vector<char> rec(12 + payload.size());
  const std::uint32_t len = static_cast<std::uint32_t>(payload.size());
  const auto crc = static_cast<std::uint32_t>(
      ::crc32(0L, reinterpret_cast<const Bytef*>(payload.data()), static_cast<uInt>(payload.size())));
  std::memcpy(rec.data(), &kMagic, 4);
  std::memcpy(rec.data() + 4, &len, 4);
  std::memcpy(rec.data() + 8, payload.data(), payload.size());
  std::memcpy(rec.data() + 8 + payload.size(), &crc, 4);
  std::lock_guard<std::mutex> lock(mutex_);
  write_all(fd_, rec.data(), rec.size(), path_);
  ::fsync(fd_);
  runs_[run.record.sample] = run;
}

void Journal::remove() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  std::remove(path_.c_str());
}

}  // namespace ek
