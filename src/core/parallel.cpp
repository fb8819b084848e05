#include "core/parallel.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace freestand::core {

int thread_count(int requested) {
    if (requested > 0) return requested;
    return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

namespace {

// The shared state of one parallel_for: the next index to hand out, the count done and the
// lowest failing index with its exception.
struct Work {
    std::atomic<std::size_t> next{0};
    std::size_t done = 0;
    std::size_t failed_at = 0;
    std::exception_ptr failure;
    std::mutex lock;
    std::condition_variable changed;
};

void run_items(Work& w, std::size_t n, const std::function<void(std::size_t)>& body) {
    for (std::size_t i = w.next++; i < n; i = w.next++) {
        std::exception_ptr error;
        try {
            body(i);
        } catch (...) {
            error = std::current_exception();
        }
        const std::lock_guard<std::mutex> guard(w.lock);
        ++w.done;
        if (error && (!w.failure || i < w.failed_at)) {
            w.failure = error;
            w.failed_at = i;
        }
        if (w.failure) w.next = n;  // the others start nothing new
        w.changed.notify_one();
    }
}

// The caller's thread reports progress while the workers run.
void report_until_done(Work& w, std::size_t n, const ProgressCallback& progress) {
    using Clock = std::chrono::steady_clock;
    auto last = Clock::now();
    std::unique_lock<std::mutex> guard(w.lock);
    while (w.done < n && !w.failure) {
        w.changed.wait_for(guard, std::chrono::milliseconds(200));
        if (!progress || Clock::now() - last < std::chrono::milliseconds(200)) continue;
        last = Clock::now();
        const std::size_t now = w.done;
        guard.unlock();
        progress(now, n);
        guard.lock();
    }
}

}  // namespace

void parallel_for(std::size_t n, int threads, const std::function<void(std::size_t)>& body,
                  const ProgressCallback& progress) {
    if (n == 0) return;
    const auto workers = std::min(n, static_cast<std::size_t>(thread_count(threads)));
    Work w;
    if (workers == 1 && !progress) {
        run_items(w, n, body);
    } else {
        std::vector<std::thread> pool;
        pool.reserve(workers);
        for (std::size_t k = 0; k < workers; ++k)
            pool.emplace_back([&] { run_items(w, n, body); });
        report_until_done(w, n, progress);
        for (std::thread& t : pool) t.join();
    }
    if (w.failure) std::rethrow_exception(w.failure);
    if (progress) progress(n, n);
}

}  // namespace freestand::core
