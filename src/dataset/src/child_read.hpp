#pragma once
// Private: the time a child process is given to read a data-set file that has
// no checksum (DatasetReader, dataset_file.cpp): `base` seconds plus
// `per_10_mb` seconds per 10 MB of file. Defaults: 60 and 1. The fuzz target
// shortens it so that a hang of the HDF5 library costs seconds, not minutes.
namespace ek::detail {

void set_child_read_limit(double base, double per_10_mb);

}  // namespace ek::detail
