#pragma once
/// Special files for the tests that check an output never replaces one (core/publish.hpp).
/// The device is a fresh null device in the test's own folder, never /dev/null: the CI runs as
/// root, so a regression would otherwise replace the machine's /dev/null with a regular file.
#include <sys/stat.h>
#include <sys/sysmacros.h>

#include <filesystem>
#include <optional>

namespace freestand::test {

/// A character device (the null device, 1:3) at dir/name, or nullopt where mknod is not
/// permitted (not root): the caller says so with WARN.
inline std::optional<std::filesystem::path> make_null_device(const std::filesystem::path& dir,
                                                             const char* name = "device") {
    const std::filesystem::path p = dir / name;
    if (::mknod(p.c_str(), S_IFCHR | 0600, makedev(1, 3)) != 0) return std::nullopt;
    return p;
}

}  // namespace freestand::test
