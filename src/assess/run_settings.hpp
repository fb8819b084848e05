#pragma once
/// How a run uses the machine: threads, the caches of history sets and runs, and progress reports. No output
/// depends on any of them: every result is the same at any thread count, with or without the
/// cache (docs/methods.md s.12).
#include <cstddef>
#include <functional>
#include <string>

#include "core/content_store.hpp"

namespace freestand::assess {

/// Reports a long step's progress from the calling thread: the step ("history sets",
/// "simulations at 0.3 g, x"), the items done and the step's total.
using StepProgress =
    std::function<void(const std::string& step, std::size_t done, std::size_t total)>;

struct RunSettings {
    RunSettings() = default;
    /// threads threads, no cache, silent.
    explicit RunSettings(int threads_) : threads(threads_) {}

    int threads = 0;                            ///< 0: every core
    const core::ContentStore* cache = nullptr;  ///< none: every history set is generated
    /// Simulation runs (assess/run_cache.hpp); none: every run is simulated.
    const core::ContentStore* run_cache = nullptr;
    StepProgress progress;                      ///< none: silent
};

}  // namespace freestand::assess
