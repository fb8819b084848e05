#include "cli/progress.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>

namespace freestand::cli {

namespace {

using Clock = std::chrono::steady_clock;

// A run shorter than this shows no bar at all.
constexpr std::chrono::seconds quiet_start{1};

void draw(const std::string& what, std::size_t done, std::size_t total, Clock::time_point start) {
    constexpr int width = 30;
    const double elapsed_s = std::chrono::duration<double>(Clock::now() - start).count();
    const double rate = elapsed_s > 0.0 ? static_cast<double>(done) / elapsed_s : 0.0;
    const double left_s = rate > 0.0 ? static_cast<double>(total - done) / rate : 0.0;
    const auto filled = static_cast<int>(width * static_cast<double>(done) / static_cast<double>(total));
    std::fprintf(stderr, "\r[%s%s] %zu/%zu %s, %.1f/s, %.0f s left  ",
                 std::string(static_cast<std::size_t>(filled), '=').c_str(),
                 std::string(static_cast<std::size_t>(width - filled), ' ').c_str(), done, total,
                 what.c_str(), rate, left_s);
    std::fflush(stderr);
}

bool stderr_is_terminal() { return ::isatty(STDERR_FILENO) == 1; }

}  // namespace

Progress::Progress(std::string what)
    : what_(std::move(what)), active_(stderr_is_terminal()), start_(Clock::now()) {}

void Progress::update(std::size_t done, std::size_t total) {
    if (!active_ || total == 0 || Clock::now() - start_ < quiet_start) return;
    draw(what_, done, total, start_);
    drawn_ = true;
}

void Progress::finish() {
    if (active_ && drawn_) std::fputs("\n", stderr);
    drawn_ = false;
}

StepProgressBar::StepProgressBar()
    : active_(stderr_is_terminal()), run_start_(Clock::now()), step_start_(run_start_) {}

void StepProgressBar::update(const std::string& step, std::size_t done, std::size_t total) {
    const std::lock_guard<std::mutex> guard(lock_);
    if (step != step_) {
        if (drawn_) std::fputs("\n", stderr);
        drawn_ = false;
        step_ = step;
        step_start_ = Clock::now();
    }
    if (!active_ || total == 0 || Clock::now() - run_start_ < quiet_start) return;
    draw(step_, done, total, step_start_);
    drawn_ = true;
}

void StepProgressBar::finish() {
    const std::lock_guard<std::mutex> guard(lock_);
    if (active_ && drawn_) std::fputs("\n", stderr);
    drawn_ = false;
}

}  // namespace freestand::cli
