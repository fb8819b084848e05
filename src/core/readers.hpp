#pragma once
/// Readers and writers of acceleration records. Every reader requires the file to state its
/// units and throws InputError naming file, line and what was expected on any defect.
#include <filesystem>
#include <string>

#include "core/record.hpp"

namespace freestand::core {

/// PEER NGA .AT2: four header lines (the third states "UNITS OF G", the fourth
/// "NPTS= n, DT= dt SEC"), then values in g. NPTS must equal the number of values.
Record read_at2(const std::filesystem::path& path);

/// COSMOS V2 processed record (acceleration in cm/s^2 or g as the header states).
Record read_cosmos_v2(const std::filesystem::path& path);

/// CSV: header "time_s,accel_<unit>" with two columns, or one column "accel_<unit>" preceded
/// by a "# dt_s: <value>" line. <unit> is one of g, mps2, cmps2. '#' lines are comments.
Record read_csv(const std::filesystem::path& path);

/// Picks the reader from the extension: .AT2/.at2, .V2/.v2, .csv. Throws InputError otherwise.
Record read_record(const std::filesystem::path& path);

/// Writes "time_s,accel_g" CSV (atomically), with '#' comment lines for name, source, component.
void write_csv_g(const Record& record, const std::filesystem::path& path);

}  // namespace freestand::core
