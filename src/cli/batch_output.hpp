#pragma once
/// What `batch` and `merge` share for a batch: publishing its folder and what they print.
#include <filesystem>
#include <string>

#include "batch/run.hpp"

namespace freestand::cli {

/// Publishes the run's folder into out, then prints summary.json (json) or one line per
/// component and "wrote OUT: N components, F failed" followed by note (timing, say; never in
/// the files). Returns the exit code: 0 when every component was assessed, 1
/// (ExitCode::failure) when one failed; the rows carry each failure's own class.
int write_batch_outputs(const batch::BatchRun& run, const std::filesystem::path& out, bool json,
                        const std::string& note);

}  // namespace freestand::cli
