#include "core/publish.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <fmt/format.h>
#include <fstream>
#include <set>

#include "core/errors.hpp"
#include "core/file_io.hpp"

namespace freestand::core {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void fail(const fs::path& p, const std::string& what) {
    throw IoError(p.string() + ": " + what);
}

// Prefix of this folder's staging and renamed-aside siblings: ".<name>.freestand-".
std::string sibling_prefix(const fs::path& dir) {
    return fmt::format(".{}.freestand-", dir.filename().string());
}

bool owned(const fs::path& dir) {
    std::error_code ec;
    if (fs::is_empty(dir, ec) && !ec) return true;
    return fs::symlink_status(dir / run_marker).type() == fs::file_type::regular;
}

// What this publish may replace: nothing that is not a real folder of freestand's, no entry
// that is not a regular file, no input of this run.
void check_target(const fs::path& dir, const std::set<std::string>& names) {
    const fs::file_status st = fs::symlink_status(dir);
    if (st.type() == fs::file_type::not_found) return;
    if (st.type() == fs::file_type::symlink)
        fail(dir, "is a symbolic link; refusing to replace it (give the folder it points to)");
    if (st.type() != fs::file_type::directory)
        fail(dir, "exists and is not a folder; refusing to replace it");
    if (!owned(dir)) {
        fail(dir, fmt::format("exists, is not empty and was not written by freestand (no {}); "
                              "choose a new or empty folder",
                              run_marker));
    }
    for (const auto& entry : fs::directory_iterator(dir)) {
        if (entry.symlink_status().type() != fs::file_type::regular) {
            fail(entry.path(), "is not a regular file; refusing to replace its folder");
        }
        if (names.count(entry.path().filename().string()) && is_input_file(entry.path()))
            fail(entry.path(), "refusing to overwrite an input file of this run");
    }
}

fs::path fresh_sibling(const fs::path& dir, const char* kind) {
    static std::atomic<unsigned> counter{0};
    return dir.parent_path() / fmt::format("{}{}-{}-{}", sibling_prefix(dir), kind, ::getpid(),
                                           counter++);
}

constexpr const char* marker_heading =
    "Written by freestand. The next run into this folder replaces it as a whole; files added "
    "by hand are kept. Files of this run:\n";

std::string marker_text(const std::set<std::string>& names) {
    std::string out = marker_heading;
    for (const std::string& n : names) out += n + "\n";
    return out;
}

// The files the previous run wrote (its marker's list): they are replaced, not carried over.
std::set<std::string> previous_run_files(const fs::path& dir) {
    std::set<std::string> out;
    std::error_code ec;
    if (fs::symlink_status(dir / run_marker, ec).type() != fs::file_type::regular) return out;
    const std::string text = read_text_file(dir / run_marker);
    std::size_t start = text.find('\n');
    while (start != std::string::npos && start + 1 < text.size()) {
        const std::size_t end = text.find('\n', start + 1);
        out.insert(text.substr(start + 1, end == std::string::npos ? end : end - start - 1));
        start = end;
    }
    return out;
}

// The staging folder with the run's files and the marker listing them.
fs::path stage(const fs::path& dir, const std::vector<OutputFile>& files,
               const std::set<std::string>& names) {
    const fs::path staging = fresh_sibling(dir, "stage");
    std::error_code ec;
    if (!fs::create_directory(staging, ec) || ec)
        fail(staging, "cannot create staging folder: " + ec.message());
    try {
        for (const OutputFile& f : files) write_new_file(staging / f.name, f.contents);
        write_new_file(staging / run_marker, marker_text(names));
    } catch (...) {
        fs::remove_all(staging, ec);
        throw;
    }
    return staging;
}

// Hard links in the staging folder to the files of the current folder that neither this run
// nor the previous one wrote (added by hand). Under the lock: the folder does not change.
void carry_over(const fs::path& dir, const fs::path& staging,
                const std::set<std::string>& names) {
    if (!fs::is_directory(fs::symlink_status(dir))) return;
    const std::set<std::string> previous = previous_run_files(dir);
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir)) {
        const std::string name = entry.path().filename().string();
        if (names.count(name) || previous.count(name) || name == run_marker) continue;
        fs::create_hard_link(entry.path(), staging / name, ec);
        if (ec) fail(entry.path(), "cannot carry over to the new run: " + ec.message());
    }
}

// Holds flock(LOCK_EX) on a folder for its lifetime.
class FolderLock {
  public:
    explicit FolderLock(const fs::path& folder)
        : fd_(::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC)) {
        if (fd_ < 0) fail(folder, std::string("cannot open to lock: ") + std::strerror(errno));
        while (::flock(fd_, LOCK_EX) != 0) {
            if (errno != EINTR) {
                ::close(fd_);
                fail(folder, std::string("cannot lock: ") + std::strerror(errno));
            }
        }
    }
    ~FolderLock() { ::close(fd_); }
    FolderLock(const FolderLock&) = delete;
    FolderLock& operator=(const FolderLock&) = delete;

  private:
    int fd_;
};

// Left-overs of killed runs: staging and renamed-aside folders exist only while a publish
// holds the lock, so under the lock any that remain belong to a run that died.
void clean_leftovers(const fs::path& dir) {
    const std::string prefix = sibling_prefix(dir);
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir.parent_path(), ec)) {
        const std::string name = entry.path().filename().string();
        if (name.rfind(prefix + "stage-", 0) == 0 || name.rfind(prefix + "old-", 0) == 0)
            fs::remove_all(entry.path(), ec);
    }
}

}  // namespace

void publish_folder(const fs::path& dir_given, const std::vector<OutputFile>& files) {
    const fs::path dir = fs::absolute(dir_given).lexically_normal();
    if (!dir.has_filename() || dir == dir.root_path())
        fail(dir_given, "cannot publish into the root or a path ending in '/..'");
    std::set<std::string> names;
    for (const OutputFile& f : files) {
        if (f.name.empty() || f.name.find('/') != std::string::npos || f.name == run_marker)
            throw std::invalid_argument("publish_folder: bad file name " + f.name);
        names.insert(f.name);
    }
    // Everything below runs under the parent's lock, so no other publish changes the folder
    // between the checks and the swap. Creating a missing parent cannot hide a refusal: with
    // no parent there is no folder to refuse.
    std::error_code ec;
    fs::create_directories(dir.parent_path(), ec);
    if (ec) fail(dir.parent_path(), "cannot create folder: " + ec.message());
    const FolderLock lock(dir.parent_path());
    clean_leftovers(dir);
    check_target(dir, names);
    const fs::path staging = stage(dir, files, names);
    try {
        carry_over(dir, staging, names);
    } catch (...) {
        fs::remove_all(staging, ec);
        throw;
    }
    const fs::path aside = fresh_sibling(dir, "old");
    const bool had_old = fs::exists(fs::symlink_status(dir));
    if (had_old) {
        fs::rename(dir, aside, ec);
        if (ec) {
            fs::remove_all(staging, ec);
            fail(dir, "cannot move the previous run aside: " + ec.message());
        }
    }
    fs::rename(staging, dir, ec);
    if (ec) {
        const std::string why = ec.message();
        if (had_old) fs::rename(aside, dir, ec);
        fs::remove_all(staging, ec);
        fail(dir, "cannot move the new run into place: " + why);
    }
    if (had_old) fs::remove_all(aside, ec);
}

}  // namespace freestand::core
