#pragma once
/// One case end to end: read, assess, render (what `assess` and `regress` share).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "assess/overrides.hpp"
#include "assess/result.hpp"
#include "report/render.hpp"

namespace freestand::report {

struct CaseRun {
    assess::AssessmentResult result;
    std::optional<fragility::Result> fragility;  ///< with [options] fragility = true
    std::optional<goal::PerformanceGoal> goal;   ///< with [site] dbe_pga_g
    Rendered rendered;
};

/// Reads the case file (its bytes are hashed into the stamp), optionally replaces its PGA levels,
/// assesses, runs the fragility analysis when the case asks for it and renders, on run's
/// threads and through its cache (the result depends on neither). commit is the build's commit
/// for the stamp. Errors propagate (IoError, InputError, NumericalError).
CaseRun run_case(const std::filesystem::path& case_file,
                 const std::optional<std::vector<double>>& pga_g, const std::string& commit,
                 const assess::RunSettings& run = {});

/// The same on case text already read (case_bytes, hashed into the stamp; case_file names it
/// in messages and resolves its relative paths) with overrides written into it
/// (assess::parse_case): a batch's run of one component, on run's threads (a batch's workers
/// share the cores out). Errors propagate as above.
CaseRun run_case(const std::string& case_bytes, const std::filesystem::path& case_file,
                 const assess::CaseOverrides& overrides, const std::string& commit,
                 const assess::RunSettings& run);

/// The one-line verdict the commands print, all from the headline's one governing level:
/// "<name>: <verdict> (governing PGA 0.400 g, direction x[ with <material>], margin 1.15 | no
/// motion, decided by <model>)" and "; open condition: ..." for each open condition.
std::string verdict_line(const assess::AssessmentResult& r);

}  // namespace freestand::report
