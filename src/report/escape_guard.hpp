#pragma once
/// Swapping mstch's global escape function for one render (Markdown or HTML escaping).
#include <functional>
#include <mutex>
#include <string>

#include <mstch/mstch.hpp>

namespace freestand::report {

/// Installs f as mstch's escape function and restores the previous one on destruction. The
/// function is global to mstch, so renders that swap it are serialised by one lock (a batch
/// renders reports on several threads).
class EscapeGuard {
  public:
    explicit EscapeGuard(std::function<std::string(const std::string&)> f)
        : lock_(mutex()), saved_(mstch::config::escape) {
        mstch::config::escape = std::move(f);
    }
    ~EscapeGuard() { mstch::config::escape = saved_; }
    EscapeGuard(const EscapeGuard&) = delete;
    EscapeGuard& operator=(const EscapeGuard&) = delete;

  private:
    static std::mutex& mutex() {
        static std::mutex m;
        return m;
    }
    std::lock_guard<std::mutex> lock_;
    std::function<std::string(const std::string&)> saved_;
};

}  // namespace freestand::report
