#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/file_io.hpp"
#include "core/printable.hpp"
#include "core/readers.hpp"
#include "core/text_parse.hpp"
#include "core/units.hpp"

namespace freestand::core {

Record read_record(const std::filesystem::path& path, double unit_g_mps2) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        throw IoError(path.string() + ": is a folder; expected a record file");
    const std::string ext = text::lower(path.extension().string());
    if (ext == ".at2") return read_at2(path, unit_g_mps2);
    if (ext == ".v2" || ext == ".v2c") return read_cosmos_v2(path, unit_g_mps2);
    if (ext == ".csv") return read_csv(path, unit_g_mps2);
    throw InputError({path.string(), 0, "extension"},
                     fmt::format("unknown record format \"{}\"; expected .AT2 (PEER NGA), .V2 (COSMOS) or .csv",
                                 path.extension().string()));
}

namespace {

/// A label on one comment line: line breaks would start a data line, and other control
/// characters (ESC, BEL from a file name) are shown as \xNN, so none reaches the file raw.
std::string one_line(const std::string& label) {
    std::string s = printable(label);
    for (char& c : s)
        if (c == '\n' || c == '\t') c = ' ';
    return s;
}

}  // namespace

std::string csv_g_text(const Record& record) {
    validate(record);
    std::string out;
    out.reserve(40 * record.size() + 200);
    out += fmt::format("# name: {}\n# source: {}\n# component: {}\n", one_line(record.name),
                       one_line(record.source), one_line(record.component));
    // "{}" prints the shortest text that parses back to the same double (fmt, Ryu-like).
    out += fmt::format("# dt_s: {}\n", record.dt_s);
    out += "time_s,accel_g\n";
    for (std::size_t i = 0; i < record.size(); ++i)
        fmt::format_to(std::back_inserter(out), "{},{}\n", record.time_s(i), units::mps2_to_g(record.accel_mps2[i]));
    return out;
}

void write_csv_g(const Record& record, const std::filesystem::path& path) {
    write_file_atomic(path, csv_g_text(record));
}

}  // namespace freestand::core
