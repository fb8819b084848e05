#include "core/content_store.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <thread>
#include <vector>

#include "core/bytes.hpp"
#include "core/errors.hpp"
#include "core/printable.hpp"
#include "core/sha256.hpp"
#include "core/text_parse.hpp"

namespace freestand::core {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view magic = "freestand-cache 1\n";
constexpr std::string_view entry_suffix = ".entry";
constexpr std::string_view temp_prefix = ".tmp-";
constexpr std::size_t key_length = 64;
// A writer killed between its write and its rename leaves its temporary file; one older than
// this is no writer's any more.
constexpr auto stale_temp_age = std::chrono::hours(1);

bool valid_key(std::string_view key) {
    return key.size() == key_length && std::all_of(key.begin(), key.end(), [](char c) {
               return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f');
           });
}

bool is_entry_name(const std::string& name) {
    return name.size() == key_length + entry_suffix.size() &&
           name.ends_with(entry_suffix) &&
           valid_key(std::string_view(name).substr(0, key_length));
}

bool is_temp_name(const std::string& name) { return name.starts_with(temp_prefix); }

// The entry file: magic, key, then the content with its length and its digest.
std::string encode_entry(std::string_view key, std::string_view content) {
    ByteWriter w;
    w.text(key);
    w.text(content);
    w.text(sha256_hex(content));
    return std::string(magic) + w.take();
}

std::optional<std::string> decode_entry(std::string_view key, std::string_view file) {
    if (!file.starts_with(magic)) return std::nullopt;
    ByteReader r(file.substr(magic.size()));
    const std::string stored_key = r.text();
    std::string content = r.text();
    const std::string digest = r.text();
    if (r.failed() || !r.at_end() || stored_key != key || digest != sha256_hex(content))
        return std::nullopt;
    return content;
}

// Reads a regular file whole, refusing anything else (a symlink, a folder, a device) and any
// file above max_bytes.
std::optional<std::string> read_regular(const fs::path& path, std::uint64_t max_bytes) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
    if (fd < 0) return std::nullopt;
    struct stat st {};
    std::optional<std::string> out;
    if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) &&
        static_cast<std::uint64_t>(st.st_size) <= max_bytes) {
        std::string bytes(static_cast<std::size_t>(st.st_size), '\0');
        std::size_t got = 0;
        while (got < bytes.size()) {
            const ssize_t n = ::read(fd, bytes.data() + got, bytes.size() - got);
            if (n <= 0) break;
            got += static_cast<std::size_t>(n);
        }
        if (got == bytes.size()) out = std::move(bytes);
    }
    ::close(fd);
    return out;
}

// A name no other writer in any process uses at the same time.
std::string temp_name() {
    static std::atomic<std::uint64_t> counter{0};
    const auto thread = std::hash<std::thread::id>{}(std::this_thread::get_id());
    return fmt::format("{}{}-{:x}-{}", temp_prefix, ::getpid(), thread, counter++);
}

bool write_all(int fd, std::string_view bytes) {
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        done += static_cast<std::size_t>(n);
    }
    return true;
}

struct Listed {
    fs::path path;
    std::uint64_t bytes = 0;
    fs::file_time_type used;
};

// The store's entries (regular files of its naming only).
std::vector<Listed> list_entries(const fs::path& dir) {
    std::vector<Listed> out;
    std::error_code ec;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        std::error_code e2;
        if (!is_entry_name(name) || !it->is_regular_file(e2) || it->is_symlink(e2)) continue;
        const auto size = it->file_size(e2);
        const auto time = it->last_write_time(e2);
        if (!e2) out.push_back({it->path(), size, time});
    }
    return out;
}

}  // namespace

std::optional<fs::path> default_cache_dir() {
    for (const auto& [var, sub] : {std::pair{"XDG_CACHE_HOME", "freestand"},
                                   std::pair{"HOME", ".cache/freestand"}}) {
        const char* v = std::getenv(var);
        if (v != nullptr && v[0] == '/') return fs::path(v) / sub;
    }
    return std::nullopt;
}

std::uint64_t cache_max_bytes_from_environment() {
    const char* v = std::getenv("FREESTAND_CACHE_MAX_MB");
    if (v == nullptr) return default_cache_max_bytes;
    const std::string text(v);
    std::uint64_t mb = 0;
    const bool digits = text.size() <= 8 && text::parse_integer(text, mb);
    if (!digits || mb < 1 || mb > 10'000'000)
        throw InputError(SourceLocation{"", 0, "FREESTAND_CACHE_MAX_MB"},
                         fmt::format("'{}'; expected a whole number of MiB from 1 to 10000000",
                                     printable(text)));
    return mb * 1024 * 1024;
}

