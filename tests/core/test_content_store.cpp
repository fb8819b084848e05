// core::ContentStore, the history cache's folder: entries found as stored, damaged entries
// detected and removed, concurrent writers, the size bound, clear and info.
#include "core/content_store.hpp"

#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "core/errors.hpp"
#include "core/sha256.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_core_test_content_store {

namespace fs = std::filesystem;
using freestand::core::ContentStore;

namespace {

fs::path fresh_dir(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() /
                         ("freestand-store-" + name + "-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    return dir;
}

std::string key_of(const std::string& text) { return freestand::core::sha256_hex(text); }

std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

}  // namespace

TEST_CASE("a stored entry is found whole, an unknown key is absent", "[core][cache]") {
    const fs::path dir = fresh_dir("basic");
    const ContentStore store(dir);
    std::string content(100000, '\0');
    for (std::size_t i = 0; i < content.size(); ++i) content[i] = static_cast<char>(i * 7);
    CHECK_FALSE(store.get(key_of("a")));
    REQUIRE(store.put(key_of("a"), content));
    const auto back = store.get(key_of("a"));
    REQUIRE(back);
    CHECK(*back == content);
    CHECK_FALSE(store.get(key_of("b")));
    CHECK_FALSE(store.get("not-a-key"));
    const auto info = store.info();
    CHECK(info.entries == 1);
    CHECK(info.bytes > content.size());
    fs::remove_all(dir);
}

TEST_CASE("a damaged entry is treated as absent and removed", "[core][cache]") {
    const fs::path dir = fresh_dir("damaged");
    const ContentStore store(dir);
    const std::string key = key_of("x");
    const fs::path file = dir / (key + ".entry");
    SECTION("a flipped byte") {
        REQUIRE(store.put(key, std::string(5000, 'q')));
        std::string bytes = slurp(file);
        bytes[bytes.size() / 2] ^= 0x01;
        std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
    }
    SECTION("cut short") {
        REQUIRE(store.put(key, std::string(5000, 'q')));
        fs::resize_file(file, fs::file_size(file) - 10);
    }
    SECTION("another key's entry under this name") {
        REQUIRE(store.put(key_of("y"), std::string(50, 'q')));
        fs::rename(dir / (key_of("y") + ".entry"), file);
    }
    SECTION("empty") {
        fs::create_directories(dir);
        std::ofstream(file).close();
    }
    CHECK_FALSE(store.get(key));
    CHECK_FALSE(fs::exists(file));
    fs::remove_all(dir);
}

TEST_CASE("an entry that is not a regular file is absent and never followed", "[core][cache]") {
    const fs::path dir = fresh_dir("special");
    fs::create_directories(dir);
    const ContentStore store(dir);
    const fs::path target = dir / "elsewhere";
    std::ofstream(target) << "do not touch";
    const std::string key = key_of("s");
    fs::create_symlink(target, dir / (key + ".entry"));
    CHECK_FALSE(store.get(key));
    // A put replaces the link itself, never writes through it.
    REQUIRE(store.put(key, "content"));
    CHECK(slurp(target) == "do not touch");
    CHECK_FALSE(fs::is_symlink(dir / (key + ".entry")));
    CHECK(store.get(key) == std::string("content"));
    fs::remove_all(dir);
}

TEST_CASE("concurrent writers and readers of one key see whole entries", "[core][cache]") {
    const fs::path dir = fresh_dir("concurrent");
    const ContentStore store(dir);
    const std::string key = key_of("c");
    const std::string content(200000, 'z');
    std::vector<std::thread> threads;
    std::atomic<int> bad{0};
    for (int t = 0; t < 4; ++t) {
        threads.emplace_back([&] {
            for (int i = 0; i < 20; ++i) {
                if (!store.put(key, content)) ++bad;
                const auto got = store.get(key);
                if (got && *got != content) ++bad;
            }
        });
    }
    for (auto& t : threads) t.join();
    CHECK(bad == 0);
    CHECK(store.get(key) == content);
    // No temporary file is left behind.
    std::size_t files = 0;
    for (const auto& e : fs::directory_iterator(dir)) files += e.is_regular_file() ? 1 : 0;
    CHECK(files == 1);
    fs::remove_all(dir);
}

TEST_CASE("prune keeps the store within its bound, least recently used first", "[core][cache]") {
    const fs::path dir = fresh_dir("prune");
    const ContentStore store(dir, 15000);
    const std::string content(10000, 'p');
    for (const char* k : {"1", "2", "3"}) {
        REQUIRE(store.put(key_of(k), content));
        // Distinct times for the least-recently-used order.
        fs::last_write_time(dir / (key_of(k) + ".entry"),
                            fs::file_time_type::clock::now() - std::chrono::hours(3) +
                                std::chrono::minutes(std::stoi(k)));
    }
    REQUIRE(store.get(key_of("1")));  // used now: the newest
    CHECK(store.prune() == 2);
    CHECK(store.get(key_of("1")));
    CHECK_FALSE(store.get(key_of("2")));
    CHECK_FALSE(store.get(key_of("3")));
    CHECK(store.info().bytes <= 15000);
    fs::remove_all(dir);
}

TEST_CASE("prune removes temporary files of killed writers, clear removes only the store's files",
          "[core][cache]") {
    const fs::path dir = fresh_dir("clear");
    const ContentStore store(dir);
    REQUIRE(store.put(key_of("k"), "v"));
    const fs::path stale = dir / ".tmp-99999-0-0";
    std::ofstream(stale) << "half";
    fs::last_write_time(stale, fs::file_time_type::clock::now() - std::chrono::hours(2));
    const fs::path fresh = dir / ".tmp-99999-0-1";
    std::ofstream(fresh) << "being written";
    std::ofstream(dir / "notes.txt") << "a user's file";
    CHECK(store.prune() == 1);
    CHECK_FALSE(fs::exists(stale));
    CHECK(fs::exists(fresh));
    CHECK(store.clear() == 2);
    CHECK(fs::exists(dir / "notes.txt"));
    CHECK(store.info().entries == 0);
    fs::remove_all(dir);
}

TEST_CASE("an unwritable folder makes put report why, and the run goes on", "[core][cache]") {
    const fs::path file = fresh_dir("unwritable");
    std::ofstream(file) << "a file where the folder would be";
    const ContentStore store(file / "sub");
    std::string why;
    CHECK_FALSE(store.put(key_of("k"), "v", &why));
    CHECK_THAT(why, Catch::Contains("cannot create"));
    CHECK_FALSE(store.get(key_of("k")));
    fs::remove(file);
}

TEST_CASE("the default folder follows XDG_CACHE_HOME, then HOME", "[core][cache]") {
    const char* xdg = std::getenv("XDG_CACHE_HOME");
    const char* home = std::getenv("HOME");
    const std::string saved_xdg = xdg ? xdg : "", saved_home = home ? home : "";
    ::setenv("XDG_CACHE_HOME", "/x/cache", 1);
    CHECK(freestand::core::default_cache_dir() == fs::path("/x/cache/freestand"));
    ::setenv("XDG_CACHE_HOME", "relative", 1);  // not absolute: ignored (XDG base dir rule)
    ::setenv("HOME", "/home/u", 1);
    CHECK(freestand::core::default_cache_dir() == fs::path("/home/u/.cache/freestand"));
    ::unsetenv("XDG_CACHE_HOME");
    ::unsetenv("HOME");
    CHECK_FALSE(freestand::core::default_cache_dir());
    if (xdg) ::setenv("XDG_CACHE_HOME", saved_xdg.c_str(), 1);
    if (home) ::setenv("HOME", saved_home.c_str(), 1);
}

TEST_CASE("FREESTAND_CACHE_MAX_MB sets the bound, anything but a whole MiB count is refused",
          "[core][cache]") {
    ::setenv("FREESTAND_CACHE_MAX_MB", "12", 1);
    CHECK(freestand::core::cache_max_bytes_from_environment() == 12ULL * 1024 * 1024);
    for (const char* bad : {"0", "-3", "1.5", "", "12MB", "99999999999"}) {
        ::setenv("FREESTAND_CACHE_MAX_MB", bad, 1);
        CHECK_THROWS_AS(freestand::core::cache_max_bytes_from_environment(), freestand::InputError);
    }
    ::unsetenv("FREESTAND_CACHE_MAX_MB");
    CHECK(freestand::core::cache_max_bytes_from_environment() ==
          freestand::core::default_cache_max_bytes);
}

}  // namespace freestand_test_core_test_content_store
