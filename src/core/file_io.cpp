#include "core/file_io.hpp"

#include <fstream>
#include <mutex>
#include <sstream>
#include <system_error>
#include <vector>

#include "core/errors.hpp"

namespace freestand::core {

std::string read_text_file(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw IoError(path.string() + ": cannot open file for reading");
    std::ostringstream buffer;
    buffer << in.rdbuf();
    if (in.bad()) throw IoError(path.string() + ": read failed");
    return buffer.str();
}

namespace {

// Files read as user inputs by this process (read_input_file).
std::mutex inputs_mutex;
std::vector<std::filesystem::path>& inputs_read() {
    static std::vector<std::filesystem::path> paths;
    return paths;
}

// The path as given and lexically normalised: "dir/new/../in.csv" names dir/in.csv once the
// writer has created dir/new, though it does not resolve before.
bool is_input(const std::filesystem::path& path) {
    const std::lock_guard<std::mutex> lock(inputs_mutex);
    for (const auto& candidate : {path, path.lexically_normal()}) {
        std::error_code ec;
        if (!std::filesystem::exists(candidate, ec)) continue;
        for (const auto& p : inputs_read())
            if (std::filesystem::equivalent(p, candidate, ec)) return true;
    }
    return false;
}

}  // namespace

std::string read_input_file(const std::filesystem::path& path) {
    std::string text = read_text_file(path);
    const std::lock_guard<std::mutex> lock(inputs_mutex);
    inputs_read().push_back(path);
    return text;
}

void write_file_atomic(const std::filesystem::path& path, std::string_view contents) {
    if (is_input(path))
        throw IoError(path.string() + ": refusing to overwrite an input file of this run");
    std::error_code ec;
    if (path.has_parent_path()) {
        std::filesystem::create_directories(path.parent_path(), ec);
        if (ec) throw IoError(path.parent_path().string() + ": cannot create directory: " + ec.message());
    }
    std::filesystem::path tmp = path;
    tmp += ".tmp";
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) throw IoError(tmp.string() + ": cannot open file for writing");
        out.write(contents.data(), static_cast<std::streamsize>(contents.size()));
        out.flush();
        if (!out) {
            out.close();
            std::filesystem::remove(tmp, ec);
            throw IoError(tmp.string() + ": write failed");
        }
    }
    std::filesystem::rename(tmp, path, ec);
    if (ec) {
        std::filesystem::remove(tmp, ec);
        throw IoError(path.string() + ": cannot move temporary file into place");
    }
}

}  // namespace freestand::core
