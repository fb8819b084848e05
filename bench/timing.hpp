#pragma once
/// Clocks the benchmarks share: wall time since a start, and the calling thread's CPU time
/// (on this shared virtual machine the CPU time of one thread is steadier than wall time).
#include <chrono>
#include <ctime>
#include <filesystem>

#include "support/paths.hpp"

namespace freestand::bench {

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

inline double thread_cpu_s() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

/// The project's root.
inline std::filesystem::path source_dir() { return freestand::test::source_dir(); }

}  // namespace freestand::bench
