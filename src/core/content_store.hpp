#pragma once
/// A folder of byte strings addressed by a digest of what made them: the history cache. An
/// entry is looked up by its key (the SHA-256 of a description of everything that determines
/// its content), so an entry found is the entry that would be computed, and nothing needs to
/// be invalidated.
///
/// Several processes may read and write one folder at once: an entry is written to a
/// temporary file and renamed into place, so a reader sees a whole entry or none. Every entry
/// carries its key, its length and the SHA-256 of its content; one that does not check is
/// treated as absent and removed (the caller recomputes it). The folder's size is bounded:
/// prune() removes the least recently used entries beyond max_bytes.
#include <cstdint>
#include <mutex>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace freestand::core {

/// Entries are bounded to this total unless FREESTAND_CACHE_MAX_MB says otherwise: 1 GiB, about
/// 10,000 three-component sets of 20 s at 5 ms.
inline constexpr std::uint64_t default_cache_max_bytes = 1024ULL * 1024 * 1024;

/// $XDG_CACHE_HOME/freestand, else $HOME/.cache/freestand (the XDG base directory rule); none
/// when neither variable is set to an absolute path.
std::optional<std::filesystem::path> default_cache_dir();

/// The bound from FREESTAND_CACHE_MAX_MB (whole MiB, 1 to 10^7), else the default. Throws
/// InputError naming the variable when it is set to anything else.
std::uint64_t cache_max_bytes_from_environment();

/// What the folder holds.
struct StoreInfo {
    std::filesystem::path dir;
    std::size_t entries = 0;
    std::uint64_t bytes = 0;
    std::uint64_t max_bytes = 0;
};

class ContentStore {
  public:
    /// The folder is created on the first put(), not here.
    explicit ContentStore(std::filesystem::path dir,
                          std::uint64_t max_bytes = default_cache_max_bytes);

    const std::filesystem::path& dir() const { return dir_; }

    /// The content stored under key (64 lower-case hex digits), or none when absent, not a
    /// regular file, or damaged (then it is removed). A hit marks the entry recently used.
    std::optional<std::string> get(std::string_view key) const;

    /// Stores content under key. Returns false, with the reason in *why, when the entry
    /// could not be written (the run goes on without it: a cache is never needed).
    bool put(std::string_view key, std::string_view content, std::string* why = nullptr) const;
    /// The reason the first failed put gave ("" when none failed), for one warning per run.
    std::string first_failure() const;

    /// Removes the least recently used entries until the total is within max_bytes, and
    /// temporary files older than an hour (left by killed writers). Returns entries removed.
    std::size_t prune() const;

    /// Removes every entry and temporary file (only files of this store's naming: the folder
    /// and anything else in it stay). Returns files removed.
    std::size_t clear() const;

    StoreInfo info() const;

  private:
    std::filesystem::path entry_path(std::string_view key) const;

    std::filesystem::path dir_;
    std::uint64_t max_bytes_;
    mutable std::mutex failure_lock_;
    mutable std::string first_failure_;
};

}  // namespace freestand::core
