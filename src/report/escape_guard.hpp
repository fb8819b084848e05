#pragma once
/// Swapping mstch's global escape function for one render (Markdown or HTML escaping).
#include <functional>
#include <string>

#include <mstch/mstch.hpp>

namespace freestand::report {

/// Installs f as mstch's escape function and restores the previous one on destruction.
class EscapeGuard {
  public:
    explicit EscapeGuard(std::function<std::string(const std::string&)> f)
        : saved_(mstch::config::escape) {
        mstch::config::escape = std::move(f);
    }
    ~EscapeGuard() { mstch::config::escape = saved_; }
    EscapeGuard(const EscapeGuard&) = delete;
    EscapeGuard& operator=(const EscapeGuard&) = delete;

  private:
    std::function<std::string(const std::string&)> saved_;
};

}  // namespace freestand::report
