#pragma once
// The sensor model as the attributes of an HDF5 group (/model of a mission or a
// result): one float64 per numeric field and one string per choice
// (solver/mission/sensor_model.h lists both).

#include <cstdint>
#include <string>

#include "io/hdf5/h5_file.h"
#include "solver/mission/sensor_model.h"

namespace gesmi::io {

void write_model_attributes(H5File& file, const std::string& group, const SensorModel& model);
/// Reads the model; fields and choices introduced after `file_version` may be absent
/// (they keep their defaults). FormatError naming the file and the attribute otherwise.
SensorModel read_model_attributes(const H5File& file, const std::string& group, std::int64_t file_version);

}  // namespace gesmi::io
