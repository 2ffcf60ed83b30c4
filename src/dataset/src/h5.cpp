#include "ek/dataset/h5.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include <cerrno>
#include <cinttypes>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <numeric>

#include "ek/core/errors.hpp"

namespace ek::h5 {
namespace {

[[noreturn]] void fail(const std::string& what) { throw InputError(what); }

herr_t collect(hid_t, const char* name, const H5L_info_t*, void* data) {
  static_cast<std::vector<std::string>*>(data)->push_back(name);
  return 0;
}

Handle space_of(const std::vector<hsize_t>& shape) {
  if (shape.empty()) return Handle(H5Screate(H5S_SCALAR), H5Sclose);
  return Handle(H5Screate_simple(static_cast<int>(shape.size()), shape.data(), nullptr), H5Sclose);
}

hsize_t count_of(const std::vector<hsize_t>& shape) {
  return std::accumulate(shape.begin(), shape.end(), hsize_t{1}, std::multiplies<hsize_t>());
}

/// Number of values of a dataset read from a file, checked against what the
/// file stores: at most 2^40 values, and at most 1100 times the stored bytes
/// (deflate, our only compression, shrinks data by at most about 1032:1). A
/// larger shape is a damaged dataspace, refused before allocating for it.
hsize_t checked_count(hid_t ds, const std::vector<hsize_t>& shape, hsize_t value_size, const std::string& name) {
  constexpr hsize_t kMaxValues = hsize_t{1} << 40;
  hsize_t count = 1;
  for (hsize_t d : shape) {
    if (d != 0 && count > kMaxValues / d) fail("HDF5: dataset '" + name + "' has a damaged shape");
    count *= d;
  }
  const hsize_t stored = H5Dget_storage_size(ds);
  if (count > 0 && count * value_size > 1100 * stored + 1024)
    fail("HDF5: dataset '" + name + "' is damaged (" + std::to_string(count) + " values in " +
         std::to_string(stored) + " stored bytes)");
  return count;
}

/// The dimensions of a dataspace of rank `rank` (checked).
std::vector<hsize_t> dims_of(hid_t space, int rank, const std::string& name) {
  if (H5Sget_simple_extent_ndims(space) != rank) fail("HDF5: '" + name + "' has the wrong rank");
  std::vector<hsize_t> dims(static_cast<size_t>(rank));
  if (rank > 0 && H5Sget_simple_extent_dims(space, dims.data(), nullptr) != rank)
    fail("HDF5: '" + name + "' has a damaged shape");
  return dims;
}

constexpr char kChecksumHeader[] = "elastic-knots-dataset checksum 1\n";
constexpr char kSignature[] = "\x89HDF\r\n\x1a\n";

/// CRC-32 of the bytes of `fd` from `offset` to `end`.
std::uint32_t crc_of(int fd, off_t offset, off_t end, const std::string& path) {
  std::vector<unsigned char> buf(1 << 20);
  uLong crc = ::crc32(0L, Z_NULL, 0);
  while (offset < end) {
    const size_t want = static_cast<size_t>(std::min<off_t>(end - offset, static_cast<off_t>(buf.size())));
    const ssize_t got = ::pread(fd, buf.data(), want, offset);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) fail("cannot read data set '" + path + "'");
    crc = ::crc32(crc, buf.data(), static_cast<uInt>(got));
    offset += got;
  }
  return static_cast<std::uint32_t>(crc);
}

/// The checksum header (h5.hpp), zero-padded to kUserBlock bytes.
void checksum_header(char (&header)[kUserBlock], std::uint32_t crc, long long length) {
  std::memset(header, 0, kUserBlock);
  std::snprintf(header, kUserBlock, "%scrc32 %08" PRIx32 "\nlength %lld\n", kChecksumHeader, crc, length);
}

/// An open file descriptor, closed on scope exit.
struct Fd {
  int fd;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

Handle string_type() {
  Handle t(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(t.id(), H5T_VARIABLE);
  H5Tset_cset(t.id(), H5T_CSET_UTF8);
  return t;
}

template <class T>
void write_numeric(hid_t parent, const std::string& name, const std::vector<hsize_t>& shape, const T* data,
                   hid_t mem_type, hid_t file_type) {
  Handle space = space_of(shape);
  Handle plist(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  // chunk + compress large arrays (curves compress well)
  if (!shape.empty() && count_of(shape) >= 4096) {
    std::vector<hsize_t> chunk = shape;
    chunk[0] = std::max<hsize_t>(1, std::min<hsize_t>(shape[0], 65536 / std::max<hsize_t>(1, count_of(shape) / std::max<hsize_t>(shape[0], 1))));
    H5Pset_chunk(plist.id(), static_cast<int>(chunk.size()), chunk.data());
    H5Pset_shuffle(plist.id());
    H5Pset_deflate(plist.id(), 4);
  }
  Handle ds(H5Dcreate2(parent, name.c_str(), file_type, space.id(), H5P_DEFAULT, plist.id(), H5P_DEFAULT), H5Dclose);
  if (!ds.valid()) fail("HDF5: cannot create dataset '" + name + "'");
  if (count_of(shape) > 0 && H5Dwrite(ds.id(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0)
    fail("HDF5: cannot write dataset '" + name + "'");
}

template <class T>
std::vector<T> read_numeric(hid_t parent, const std::string& name, std::vector<hsize_t>* shape_out, hid_t mem_type) {
  Handle ds(H5Dopen2(parent, name.c_str(), H5P_DEFAULT), H5Dclose);
  if (!ds.valid()) fail("HDF5: dataset '" + name + "' is missing");
  Handle space(H5Dget_space(ds.id()), H5Sclose);
  const int rank = H5Sget_simple_extent_ndims(space.id());
  if (rank < 0 || rank > 8) fail("HDF5: dataset '" + name + "' has a damaged shape");
  const std::vector<hsize_t> shape = dims_of(space.id(), rank, name);
  std::vector<T> out(checked_count(ds.id(), shape, sizeof(T), name));
  if (!out.empty() && H5Dread(ds.id(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()) < 0)
    fail("HDF5: cannot read dataset '" + name + "'");
  if (shape_out) *shape_out = shape;
  return out;
}

}  // namespace

void quiet() {
  static std::once_flag once;
  std::call_once(once, [] { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); });
}

Handle create_file(const std::string& path) {
  quiet();
  Handle fcpl(H5Pcreate(H5P_FILE_CREATE), H5Pclose);
  Handle fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  // closing the file closes every object in it, so that the file is complete when sealed
  if (H5Pset_userblock(fcpl.id(), kUserBlock) < 0 || H5Pset_fclose_degree(fapl.id(), H5F_CLOSE_STRONG) < 0)
    fail("HDF5: cannot set up data set '" + path + "'");
  Handle f(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, fcpl.id(), fapl.id()), H5Fclose);
  if (!f.valid()) fail("cannot create data set '" + path + "'");
  return f;
}

void seal(const std::string& path) {
  const Fd f{::open(path.c_str(), O_RDWR)};
  struct stat st {};
  if (f.fd < 0 || ::fstat(f.fd, &st) != 0 || st.st_size < static_cast<off_t>(kUserBlock))
    fail("cannot write the checksum of data set '" + path + "'");
  char header[kUserBlock];
  checksum_header(header, crc_of(f.fd, static_cast<off_t>(kUserBlock), st.st_size, path), st.st_size);
  if (::pwrite(f.fd, header, sizeof header, 0) != static_cast<ssize_t>(sizeof header) || ::fsync(f.fd) != 0)
    fail("cannot write the checksum of data set '" + path + "'");
}

bool verify(const std::string& path, const std::string& kind) {
  const Fd f{::open(path.c_str(), O_RDONLY)};
  struct stat st {};
  if (f.fd < 0 || ::fstat(f.fd, &st) != 0) fail("cannot open " + kind + " '" + path + "': " + std::strerror(errno));
  char header[kUserBlock + 1] = {};
  const ssize_t got = ::pread(f.fd, header, kUserBlock, 0);
  if (got >= 8 && std::memcmp(header, kSignature, 8) == 0) return false;  // written before checksums
  const size_t tag = sizeof kChecksumHeader - 1;
  if (got < static_cast<ssize_t>(tag) || std::memcmp(header, kChecksumHeader, tag) != 0)
    fail("'" + path + "' is not a readable HDF5 " + kind);
  unsigned crc = 0;
  long long length = -1;
  char canonical[kUserBlock];
  if (got != static_cast<ssize_t>(kUserBlock) || std::sscanf(header + tag, "crc32 %8x\nlength %lld\n", &crc, &length) != 2 ||
      (checksum_header(canonical, crc, length), std::memcmp(header, canonical, kUserBlock) != 0))
    fail(kind + " '" + path + "' is damaged: its checksum header is unreadable");
  if (length != static_cast<long long>(st.st_size))
    fail(kind + " '" + path + "' is damaged: " + std::to_string(st.st_size) + " bytes, but it was written with " +
         std::to_string(length) + " (truncated or extended since)");
  if (crc_of(f.fd, static_cast<off_t>(kUserBlock), st.st_size, path) != crc)
    fail(kind + " '" + path + "' is damaged: its checksum does not match (its bytes changed after it was written)");
  return true;
}

Handle open_file(const std::string& path, bool writable) {
  quiet();
  if (H5Fis_hdf5(path.c_str()) <= 0)
    fail("'" + path + "' is not a readable HDF5 data set");
  Handle f(H5Fopen(path.c_str(), writable ? H5F_ACC_RDWR : H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!f.valid()) fail("cannot open data set '" + path + "'");
  return f;
}

Handle create_group(hid_t parent, const std::string& name) {
  Handle g(H5Gcreate2(parent, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
  if (!g.valid()) fail("HDF5: cannot create group '" + name + "'");
  return g;
}

Handle open_group(hid_t parent, const std::string& name) {
  Handle g(H5Gopen2(parent, name.c_str(), H5P_DEFAULT), H5Gclose);
  if (!g.valid()) fail("HDF5: group '" + name + "' is missing");
  return g;
}

bool exists(hid_t parent, const std::string& name) { return H5Lexists(parent, name.c_str(), H5P_DEFAULT) > 0; }

std::vector<std::string> children(hid_t group) {
  std::vector<std::string> names;
  hsize_t idx = 0;
  H5Literate(group, H5_INDEX_NAME, H5_ITER_INC, &idx, collect, &names);
  return names;
}

void write_doubles(hid_t parent, const std::string& name, const std::vector<hsize_t>& shape, const double* data) {
  write_numeric(parent, name, shape, data, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE);
}

void write_float32(hid_t parent, const std::string& name, const std::vector<hsize_t>& shape, const double* data) {
  write_numeric(parent, name, shape, data, H5T_NATIVE_DOUBLE, H5T_IEEE_F32LE);
}

void write_int64(hid_t parent, const std::string& name, const std::vector<hsize_t>& shape, const std::int64_t* data) {
  write_numeric(parent, name, shape, data, H5T_NATIVE_INT64, H5T_STD_I64LE);
}

std::vector<double> read_doubles(hid_t parent, const std::string& name, std::vector<hsize_t>* shape) {
  return read_numeric<double>(parent, name, shape, H5T_NATIVE_DOUBLE);
}

std::vector<std::int64_t> read_int64(hid_t parent, const std::string& name, std::vector<hsize_t>* shape) {
  return read_numeric<std::int64_t>(parent, name, shape, H5T_NATIVE_INT64);
}

void write_strings(hid_t parent, const std::string& name, const std::vector<std::string>& values) {
  Handle type = string_type();
  std::vector<hsize_t> shape{values.size()};
  Handle space = space_of(shape);
  Handle ds(H5Dcreate2(parent, name.c_str(), type.id(), space.id(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose);
  if (!ds.valid()) fail("HDF5: cannot create dataset '" + name + "'");
  std::vector<const char*> ptrs;
  for (const auto& v : values) ptrs.push_back(v.c_str());
  if (!ptrs.empty() && H5Dwrite(ds.id(), type.id(), H5S_ALL, H5S_ALL, H5P_DEFAULT, ptrs.data()) < 0)
    fail("HDF5: cannot write dataset '" + name + "'");
}

std::vector<std::string> read_strings(hid_t parent, const std::string& name) {
  Handle ds(H5Dopen2(parent, name.c_str(), H5P_DEFAULT), H5Dclose);
  if (!ds.valid()) fail("HDF5: dataset '" + name + "' is missing");
  Handle space(H5Dget_space(ds.id()), H5Sclose);
  const hsize_t n = dims_of(space.id(), 1, name).front();
  if (n > H5Dget_storage_size(ds.id())) fail("HDF5: dataset '" + name + "' is damaged");
  Handle type = string_type();
  std::vector<char*> ptrs(n, nullptr);
  if (n > 0 && H5Dread(ds.id(), type.id(), H5S_ALL, H5S_ALL, H5P_DEFAULT, ptrs.data()) < 0)
    fail("HDF5: cannot read dataset '" + name + "'");
  std::vector<std::string> out;
  for (char* p : ptrs) out.emplace_back(p ? p : "");
  if (n > 0) H5Dvlen_reclaim(type.id(), space.id(), H5P_DEFAULT, ptrs.data());
  return out;
}

namespace {

void write_attr(hid_t obj, const std::string& name, hid_t mem_type, hid_t file_type, const std::vector<hsize_t>& shape,
                const void* data) {
  if (H5Aexists(obj, name.c_str()) > 0) H5Adelete(obj, name.c_str());
  Handle space = space_of(shape);
  Handle a(H5Acreate2(obj, name.c_str(), file_type, space.id(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  // An empty list has nothing to write (HDF5 refuses a write from no buffer).
  const bool empty = !shape.empty() && count_of(shape) == 0;
  if (!a.valid() || (!empty && H5Awrite(a.id(), mem_type, data) < 0))
    fail("HDF5: cannot write attribute '" + name + "'");
}

Handle open_attr(hid_t obj, const std::string& name) {
  Handle a(H5Aopen(obj, name.c_str(), H5P_DEFAULT), H5Aclose);
  if (!a.valid()) fail("data set attribute '" + name + "' is missing");
  return a;
}

/// Opens an attribute that must hold exactly one value.
Handle open_scalar_attr(hid_t obj, const std::string& name) {
  Handle a = open_attr(obj, name);
  Handle space(H5Aget_space(a.id()), H5Sclose);
  if (H5Sget_simple_extent_npoints(space.id()) != 1) fail("data set attribute '" + name + "' is not one value");
  return a;
}

}  // namespace

void set_attr(hid_t obj, const std::string& name, const std::string& value) {
  Handle type = string_type();
  const char* p = value.c_str();
  write_attr(obj, name, type.id(), type.id(), {}, &p);
}

void set_attr(hid_t obj, const std::string& name, double value) {
  write_attr(obj, name, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, {}, &value);
}

void set_attr(hid_t obj, const std::string& name, std::int64_t value) {
  write_attr(obj, name, H5T_NATIVE_INT64, H5T_STD_I64LE, {}, &value);
}

void set_attr(hid_t obj, const std::string& name, const std::vector<std::int64_t>& values) {
  write_attr(obj, name, H5T_NATIVE_INT64, H5T_STD_I64LE, {values.size()}, values.data());
}

bool has_attr(hid_t obj, const std::string& name) { return H5Aexists(obj, name.c_str()) > 0; }

std::string get_attr_string(hid_t obj, const std::string& name) {
  Handle a = open_scalar_attr(obj, name);
  Handle type = string_type();
  char* p = nullptr;
  if (H5Aread(a.id(), type.id(), &p) < 0) fail("data set attribute '" + name + "' is not a string");
  std::string out = p ? p : "";
  H5free_memory(p);
  return out;
}

double get_attr_double(hid_t obj, const std::string& name) {
  Handle a = open_scalar_attr(obj, name);
  double v = 0.0;
  if (H5Aread(a.id(), H5T_NATIVE_DOUBLE, &v) < 0) fail("data set attribute '" + name + "' is not a number");
  return v;
}

std::int64_t get_attr_int(hid_t obj, const std::string& name) {
  Handle a = open_scalar_attr(obj, name);
  std::int64_t v = 0;
  if (H5Aread(a.id(), H5T_NATIVE_INT64, &v) < 0) fail("data set attribute '" + name + "' is not an integer");
  return v;
}

std::vector<std::int64_t> get_attr_ints(hid_t obj, const std::string& name) {
  Handle a = open_attr(obj, name);
  Handle space(H5Aget_space(a.id()), H5Sclose);
  const hsize_t n = dims_of(space.id(), 1, name).front();
  if (n > 4096) fail("data set attribute '" + name + "' is damaged");
  std::vector<std::int64_t> v(n);
  if (n > 0 && H5Aread(a.id(), H5T_NATIVE_INT64, v.data()) < 0)
    fail("data set attribute '" + name + "' is not an integer list");
  return v;
}

}  // namespace ek::h5
