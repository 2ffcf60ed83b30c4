#pragma once
// Private: thin RAII helpers over the HDF5 C API for the data-set files.
#include <hdf5.h>

#include <cstdint>
#include <string>
#include <vector>

namespace ek::h5 {

/// Owns an HDF5 identifier and closes it with the matching H5*close.
class Handle {
 public:
  Handle() = default;
  Handle(hid_t id, herr_t (*closer)(hid_t)) : id_(id), closer_(closer) {}
  ~Handle() { reset(); }
  Handle(Handle&& o) noexcept : id_(o.id_), closer_(o.closer_) { o.id_ = -1; }
  Handle& operator=(Handle&& o) noexcept {
    if (this != &o) {
      reset();
      id_ = o.id_;
      closer_ = o.closer_;
      o.id_ = -1;
    }
    return *this;
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  hid_t id() const { return id_; }
  bool valid() const { return id_ >= 0; }
  void reset() {
    if (id_ >= 0 && closer_) closer_(id_);
    id_ = -1;
  }

 private:
  hid_t id_ = -1;
  herr_t (*closer_)(hid_t) = nullptr;
};

/// Silences HDF5's automatic error printing for the lifetime of the process
/// (errors are turned into exceptions with our own messages).
void quiet();

Handle create_file(const std::string& path);      ///< truncates; throws InputError
Handle open_file(const std::string& path, bool writable);  ///< throws InputError naming the file
Handle create_group(hid_t parent, const std::string& name);
Handle open_group(hid_t parent, const std::string& name);
bool exists(hid_t parent, const std::string& name);
std::vector<std::string> children(hid_t group);   ///< names of the members, in creation/name order

/// Datasets of doubles / int64 / strings with an arbitrary shape (row-major).
void write_doubles(hid_t parent, const std::string& name, const std::vector<hsize_t>& shape, const double* data);
void write_int64(hid_t parent, const std::string& name, const std::vector<hsize_t>& shape, const std::int64_t* data);
void write_strings(hid_t parent, const std::string& name, const std::vector<std::string>& values);
std::vector<double> read_doubles(hid_t parent, const std::string& name, std::vector<hsize_t>* shape = nullptr);
std::vector<std::int64_t> read_int64(hid_t parent, const std::string& name, std::vector<hsize_t>* shape = nullptr);
std::vector<std::string> read_strings(hid_t parent, const std::string& name);

/// Attributes on a group or file.
void set_attr(hid_t obj, const std::string& name, const std::string& value);
void set_attr(hid_t obj, const std::string& name, double value);
void set_attr(hid_t obj, const std::string& name, std::int64_t value);
void set_attr(hid_t obj, const std::string& name, const std::vector<std::int64_t>& values);
bool has_attr(hid_t obj, const std::string& name);
std::string get_attr_string(hid_t obj, const std::string& name);
double get_attr_double(hid_t obj, const std::string& name);
std::int64_t get_attr_int(hid_t obj, const std::string& name);
std::vector<std::int64_t> get_attr_ints(hid_t obj, const std::string& name);

}  // namespace ek::h5
