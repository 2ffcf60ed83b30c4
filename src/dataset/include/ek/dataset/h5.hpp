#pragma once
/// \file
/// Thin RAII helpers over the HDF5 C API, shared by the HDF5 files of the
/// project: data sets (dataset_file.hpp) and transition graphs
/// (ek/transitions/transitions_file.hpp). Includes hdf5.h: a module that uses
/// it links HDF5 itself.
#include <hdf5.h>

#include <cstdint>
#include <string>
#include <vector>

/// The HDF5 helpers: RAII handles, files with a checksum header, groups,
/// datasets and attributes. Every failure is an InputError.
namespace ek::h5 {

/// Owns an HDF5 identifier and closes it with the matching H5*close.
class Handle {
 public:
  Handle() = default;  ///< No identifier (valid() is false).
  /// Owns `id`, closed by `closer` (H5Fclose, H5Gclose, ...).
  Handle(hid_t id, herr_t (*closer)(hid_t)) : id_(id), closer_(closer) {}
  ~Handle() { reset(); }  ///< Closes the identifier.
  /// Takes over `o`'s identifier (`o` is left empty).
  Handle(Handle&& o) noexcept : id_(o.id_), closer_(o.closer_) { o.id_ = -1; }
  /// Closes the own identifier and takes over `o`'s.
  Handle& operator=(Handle&& o) noexcept {
    if (this != &o) {
      reset();
      id_ = o.id_;
      closer_ = o.closer_;
      o.id_ = -1;
    }
    return *this;
  }
  /// Not copyable: one handle closes its identifier.
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;  ///< Not copyable.
  hid_t id() const { return id_; }            ///< The identifier (-1 when empty).
  bool valid() const { return id_ >= 0; }     ///< Whether it holds an identifier.
  void reset() { close(); }                   ///< Closes the identifier, ignoring errors.
  /// Closes the identifier; false when HDF5 reports an error (a file that
  /// could not be flushed completely).
  bool close() {
    const herr_t status = (id_ >= 0 && closer_) ? closer_(id_) : 0;
    id_ = -1;
    return status >= 0;
  }

 private:
  hid_t id_ = -1;
  herr_t (*closer_)(hid_t) = nullptr;
};

/// Silences HDF5's automatic error printing for the lifetime of the process
/// (errors are turned into exceptions with our own messages).
void quiet();

/// Creates (truncates) a file with a user block of kUserBlock bytes in front
/// of the HDF5 data, for the checksum header written by seal(). Throws InputError.
Handle create_file(const std::string& path);
/// Opens a file; throws InputError naming the file. Call verify() first.
Handle open_file(const std::string& path, bool writable);

/// The checksum header (the HDF5 user block, which the HDF5 library skips):
/// ~~~{.unparsed}
///   "elastic-knots-dataset checksum 1\ncrc32 <8 hex digits>\nlength <bytes>\n",
/// ~~~
/// zero-padded to kUserBlock bytes. crc32 is the CRC-32 (zlib) of every byte
/// after the user block, length the size of the whole file: any change to the
/// file after it was written (truncation, a flipped bit, a byte appended) is
/// detected before HDF5 parses it.
constexpr hsize_t kUserBlock = 512;
/// Writes the checksum header of the closed file `path` (created by create_file).
void seal(const std::string& path);
/// Checks a file before HDF5 opens it. A sealed file must match its header:
/// returns true. A file whose HDF5 signature is at byte 0 has no header
/// (written before data sets carried a checksum): returns false, unchecked.
/// Throws InputError naming the file otherwise (damaged, or not a data set);
/// `kind` names what the file should be in the messages ("data set", "ledger").
bool verify(const std::string& path, const std::string& kind = "data set");
Handle create_group(hid_t parent, const std::string& name);  ///< A new group `name` in `parent`.
Handle open_group(hid_t parent, const std::string& name);  ///< The group `name` of `parent`; InputError when missing.
bool exists(hid_t parent, const std::string& name);  ///< Whether `parent` has a member (link) named `name`.
std::vector<std::string> children(hid_t group);   ///< names of the members, in creation/name order

/// Datasets of doubles / int64 / strings with an arbitrary shape (row-major).
/// Arrays of 4096 values or more are chunked and compressed (shuffle,
/// deflate 4). This one: float64 values.
void write_doubles(hid_t parent, const std::string& name, const std::vector<hsize_t>& shape, const double* data);
/// Doubles stored as float32 (rounded to nearest); read_doubles reads them back as doubles.
void write_float32(hid_t parent, const std::string& name, const std::vector<hsize_t>& shape, const double* data);
/// int64 values in a dataset of `shape` (row-major).
void write_int64(hid_t parent, const std::string& name, const std::vector<hsize_t>& shape, const std::int64_t* data);
/// A one-dimensional dataset of variable-length strings.
void write_strings(hid_t parent, const std::string& name, const std::vector<std::string>& values);
/// A numeric dataset read as doubles, row-major; its shape into `shape` when
/// given. InputError when missing or damaged.
std::vector<double> read_doubles(hid_t parent, const std::string& name, std::vector<hsize_t>* shape = nullptr);
/// An integer dataset read as int64, row-major (as read_doubles()).
std::vector<std::int64_t> read_int64(hid_t parent, const std::string& name, std::vector<hsize_t>* shape = nullptr);
/// A one-dimensional dataset of strings; InputError when missing or damaged.
std::vector<std::string> read_strings(hid_t parent, const std::string& name);

/// Attributes on a group or file: set_attr() replaces an attribute of the
/// same name. This one: a string.
void set_attr(hid_t obj, const std::string& name, const std::string& value);
void set_attr(hid_t obj, const std::string& name, double value);                             ///< A float64 attribute.
void set_attr(hid_t obj, const std::string& name, std::int64_t value);                       ///< An int64 attribute.
void set_attr(hid_t obj, const std::string& name, const std::vector<std::int64_t>& values);  ///< A list of int64.
bool has_attr(hid_t obj, const std::string& name);  ///< Whether `obj` has the attribute.
/// A string attribute; InputError when missing or not one string.
std::string get_attr_string(hid_t obj, const std::string& name);
/// A numeric attribute as a double; InputError when missing.
double get_attr_double(hid_t obj, const std::string& name);
std::int64_t get_attr_int(hid_t obj, const std::string& name);  ///< An integer attribute; InputError when missing.
/// An integer list (at most 4096); InputError when missing.
std::vector<std::int64_t> get_attr_ints(hid_t obj, const std::string& name);

}  // namespace ek::h5
