#pragma once
// Test helper: copies a data-set file into the layout of files written before
// data sets carried a checksum (no user block, HDF5 signature at byte 0):
// the root attributes, /knot_names and /knots, through the HDF5 C API, so
// that the reader's handling of older files can be tested on fresh files.
#include <hdf5.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace ek::fixtures {

namespace detail {

inline herr_t copy_attribute(hid_t src, const char* name, const H5A_info_t*, void* dst_ptr) {
  const hid_t dst = *static_cast<hid_t*>(dst_ptr);
  const hid_t a = H5Aopen(src, name, H5P_DEFAULT);
  const hid_t type = H5Aget_type(a), space = H5Aget_space(a);
  const hssize_t count = H5Sget_simple_extent_npoints(space);
  std::vector<unsigned char> buf(static_cast<size_t>(count) * H5Tget_size(type) + 1);
  herr_t status = H5Aread(a, type, buf.data());
  const hid_t b = H5Acreate2(dst, name, type, space, H5P_DEFAULT, H5P_DEFAULT);
  if (status >= 0) status = H5Awrite(b, type, buf.data());
  if (H5Tis_variable_str(type) > 0) H5Dvlen_reclaim(type, space, H5P_DEFAULT, buf.data());
  H5Aclose(b);
  H5Sclose(space);
  H5Tclose(type);
  H5Aclose(a);
  return status;
}

}  // namespace detail

inline void write_unsealed_copy(const std::string& from, const std::string& to) {
  const hid_t src = H5Fopen(from.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const hid_t dst = H5Fcreate(to.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (src < 0 || dst < 0) throw std::runtime_error("write_unsealed_copy: cannot open " + from + " or " + to);
  hid_t dst_root = dst;
  herr_t status = H5Aiterate2(src, H5_INDEX_NAME, H5_ITER_INC, nullptr, detail::copy_attribute, &dst_root);
  for (const char* name : {"knots", "knot_names"})
    if (status >= 0) status = H5Ocopy(src, name, dst, name, H5P_DEFAULT, H5P_DEFAULT);
  H5Fclose(src);
  H5Fclose(dst);
  if (status < 0) throw std::runtime_error("write_unsealed_copy: HDF5 could not copy " + from);
}

}  // namespace ek::fixtures
