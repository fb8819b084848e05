#pragma once
/// One case assessed, without rendering: what `assess` renders and what the Python module
/// returns as result.json.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "assess/case.hpp"
#include "assess/result.hpp"
#include "assess/run_settings.hpp"
#include "fragility/fragility.hpp"
#include "goal/goal.hpp"
#include "report/json.hpp"

namespace freestand::report {

struct CaseAssessment {
    assess::AssessmentResult result;
    std::optional<fragility::Result> fragility;  ///< with [options] fragility = true
    std::optional<goal::PerformanceGoal> goal;   ///< with [site] dbe_pga_g
    Stamp stamp;
};

/// Assesses the parsed case c (case_bytes are hashed into the stamp, case_file names it), runs
/// its fragility analysis when it asks for one and, when it names its DBE, the performance goal
/// for the headline's configuration, which then decides the headline with the levels
/// (goal::apply_goal); on run's threads and through its cache (the result depends on neither).
/// Errors propagate (InputError, NumericalError).
CaseAssessment assess_case(const assess::Case& c, const std::string& case_bytes,
                           const std::filesystem::path& case_file, const std::string& commit,
                           const assess::RunSettings& run = {});

/// Reads and assesses the case file, its PGA levels replaced by pga_g when given (IoError,
/// InputError, NumericalError).
CaseAssessment assess_case_file(const std::filesystem::path& case_file,
                                const std::optional<std::vector<double>>& pga_g,
                                const std::string& commit, const assess::RunSettings& run = {});

/// result.json: the assessment with its stamp and, with a fragility result, its "fragility"
/// object, with a goal its "performance_goal" object; 2-space indented with a trailing newline.
std::string result_json_text(const assess::AssessmentResult& r, const Stamp& stamp,
                             const fragility::Result* fragility,
                             const goal::PerformanceGoal* goal = nullptr);

}  // namespace freestand::report
