#pragma once
/// File reading and atomic writing shared by every stage.
#include <filesystem>
#include <string>
#include <string_view>

namespace freestand::core {

/// Reads a whole file; throws IoError naming the path if it cannot.
std::string read_text_file(const std::filesystem::path& path);

/// Reads a whole user input (a record, a case file, a target spectrum) like read_text_file and
/// remembers it: write_file_atomic refuses to replace it for the rest of the process, so an
/// output path that names an input (simulate --out on the --motion file, say) is an error
/// instead of a lost input.
std::string read_input_file(const std::filesystem::path& path);

/// Writes text to path atomically: a temporary file beside it, then rename, so a reader never
/// sees a half-written file. Creates missing parent directories. Throws IoError on failure, and
/// before writing anything if path is a file read by read_input_file.
void write_file_atomic(const std::filesystem::path& path, std::string_view contents);

}  // namespace freestand::core
