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

/// True when path names a file read by read_input_file in this process.
bool is_input_file(const std::filesystem::path& path);

/// Creates path (which must not exist; a symlink is not followed) and writes contents to it.
/// Throws IoError naming the path.
void write_new_file(const std::filesystem::path& path, std::string_view contents);

/// Writes text to path atomically: a temporary file of a unique name beside it, then rename, so
/// a reader never sees a half-written file and concurrent writers do not share a temporary.
/// Creates missing parent directories and removes the temporaries of path whose process died.
/// A write stopped by the file-size limit (SIGXFSZ is ignored, so write() fails with EFBIG) is
/// an IoError naming path, like any failed write, and leaves no temporary. Throws IoError
/// before writing anything if path is a
/// file read by read_input_file, or exists and is not a regular file (a device, a FIFO, a
/// symlink, a folder: never replaced).
void write_file_atomic(const std::filesystem::path& path, std::string_view contents);

/// True when name is prefix followed by "<pid>-" and no process has that id: a file or folder
/// named for the process that made it, left by a run that died. A live process of that id (its
/// maker, or a reused id) and this process keep theirs.
bool left_by_dead_process(std::string_view name, std::string_view prefix);

}  // namespace freestand::core
