#include "core/publish.hpp"

#include <fcntl.h>
#include <stdio.h>
#include <sys/file.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <fmt/format.h>
#include <fstream>
#include <iostream>
#include <map>
#include <set>

#include "core/errors.hpp"
#include "core/file_io.hpp"
#include "core/printable.hpp"

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

// Removing the previous run's files needs write (and search) access to the folder that holds
// them (POSIX unlink, rmdir): the target and each of its sub-folders. Checked before anything
// moves, so a read-only previous run is an error that leaves it as it was, not a renamed-aside
// folder that cannot be removed. faccessat with AT_EACCESS answers for the effective user and
// reports a read-only file system (EROFS) and an immutable folder (EPERM) too.
void check_removable(const fs::path& dir) {
    const auto require_writable = [](const fs::path& folder) {
        if (::faccessat(AT_FDCWD, folder.c_str(), W_OK | X_OK, AT_EACCESS) != 0) {
            fail(folder, fmt::format("cannot replace the previous run: {}; make the folder "
                                     "writable or remove it",
                                     std::strerror(errno)));
        }
    };
    if (!fs::is_directory(fs::symlink_status(dir))) return;
    require_writable(dir);
    for (const auto& entry : fs::directory_iterator(dir))
        if (entry.symlink_status().type() == fs::file_type::directory) require_writable(entry.path());
}

// A folder that should go and cannot is named on standard error: the run itself is published
// (or refused with its own error), so this is not the run's failure, but nothing is left behind
// unsaid.
void remove_or_warn(const fs::path& folder, const char* what) {
    std::error_code ec;
    fs::remove_all(folder, ec);
    if (ec) {
        std::cerr << printable(fmt::format("freestand: warning: {}: cannot remove {}: {}; remove "
                                           "it by hand\n",
                                           folder.string(), what, ec.message()));
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
            remove_or_warn(entry.path(), "this left-over of an earlier run");
    }
}

// The folder a path names: absolute, lexically normal and without a trailing separator, so
// "new/", "new" and "new/x/.." are one folder and "." is the working folder. The root has no
// parent to stage beside and is refused.
fs::path target_folder(const fs::path& given) {
    fs::path dir = fs::absolute(given).lexically_normal();
    if (!dir.has_filename()) dir = dir.parent_path();
    if (dir == dir.root_path()) fail(given, "cannot publish into the root folder");
    return dir;
}

// True when dir is the working folder or holds it. Such a folder is not renamed aside: a shell
// standing in it would be left in a removed folder, seeing none of the run's files.
bool holds_working_folder(const fs::path& dir) {
    std::error_code ec;
    const fs::path cwd = fs::current_path(ec);
    if (ec) return false;
    const fs::path rel = cwd.lexically_relative(dir);
    return !rel.empty() && *rel.begin() != "..";
}

// The staged entry replaces target: a file by rename, a folder by an atomic exchange
// (renameat2 RENAME_EXCHANGE, Linux 3.15) that leaves the old folder in staging's place.
void replace_entry(const fs::path& staged, const fs::path& target) {
    const bool folder_over_folder = fs::is_directory(fs::symlink_status(staged)) &&
                                    fs::is_directory(fs::symlink_status(target));
    const int rc = folder_over_folder ? ::renameat2(AT_FDCWD, staged.c_str(), AT_FDCWD,
                                                    target.c_str(), RENAME_EXCHANGE)
                                      : ::rename(staged.c_str(), target.c_str());
    if (rc != 0) fail(target, std::string("cannot move the new run into place: ") + std::strerror(errno));
}

// The working folder's entries replaced one by one (see holds_working_folder): each file whole
// by a rename, each sub-folder by an exchange, the previous run's other files removed and the
// marker written last, so a run killed half-way leaves a folder the next run still owns.
// A reader may briefly see files of both runs.
void replace_in_place(const fs::path& dir, const fs::path& staging, const Layout& layout) {
    const std::set<std::string> previous = previous_run_files(dir);
    for (const std::string& name : layout.top) replace_entry(staging / name, dir / name);
    std::error_code ec;
    for (const std::string& name : previous) {
        if (layout.top.count(name) || !plain_name(name)) continue;
        fs::remove_all(dir / name, ec);
        if (ec) fail(dir / name, "cannot remove the previous run's file: " + ec.message());
    }
    replace_entry(staging / run_marker, dir / run_marker);
    remove_or_warn(staging, "the previous run's folders");
}

// The whole folder replaced: the previous run renamed aside, the staging folder renamed into
// its place, the previous run removed.
void swap_folder(const fs::path& dir, const fs::path& staging) {
    std::error_code ec;
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
    if (had_old) remove_or_warn(aside, "the previous run");
}

}  // namespace

void check_publish_target(const fs::path& dir) { check_folder(target_folder(dir)); }

void publish_folder(const fs::path& dir_given, const std::vector<OutputFile>& files) {
    const fs::path dir = target_folder(dir_given);
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
    check_removable(dir);
    const fs::path staging = stage(dir, files, layout);
    try {
        carry_over(dir, staging, layout);
        if (holds_working_folder(dir)) {
            replace_in_place(dir, staging, layout);
            return;
        }
    } catch (...) {
        fs::remove_all(staging, ec);
        throw;
    }
    swap_folder(dir, staging);
}

}  // namespace freestand::core
