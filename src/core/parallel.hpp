#pragma once
/// Independent work items on several threads, with results that do not depend on the thread
/// count: item i writes only its own slot, items are handed out in index order, and a failure
/// rethrown is the lowest-indexed one, as a single thread would have met it first.
#include <cstddef>
#include <functional>

namespace freestand::core {

/// Threads to use for `requested` (0: every core the machine reports, at least 1).
int thread_count(int requested);

/// Called from the calling thread with the number of items done, at most every 200 ms and
/// once at the end.
using ProgressCallback = std::function<void(std::size_t done, std::size_t total)>;

/// Runs body(i) for i in [0, n) on min(n, thread_count(threads)) threads (the caller's own
/// thread when that is 1). After a failure no further item starts; the exception of the
/// lowest failing index is rethrown once every started item has ended.
void parallel_for(std::size_t n, int threads, const std::function<void(std::size_t)>& body,
                  const ProgressCallback& progress = {});

}  // namespace freestand::core
