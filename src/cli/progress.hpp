#pragma once
/// A progress bar on standard error when it is a terminal (items done, rate, time left), drawn
/// once the run has taken a second; silent otherwise, so logs, pipes and quick runs stay clean.
#include <chrono>
#include <cstddef>
#include <mutex>
#include <string>

namespace freestand::cli {

class Progress {
  public:
    /// what: the unit counted ("samples").
    explicit Progress(std::string what);
    /// Redraws the bar (no-op when stderr is not a terminal or within the first second).
    void update(std::size_t done, std::size_t total);
    /// Ends the bar's line.
    void finish();

  private:
    std::string what_;
    bool active_;
    bool drawn_ = false;
    std::chrono::steady_clock::time_point start_;
};

/// One bar per step of a run ("history sets", then "simulations at 0.3 g, x", ...): a new step
/// ends the previous step's line. The first second counts from the run's start.
class StepProgressBar {
  public:
    StepProgressBar();
    void update(const std::string& step, std::size_t done, std::size_t total);
    void finish();

  private:
    std::mutex lock_;
    std::string step_;
    bool active_;
    bool drawn_ = false;
    std::chrono::steady_clock::time_point run_start_, step_start_;
};

}  // namespace freestand::cli
