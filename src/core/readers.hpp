#pragma once
/// Readers and writers of acceleration records. Every reader requires the file to state its
/// units and throws InputError naming file, line and what was expected on any defect. Values
/// in g are converted with the unit g of size unit_g_mps2 (a case's site.g_mps2; the thesis's
/// 9.81 by default; docs/methods.md, Conventions).
#include <filesystem>
#include <string>

#include "core/limits.hpp"
#include "core/record.hpp"
#include "core/units.hpp"

namespace freestand::core {

/// PEER NGA .AT2: four header lines (the third states "UNITS OF G", the fourth
/// "NPTS= n, DT= dt SEC"), then values in g. NPTS must equal the number of values.
Record read_at2(const std::filesystem::path& path, double unit_g_mps2 = units::g_mps2);

/// COSMOS Strong Motion Data Format v1.20 processed record (line 1 "Corrected acceleration ...
/// (Format v01.20 with N text lines)"); the first acceleration channel is read. Units from the
/// data header ("units=cm/sec2 (04)" or "units=g (02)") and/or integer-header #3, which must
/// agree; dt from real-header #62 (ms), else #34 (s). The data header's point count must equal
/// the number of values. Also used for .V2C files.
Record read_cosmos_v2(const std::filesystem::path& path, double unit_g_mps2 = units::g_mps2);

/// CSV: a header naming a time and an acceleration column (either order), or one acceleration
/// column preceded by a "# dt_s: <value>" line. Names carry their unit ("time_s", "t (ms)",
/// "accel_g", "Acceleration [m/s^2]", "a_gal"; the list in csv_columns.hpp and docs/methods.md);
/// an unknown name is an InputError listing the accepted ones. The separator is the header's:
/// ';', else a tab, else ','; with ';' or a tab a number may use a decimal comma. A UTF-8 BOM
/// and CRLF line ends are accepted. '#' lines are comments; blank lines are skipped. Time steps
/// must agree to 1e-6 relative; dt is their mean, and the first row becomes t = 0. A second
/// "# dt_s" line must state the same step. Rows are counted as they are read: the first beyond
/// limits::max_samples is an InputError at its line. Optional
/// "# name:" and "# component:" comments set those labels.
Record read_csv(const std::filesystem::path& path, double unit_g_mps2 = units::g_mps2);

/// The same readers on text already in memory; file_label names the file in messages (and
/// its stem names the record). The fuzz targets drive these.
Record parse_at2(const std::string& text, const std::string& file_label,
                 double unit_g_mps2 = units::g_mps2);
/// A COSMOS file is refused at line max_lines + 1 as soon as it is that long (the default: one
/// line per sample of the limit, and room for the headers and comments), and its data block at
/// the first line that passes the header's NPTS.
Record parse_cosmos_v2(const std::string& text, const std::string& file_label,
                       std::size_t max_lines = limits::max_cosmos_lines,
                       double unit_g_mps2 = units::g_mps2);
/// parse_csv refuses the first row beyond max_samples (the README's limit; a test passes a
/// small one) without reading further.
Record parse_csv(const std::string& text, const std::string& file_label,
                 double max_samples = limits::max_samples, double unit_g_mps2 = units::g_mps2);

/// Picks the reader from the extension, ignoring case: .AT2, .V2 or .V2C, .csv. Throws
/// InputError (field "extension") otherwise.
Record read_record(const std::filesystem::path& path, double unit_g_mps2 = units::g_mps2);

/// Writes "time_s,accel_g" CSV (atomically), with '#' comment lines for name, source, component
/// and dt_s. Numbers use the shortest text that parses back to the same double, so read_csv
/// returns the values to about 1 ulp. Throws InputError if the record fails core::validate.
void write_csv_g(const Record& record, const std::filesystem::path& path);

/// The text write_csv_g writes (for a caller that publishes it with other files).
std::string csv_g_text(const Record& record);

}  // namespace freestand::core
