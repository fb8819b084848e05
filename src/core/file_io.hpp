#pragma once
/// File reading and atomic writing shared by every stage.
#include <filesystem>
#include <string>
#include <string_view>

namespace freestand::core {

/// Reads a whole file; throws IoError naming the path if it cannot.
std::string read_text_file(const std::filesystem::path& path);

/// Writes text to path atomically: a temporary file beside it, then rename, so a reader never
/// sees a half-written file. Creates missing parent directories. Throws IoError on failure.
void write_file_atomic(const std::filesystem::path& path, std::string_view contents);

}  // namespace freestand::core
