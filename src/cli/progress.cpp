#include "cli/progress.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>

namespace freestand::cli {

Progress::Progress(std::string what)
    : what_(std::move(what)), active_(::isatty(STDERR_FILENO) == 1),
      start_(std::chrono::steady_clock::now()) {}

void Progress::update(std::size_t done, std::size_t total) {
    if (!active_ || total == 0) return;
    constexpr int width = 30;
    const double elapsed_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const double rate = elapsed_s > 0.0 ? static_cast<double>(done) / elapsed_s : 0.0;
    const double left_s = rate > 0.0 ? static_cast<double>(total - done) / rate : 0.0;
    const auto filled = static_cast<int>(width * static_cast<double>(done) / static_cast<double>(total));
    std::fprintf(stderr, "\r[%s%s] %zu/%zu %s, %.0f/s, %.0f s left  ",
                 std::string(static_cast<std::size_t>(filled), '=').c_str(),
                 std::string(static_cast<std::size_t>(width - filled), ' ').c_str(), done, total,
                 what_.c_str(), rate, left_s);
    std::fflush(stderr);
    drawn_ = true;
}

void Progress::finish() {
    if (active_ && drawn_) std::fputs("\n", stderr);
    drawn_ = false;
}

}  // namespace freestand::cli