ContentStore::ContentStore(fs::path dir, std::uint64_t max_bytes)
    : dir_(std::move(dir)), max_bytes_(max_bytes) {}

fs::path ContentStore::entry_path(std::string_view key) const {
    return dir_ / (std::string(key) + std::string(entry_suffix));
}

std::optional<std::string> ContentStore::get(std::string_view key) const {
    if (!valid_key(key)) return std::nullopt;
    const fs::path path = entry_path(key);
    const std::optional<std::string> file = read_regular(path, max_bytes_);
    if (!file) return std::nullopt;
    std::optional<std::string> content = decode_entry(key, *file);
    std::error_code ec;
    if (!content) {
        // Damaged (cut short by a full disk, edited): recomputed by the caller, rewritten then.
        fs::remove(path, ec);
        return std::nullopt;
    }
    fs::last_write_time(path, fs::file_time_type::clock::now(), ec);  // recently used
    return content;
}

bool ContentStore::put(std::string_view key, std::string_view content, std::string* why) const {
    const auto fail = [&](const std::string& reason) {
        if (why != nullptr) *why = reason;
        const std::lock_guard<std::mutex> guard(failure_lock_);
        if (first_failure_.empty()) first_failure_ = reason;
        return false;
    };
    if (!valid_key(key)) return fail("invalid key");
    std::error_code ec;
    fs::create_directories(dir_, ec);
    if (ec) return fail(fmt::format("cannot create {}: {}", dir_.string(), ec.message()));
    const fs::path temp = dir_ / temp_name();
    const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd < 0) return fail(fmt::format("cannot write in {}: {}", dir_.string(), std::strerror(errno)));
    const bool written = write_all(fd, encode_entry(key, content));
    const int saved = errno;
    const bool closed = ::close(fd) == 0;
    if (!written || !closed) {
        fs::remove(temp, ec);
        return fail(fmt::format("cannot write in {}: {}", dir_.string(), std::strerror(saved)));
    }
    // rename() replaces the name atomically (a symlink placed there is replaced, never
    // followed): readers see the old entry or this one, whole.
    if (::rename(temp.c_str(), entry_path(key).c_str()) != 0) {
        const int err = errno;
        fs::remove(temp, ec);
        return fail(fmt::format("cannot write in {}: {}", dir_.string(), std::strerror(err)));
    }
    return true;
}

std::string ContentStore::first_failure() const {
    const std::lock_guard<std::mutex> guard(failure_lock_);
    return first_failure_;
}

std::size_t ContentStore::prune() const {
    std::size_t removed = 0;
    std::error_code ec;
    const auto now = fs::file_time_type::clock::now();
    for (fs::directory_iterator it(dir_, ec), end; !ec && it != end; it.increment(ec)) {
        std::error_code e2;
        if (is_temp_name(it->path().filename().string()) &&
            now - it->last_write_time(e2) > stale_temp_age && !e2 && fs::remove(it->path(), e2))
            ++removed;
    }
    std::vector<Listed> entries = list_entries(dir_);
    std::uint64_t total = 0;
    for (const Listed& e : entries) total += e.bytes;
    if (total <= max_bytes_) return removed;
    std::sort(entries.begin(), entries.end(),
              [](const Listed& a, const Listed& b) { return a.used < b.used; });
    for (const Listed& e : entries) {
        if (total <= max_bytes_) break;
        std::error_code e2;
        if (fs::remove(e.path, e2)) ++removed;
        total -= e.bytes;  // gone either way: removed here or by another process
    }
    return removed;
}

std::size_t ContentStore::clear() const {
    std::size_t removed = 0;
    std::error_code ec;
    std::vector<fs::path> mine;
    for (fs::directory_iterator it(dir_, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        std::error_code e2;
        if ((is_entry_name(name) || is_temp_name(name)) && !it->is_symlink(e2) &&
            it->is_regular_file(e2))
            mine.push_back(it->path());
    }
    for (const fs::path& p : mine) {
        std::error_code e2;
        if (fs::remove(p, e2)) ++removed;
    }
    return removed;
}

StoreInfo ContentStore::info() const {
    StoreInfo out;
    out.dir = dir_;
    out.max_bytes = max_bytes_;
    for (const Listed& e : list_entries(dir_)) {
        ++out.entries;
        out.bytes += e.bytes;
    }
    return out;
}

}  // namespace freestand::core
