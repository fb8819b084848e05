// The shard file (fragility/shard_file.hpp), whatever its records: the header line, then JSON
// lines; a set of shards is one run's 1..N each once. Refused with InputError naming the file,
// line and field.
#include <catch2/catch.hpp>

#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <unistd.h>
#include <vector>

#include "core/errors.hpp"
#include "fragility/shard_file.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_fragility_test_shard_file {

namespace fs = std::filesystem;
using Catch::Contains;
using freestand::InputError;
using freestand::fragility::join_shards;
using freestand::fragility::parse_shard;
using freestand::fragility::ShardFile;

std::string header(int k, int n, const std::string& run = "{\"x\":1}") {
    return "{\"freestand_shard\":1,\"kind\":\"test\",\"shard\":" + std::to_string(k) +
           ",\"of\":" + std::to_string(n) + ",\"run\":" + run + "}\n";
}

std::string message_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    FAIL("expected an InputError");
    return "";
}

TEST_CASE("a shard file's header and records are read with their lines", "[fragility][shards]") {
    const ShardFile s = parse_shard(header(2, 3) + "{\"a\":1}\n{\"a\":2}\n", "s.jsonl");
    CHECK(s.kind == "test");
    CHECK(s.k == 2);
    CHECK(s.n == 3);
    CHECK(s.run == nlohmann::json{{"x", 1}});
    REQUIRE(s.records.size() == 2);
    CHECK(s.records[1]["a"] == 2);
    CHECK(s.record_lines == std::vector<int>{2, 3});
}

TEST_CASE("a malformed shard file is refused naming its file and line", "[fragility][shards]") {
    CHECK_THAT(message_of([] { parse_shard(header(1, 1) + "{\"a\":\n", "s.jsonl"); }),
               Contains("s.jsonl:2") && Contains("not a JSON line"));
    CHECK_THAT(message_of([] { parse_shard("{\"freestand_shard\":2}\n", "s.jsonl"); }),
               Contains("s.jsonl:1") && Contains("expected a freestand shard header"));
    CHECK_THAT(message_of([] { parse_shard("", "s.jsonl"); }), Contains("empty shard file"));
}

TEST_CASE("a shard count beyond an int, or not whole, is a malformed header", "[fragility][shards]") {
    // 1e39 as an int was undefined behaviour in the JSON library's conversion (found by
    // fuzz_shard_file); each must be the header's refusal.
    for (const std::string of : {"999999999999999999999999999999999999991", "1e39", "2.5",
                                 "-1e30", "18446744073709551615", "-9223372036854775808"}) {
        const std::string text = "{\"freestand_shard\":1,\"kind\":\"batch\",\"shard\":1,\"of\":" +
                                 of + ",\"run\":{}}\n";
        INFO(of);
        CHECK_THAT(message_of([&] { parse_shard(text, "s.jsonl"); }),
                   Contains("s.jsonl:1") && Contains("expected a freestand shard header"));
    }
}

TEST_CASE("shards join in shard order and must make one whole run", "[fragility][shards]") {
    auto shard = [](int k, int n, const std::string& run, const std::string& file) {
        return parse_shard(header(k, n, run) + "{\"k\":" + std::to_string(k) + "}\n", file);
    };
    const auto set = join_shards({shard(2, 2, "{\"x\":1}", "b"), shard(1, 2, "{\"x\":1}", "a")});
    CHECK(set.kind == "test");
    REQUIRE(set.records.size() == 2);
    CHECK(set.records[0]["k"] == 1);
    CHECK(set.record_at[0].file == "a");
    CHECK(set.record_at[1].line == 2);
    CHECK_THAT(message_of([&] { join_shards({shard(1, 3, "{\"x\":1}", "a")}); }),
               Contains("shard 2 of 3 is missing"));
    CHECK_THAT(message_of([&] {
                   join_shards({shard(1, 2, "{\"x\":1}", "a"), shard(1, 2, "{\"x\":1}", "b")});
               }),
               Contains("shard 1 of 2 is also in a"));
    CHECK_THAT(message_of([&] {
                   join_shards({shard(1, 2, "{\"x\":1}", "a"), shard(2, 2, "{\"x\":2}", "b")});
               }),
               Contains("b:1") && Contains("belongs to another run than a"));
    CHECK_THAT(message_of([] { join_shards({}); }), Contains("no shard given"));
}

TEST_CASE("a folder without shard files and a missing path are refused", "[fragility][shards]") {
    const fs::path dir = fs::temp_directory_path() /
                         ("freestand_shard_file_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    CHECK_THAT(message_of([&] { freestand::fragility::read_shards({dir}); }),
               Contains("no shard-K-of-N.jsonl file in this folder"));
    CHECK_THROWS_AS(freestand::fragility::read_shards({dir / "absent"}), freestand::IoError);
    fs::remove_all(dir);
}

}  // namespace freestand_test_fragility_test_shard_file
