#pragma once
// Private: the data set's parameters (metadata_fields()) as root attributes
// of an HDF5 file, shared by the data-set file and the ledger.
#include <hdf5.h>

#include <string>

#include "ek/dataset/metadata.hpp"

namespace ek::detail {

/// One attribute per field of metadata_fields(); an empty field is left out
/// (not recorded), which only the fields that older files may lack allow
/// (std::invalid_argument otherwise).
void write_parameters(hid_t file, const DatasetMetadata& meta);

/// The fields as metadata_fields() reads them: a field without its
/// attribute is its documented value, "not recorded", or an InputError
/// naming `path` when every file has it.
DatasetMetadata read_parameters(hid_t file, const std::string& path);

}  // namespace ek::detail
