#pragma once
// Private: the data set's parameters (metadata_fields()) as root attributes
// of an HDF5 file, shared by the data-set file and the ledger.
#include <hdf5.h>

#include <functional>
#include <string>

#include "ek/dataset/dataset_file.hpp"
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

/// A knot group's header (KnotHeader): its attributes name, crossing_number,
/// bridge_index, braid_index, alexander, samples_used, adaptive, complete,
/// a link's components, conway and linking_numbers, and its score_history.
void write_knot_header(hid_t group, const KnotHeader& header);

/// The same read back; `damaged(what)` (which throws) for a name that is not
/// the group's, a score history that is no list, or link fields that do not
/// fit (fewer than 2 components, one of fewer than 4 or more than 2^24
/// vertices, linking numbers not m by m).
KnotHeader read_knot_header(hid_t group, const std::string& name,
                            const std::function<void(const std::string&)>& damaged);

}  // namespace ek::detail
