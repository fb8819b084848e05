#include "core/file_io.hpp"

#include <fstream>
#include <sstream>
#include <system_error>

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

void write_file_atomic(const std::filesystem::path& path, std::string_view contents) {
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
