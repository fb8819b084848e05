#pragma once
/// Swapping mstch's global escape function for one render (Markdown or HTML escaping).
#include <functional>
#include <mutex>
#include <string>

#include <mstch/mstch.hpp>

namespace freestand::report {

/// Installs f as mstch's escape function and restores the previous one on destruction. The
/// escape function is one process-wide variable, so a guard also holds a process-wide lock for
/// its lifetime: renders on several threads (a batch's workers) run one at a time, each with
/// its own escaping. Guards must not nest.
class EscapeGuard {
  public:
    explicit EscapeGuard(std::function<std::string(const std::string&)> f)
        : lock_(render_mutex()), saved_(mstch::config::escape) {
        mstch::config::escape = std::move(f);
    }
    ~EscapeGuard() { mstch::config::escape = saved_; }
    EscapeGuard(const EscapeGuard&) = delete;
    EscapeGuard& operator=(const EscapeGuard&) = delete;

  private:
    static std::mutex& render_mutex() {
        static std::mutex m;
        return m;
    }
    std::unique_lock<std::mutex> lock_;
    std::function<std::string(const std::string&)> saved_;
};

}  // namespace freestand::report
