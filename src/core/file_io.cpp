#include "core/file_io.hpp"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <fmt/format.h>
#include <fstream>
#include <mutex>
#include <sstream>
#include <system_error>
#include <vector>

#include "core/errors.hpp"
#include "core/limits.hpp"
#include "core/text_parse.hpp"

namespace freestand::core {

std::string read_text_file(const std::filesystem::path& path) {
    const auto too_large = [&path](const std::string& how_large) {
        return InputError(SourceLocation{path.string(), 0, ""},
                          fmt::format("{}; an input file is limited to {:.0f} bytes (512 MiB; "
                                      "README, Limits)",
                                      how_large, limits::max_input_bytes));
    };
    std::error_code ec;
    const auto type = std::filesystem::status(path, ec).type();
    if (type == std::filesystem::file_type::directory)
        throw IoError(path.string() + ": is a folder; expected a file");
    if (type == std::filesystem::file_type::regular) {
        const auto bytes = static_cast<double>(std::filesystem::file_size(path, ec));
        if (!ec && bytes > limits::max_input_bytes)
            throw too_large(fmt::format("{:.0f} bytes", bytes));
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) throw IoError(path.string() + ": cannot open file for reading");
    // A device or a pipe has no size to check first (/dev/zero never ends): the limit is
    // checked as it is read.
    const auto limit = static_cast<std::size_t>(limits::max_input_bytes);
    std::string text;
    std::vector<char> chunk(std::size_t{1} << 20);
    while (in) {
        in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
        text.append(chunk.data(), static_cast<std::size_t>(in.gcount()));
        if (text.size() > limit) throw too_large(fmt::format("does not end within {} bytes", limit));
    }
    if (in.bad()) throw IoError(path.string() + ": read failed");
    return text;
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

bool is_input_file(const std::filesystem::path& path) { return is_input(path); }

std::string read_input_file(const std::filesystem::path& path) {
    std::string text = read_text_file(path);
    const std::lock_guard<std::mutex> lock(inputs_mutex);
    inputs_read().push_back(path);
    return text;
}

namespace {

// A write beyond the file-size limit (RLIMIT_FSIZE, ulimit -f) raises SIGXFSZ, whose default
// action ends the process before it can remove its temporary file. Ignored, the write fails
// with EFBIG instead (POSIX write()), which is an IoError like any other failed write. A handler
// the embedding process installed (Python's, say) is left as it is.
void let_file_size_limit_fail_writes() {
    static const bool done = [] {
        struct sigaction current {};
        if (::sigaction(SIGXFSZ, nullptr, &current) == 0 && current.sa_handler == SIG_DFL)
            ::signal(SIGXFSZ, SIG_IGN);
        return true;
    }();
    (void)done;
}

std::string write_failure(int err) {
    std::string out = std::string("write failed: ") + std::strerror(err);
    if (err == EFBIG) out += " (the file-size limit, ulimit -f, or the file system's largest file)";
    return out;
}

}  // namespace

void write_new_file(const std::filesystem::path& path, std::string_view contents) {
    let_file_size_limit_fail_writes();
    const int fd =
        ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (fd < 0) throw IoError(path.string() + ": cannot create: " + std::strerror(errno));
    std::size_t done = 0;
    while (done < contents.size()) {
        const ssize_t n = ::write(fd, contents.data() + done, contents.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            const int err = errno;
            ::close(fd);
            throw IoError(path.string() + ": " + write_failure(n < 0 ? err : EIO));
        }
        done += static_cast<std::size_t>(n);
    }
    if (::close(fd) != 0) throw IoError(path.string() + ": " + write_failure(errno));
}

namespace {

// The temporaries write_file_atomic names "<file>.freestand-tmp-<pid>-<n>": one whose process
// has died was left by a killed run and is removed.
void remove_dead_temporaries(const std::filesystem::path& path) {
    namespace fs = std::filesystem;
    const std::string prefix = path.filename().string() + ".freestand-tmp-";
    const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(folder, ec))
        if (left_by_dead_process(entry.path().filename().string(), prefix)) fs::remove(entry.path(), ec);
}

}  // namespace

bool left_by_dead_process(std::string_view name, std::string_view prefix) {
    if (name.substr(0, prefix.size()) != prefix) return false;
    const std::string_view rest = name.substr(prefix.size());
    const std::size_t dash = rest.find('-');
    pid_t pid = 0;
    if (dash == std::string_view::npos || dash > 9 ||
        !text::parse_integer(rest.substr(0, dash), pid))
        return false;
    // kill(pid, 0) sends nothing: ESRCH says no process has the id (EPERM: one does).
    return pid > 0 && pid != ::getpid() && ::kill(pid, 0) != 0 && errno == ESRCH;
}

void write_file_atomic(const std::filesystem::path& path, std::string_view contents) {
    namespace fs = std::filesystem;
    if (is_input(path))
        throw IoError(path.string() + ": refusing to overwrite an input file of this run");
    const fs::file_type existing = fs::symlink_status(path).type();
    if (existing != fs::file_type::not_found && existing != fs::file_type::regular) {
        throw IoError(path.string() + ": exists and is not a regular file (" +
                      (existing == fs::file_type::symlink ? "a symbolic link" : "a device, FIFO or folder") +
                      "); refusing to replace it");
    }
    std::error_code ec;
    if (path.has_parent_path()) {
        fs::create_directories(path.parent_path(), ec);
        if (ec) throw IoError(path.parent_path().string() + ": cannot create directory: " + ec.message());
    }
    remove_dead_temporaries(path);
    static std::atomic<unsigned> counter{0};
    fs::path tmp = path;
    tmp += fmt::format(".freestand-tmp-{}-{}", ::getpid(), counter++);
    try {
        write_new_file(tmp, contents);
    } catch (const IoError& e) {
        // The temporary's name means nothing to the user: the error names the file.
        fs::remove(tmp, ec);
        throw IoError(path.string() + std::string(e.what()).substr(tmp.string().size()));
    }
    fs::rename(tmp, path, ec);
    if (ec) {
        fs::remove(tmp, ec);
        throw IoError(path.string() + ": cannot move temporary file into place");
    }
}

}  // namespace freestand::core
