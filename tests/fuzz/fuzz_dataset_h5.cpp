// The data-set reader (src/dataset: checksum header, HDF5, every knot group).
// The bytes are written to a file in the temporary folder, which
// DatasetReader opens; every knot it lists is read. A file without checksum
// is first read in a child process (dataset_file.cpp): failures of the HDF5
// library there are the file's, refused with an InputError; the child is
// given 3 s here instead of a minute.
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>

#include "child_read.hpp"
#include "ek/dataset/dataset_file.hpp"
#include "fuzz_common.hpp"

namespace {

std::string scratch_path() {
  const char* dir = std::getenv("TMPDIR");
  return std::string(dir && *dir ? dir : "/tmp") + "/ek-fuzz-dataset-" + std::to_string(::getpid()) + ".h5";
}

const std::string& path() {
  static const std::string p = scratch_path();
  return p;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  std::atexit([] { std::remove(path().c_str()); });
  ek::detail::set_child_read_limit(3.0, 0.0);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  {
    std::ofstream out(path(), std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    if (!out) ek::fuzz::check_failed("cannot write the scratch file", __FILE__, __LINE__);
  }
  ek::fuzz::expect_result_or_input_error([&] {
    ek::DatasetReader reader(path());
    for (const auto& name : reader.knot_names()) {
      if (!reader.has_knot(name)) continue;
      const ek::KnotEntry k = reader.read(name);
      EK_FUZZ_CHECK(k.name == name);
      EK_FUZZ_CHECK(k.attributes.rows() == static_cast<Eigen::Index>(k.equilibria.size()));
      for (const auto& run : k.runs) EK_FUZZ_CHECK(run.equilibrium < static_cast<int>(k.equilibria.size()));
    }
  });
  return 0;
}
