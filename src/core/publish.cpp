#include "core/publish.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <fmt/format.h>
#include <fstream>
#include <map>
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

// The files and sub-folders the previous run wrote (its marker's list, a folder's trailing '/'
// dropped): they are replaced, not carried over.
std::set<std::string> previous_run_files(const fs::path& dir) {
    std::set<std::string> out;
    std::error_code ec;
    if (fs::symlink_status(dir / run_marker, ec).type() != fs::file_type::regular) return out;
    const std::string text = read_text_file(dir / run_marker);
    std::size_t start = text.find('\n');
    while (start != std::string::npos && start + 1 < text.size()) {
        const std::size_t end = text.find('\n', start + 1);
        std::string name = text.substr(start + 1, end == std::string::npos ? end : end - start - 1);
        if (!name.empty() && name.back() == '/') name.pop_back();
        out.insert(std::move(name));
        start = end;
    }
    return out;
}

// This run's files: top-level names (files and sub-folders) and each sub-folder's files.
struct Layout {
    std::set<std::string> top;                                ///< every top-level name
    std::set<std::string> top_files;                          ///< top-level files only
    std::map<std::string, std::set<std::string>> sub_files;  ///< sub-folder -> its files

    const std::set<std::string>& files_of(const std::string& sub) const {
        static const std::set<std::string> none;
        const auto it = sub_files.find(sub);
        return it == sub_files.end() ? none : it->second;
    }
};

bool plain_name(const std::string& n) {
    return !n.empty() && n != "." && n != ".." && n != run_marker &&
           n.find('/') == std::string::npos;
}

Layout layout_of(const std::vector<OutputFile>& files) {
    Layout out;
    for (const OutputFile& f : files) {
        const std::size_t slash = f.name.find('/');
        const std::string head = f.name.substr(0, slash);
        const bool nested = slash != std::string::npos;
        if (!plain_name(head) || (nested && !plain_name(f.name.substr(slash + 1))))
            throw std::invalid_argument("publish_folder: bad file name " + f.name);
        if (nested ? out.top_files.count(head) > 0 : out.sub_files.count(head) > 0)
            throw std::invalid_argument("publish_folder: " + head + " is a file and a folder");
        out.top.insert(head);
        if (nested) {
            out.sub_files[head].insert(f.name.substr(slash + 1));
        } else {
            out.top_files.insert(head);
        }
    }
    return out;
}

// A sub-folder of the target that this run replaces (dropped = this run does not write it):
// freestand's own, regular files only, none an input of the run, and when dropped no file the
// previous run did not write (it would be lost with the folder).
void check_subfolder(const fs::path& sub, const std::set<std::string>& names, bool dropped) {
    if (!owned(sub)) {
        fail(sub, fmt::format("exists, is not empty and was not written by freestand (no {}); "
                              "move it out of the output folder",
                              run_marker));
    }
    const std::set<std::string> previous = dropped ? previous_run_files(sub)
                                                   : std::set<std::string>{};
    for (const auto& entry : fs::directory_iterator(sub)) {
        const std::string name = entry.path().filename().string();
        if (entry.symlink_status().type() != fs::file_type::regular)
            fail(entry.path(), "is not a regular file; refusing to replace its folder");
        if (names.count(name) && is_input_file(entry.path()))
            fail(entry.path(), "refusing to overwrite an input file of this run");
        if (dropped && name != run_marker && !previous.count(name)) {
            fail(entry.path(), "was added by hand to a sub-folder this run no longer writes; "
                               "move it out first");
        }
    }
}

// What this publish may replace: nothing that is not a real folder of freestand's, no entry
// that is neither a regular file nor a sub-folder of this run or the previous one, no input of
// this run.
// The folder itself: absent, or a real folder of freestand's. Returns whether it exists.
bool check_folder(const fs::path& dir) {
    const fs::file_status st = fs::symlink_status(dir);
    if (st.type() == fs::file_type::not_found) return false;
    if (st.type() == fs::file_type::symlink)
        fail(dir, "is a symbolic link; refusing to replace it (give the folder it points to)");
    if (st.type() != fs::file_type::directory)
        fail(dir, "exists and is not a folder; refusing to replace it");
    if (!owned(dir)) {
        fail(dir, fmt::format("exists, is not empty and was not written by freestand (no {}); "
                              "choose a new or empty folder",
                              run_marker));
    }
    return true;
}

