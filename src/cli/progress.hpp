#pragma once
/// A progress bar on standard error when it is a terminal (samples done, rate, time left);
/// silent otherwise, so logs and pipes stay clean.
#include <chrono>
#include <cstddef>
#include <string>

namespace freestand::cli {

class Progress {
  public:
    /// what: the unit counted ("samples").
    explicit Progress(std::string what);
    /// Redraws the bar (no-op when stderr is not a terminal).
    void update(std::size_t done, std::size_t total);
    /// Ends the bar's line.
    void finish();

  private:
    std::string what_;
    bool active_;
    bool drawn_ = false;
    std::chrono::steady_clock::time_point start_;
};

}  // namespace freestand::cli
