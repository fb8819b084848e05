// core::parallel_for: every item once, results independent of the thread count, the failure
// of the lowest index, progress from the caller's thread.
#include "core/parallel.hpp"

#include <catch2/catch.hpp>

#include <atomic>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_core_test_parallel {

using freestand::core::parallel_for;

TEST_CASE("parallel_for runs every item once, on as many threads as asked", "[core][parallel]") {
    for (int threads : {1, 2, 3, 8}) {
        std::vector<int> hits(100, 0);
        std::set<std::thread::id> seen;
        std::mutex lock;
        parallel_for(hits.size(), threads, [&](std::size_t i) {
            ++hits[i];
            const std::lock_guard<std::mutex> guard(lock);
            seen.insert(std::this_thread::get_id());
            // Long enough that every worker gets an item.
            std::this_thread::sleep_for(std::chrono::microseconds(200));
        });
        CHECK(hits == std::vector<int>(100, 1));
        CHECK(seen.size() == static_cast<std::size_t>(threads));
    }
}

TEST_CASE("parallel_for with zero threads uses every core", "[core][parallel]") {
    CHECK(freestand::core::thread_count(0) ==
          static_cast<int>(std::max(1u, std::thread::hardware_concurrency())));
    CHECK(freestand::core::thread_count(5) == 5);
}

TEST_CASE("parallel_for rethrows the lowest failing index, whatever the thread count",
          "[core][parallel]") {
    for (int threads : {1, 2, 4}) {
        std::atomic<int> started{0};
        try {
            parallel_for(50, threads, [&](std::size_t i) {
                ++started;
                if (i == 7 || i == 8 || i == 30) throw std::runtime_error(std::to_string(i));
            });
            FAIL("no exception");
        } catch (const std::runtime_error& e) {
            CHECK(std::string(e.what()) == "7");
        }
        // Nothing new starts after a failure: at most one item per other thread past 8.
        CHECK(started.load() <= 9 + threads);
    }
}

TEST_CASE("parallel_for reports progress on the caller's thread, ending with all done",
          "[core][parallel]") {
    const auto caller = std::this_thread::get_id();
    std::vector<std::size_t> reports;
    bool on_caller = true;
    parallel_for(
        20, 2, [](std::size_t) { std::this_thread::sleep_for(std::chrono::milliseconds(25)); },
        [&](std::size_t done, std::size_t total) {
            on_caller = on_caller && std::this_thread::get_id() == caller;
            CHECK(total == 20);
            reports.push_back(done);
        });
    CHECK(on_caller);
    REQUIRE(reports.size() >= 2);  // 250 ms of work: at least one report before the last
    CHECK(reports.back() == 20);
    CHECK(std::is_sorted(reports.begin(), reports.end()));
}

}  // namespace freestand_test_core_test_parallel