void check_target(const fs::path& dir, const Layout& layout) {
    if (!check_folder(dir)) return;
    const std::set<std::string> previous = previous_run_files(dir);
    for (const auto& entry : fs::directory_iterator(dir)) {
        const std::string name = entry.path().filename().string();
        const fs::file_type type = entry.symlink_status().type();
        if (type == fs::file_type::directory &&
            (layout.sub_files.count(name) || previous.count(name))) {
            check_subfolder(entry.path(), layout.files_of(name), !layout.sub_files.count(name));
            continue;
        }
        if (type != fs::file_type::regular)
            fail(entry.path(), "is not a regular file; refusing to replace its folder");
        if (layout.top.count(name) && is_input_file(entry.path()))
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

std::string marker_text(const std::set<std::string>& files,
                        const std::set<std::string>& folders = {}) {
    std::string out = marker_heading;
    for (const std::string& n : files) out += n + "\n";
    for (const std::string& n : folders) out += n + "/\n";
    return out;
}

// The staging folder with the run's files and the markers listing them: each sub-folder has
// its own, so it reads as a folder published on its own.
fs::path stage(const fs::path& dir, const std::vector<OutputFile>& files, const Layout& layout) {
    const fs::path staging = fresh_sibling(dir, "stage");
    std::error_code ec;
    if (!fs::create_directory(staging, ec) || ec)
        fail(staging, "cannot create staging folder: " + ec.message());
    try {
        std::set<std::string> folders;
        for (const auto& [sub, names] : layout.sub_files) {
            if (!fs::create_directory(staging / sub, ec) || ec)
                fail(staging / sub, "cannot create folder: " + ec.message());
            write_new_file(staging / sub / run_marker, marker_text(names));
            folders.insert(sub);
        }
        for (const OutputFile& f : files) write_new_file(staging / f.name, f.contents);
        write_new_file(staging / run_marker, marker_text(layout.top_files, folders));
    } catch (...) {
        fs::remove_all(staging, ec);
        throw;
    }
    return staging;
}

// Hard links in staging to the files of folder that neither this run (names) nor the previous
// one wrote (added by hand). Sub-folders are not files: they are replaced or dropped whole.
void carry_over_files(const fs::path& folder, const fs::path& staging,
                      const std::set<std::string>& names) {
    if (!fs::is_directory(fs::symlink_status(folder))) return;
    const std::set<std::string> previous = previous_run_files(folder);
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(folder)) {
        const std::string name = entry.path().filename().string();
        if (entry.symlink_status().type() == fs::file_type::directory) continue;
        if (names.count(name) || previous.count(name) || name == run_marker) continue;
        fs::create_hard_link(entry.path(), staging / name, ec);
        if (ec) fail(entry.path(), "cannot carry over to the new run: " + ec.message());
    }
}

// The hand-added files of the folder and of each sub-folder this run writes again. Under the
// lock: the folder does not change.
void carry_over(const fs::path& dir, const fs::path& staging, const Layout& layout) {
    carry_over_files(dir, staging, layout.top);
    for (const auto& [sub, names] : layout.sub_files) carry_over_files(dir / sub, staging / sub, names);
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

void check_publish_target(const fs::path& dir) { check_folder(fs::absolute(dir).lexically_normal()); }

void publish_folder(const fs::path& dir_given, const std::vector<OutputFile>& files) {
    const fs::path dir = fs::absolute(dir_given).lexically_normal();
    if (!dir.has_filename() || dir == dir.root_path())
        fail(dir_given, "cannot publish into the root or a path ending in '/..'");
    const Layout layout = layout_of(files);
    // Everything below runs under the parent's lock, so no other publish changes the folder
    // between the checks and the swap. Creating a missing parent cannot hide a refusal: with
    // no parent there is no folder to refuse.
    std::error_code ec;
    fs::create_directories(dir.parent_path(), ec);
    if (ec) fail(dir.parent_path(), "cannot create folder: " + ec.message());
    const FolderLock lock(dir.parent_path());
    clean_leftovers(dir);
    check_target(dir, layout);
    const fs::path staging = stage(dir, files, layout);
    try {
        carry_over(dir, staging, layout);
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
