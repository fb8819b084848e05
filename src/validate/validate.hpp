#pragma once
/// Validation against the thesis (issue 13 s.3): its shake-table tests and worked examples run
/// through freestand's own models with the thesis's stated inputs, side by side with what the
/// thesis measured or computed. Nothing here is tuned to agree: where the two differ, the row
/// says so and gives the likely reason.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace freestand::validate {

/// How a prediction compares with the thesis.
enum class Agreement {
    agrees,          ///< same outcome, or within the row's tolerance
    differs,         ///< the row's reason says why
    not_comparable,  ///< the thesis gives no comparable value (a lost figure)
};
/// "agrees", "differs", "not comparable".
const char* to_string(Agreement a);

/// One comparison: a test or worked example of the thesis and freestand's prediction of it.
struct Row {
    std::string group;     ///< key of its Group
    std::string id;        ///< stable key, e.g. "ts1-2hz", "gb-pvc-0.15g"
    std::string test;      ///< what was tested, in words
    std::string thesis;    ///< what the thesis measured or computed, in words
    std::string predicted; ///< what freestand predicts, in words
    std::string unit;      ///< unit of the values below ("mm", "m/s", "" for outcomes)
    std::optional<double> thesis_value;
    std::optional<double> predicted_value;
    std::string difference;                 ///< predicted against thesis, in words
    std::optional<double> difference_value; ///< predicted - thesis, in unit
    Agreement agreement = Agreement::agrees;
    /// Likely reason where they differ or cannot be compared; a caveat where they agree.
    std::string reason;
    std::vector<std::string> sources;  ///< keys of the thesis facts behind the row (thesis.hpp)
};

/// A family of rows sharing a method and its assumptions.
struct Group {
    std::string key;
    std::string title;
    std::string method;                    ///< how freestand predicts, citing docs/methods.md
    std::string tolerance;                 ///< when a numeric row "agrees"
    std::vector<std::string> assumptions;  ///< every modelling choice, in words
};

/// The whole validation.
struct Validation {
    std::vector<Group> groups;
    std::vector<Row> rows;  ///< grouped, in report order
    /// What the thesis's tests could physically have been (stroke, recorded velocities), with
    /// the numbers worked out.
    std::vector<std::string> notes;
    std::vector<std::filesystem::path> case_files;  ///< the shipped cases it read
};

/// The shipped cases the glove-box rows assess, by file name.
const std::vector<std::string>& case_names();

/// True when cases_dir holds every file of case_names().
bool has_cases(const std::filesystem::path& cases_dir);

/// Runs every comparison. The glove-box rows assess case_names() read from cases_dir (IoError
/// when one cannot be read). Deterministic.
Validation run(const std::filesystem::path& cases_dir);

}  // namespace freestand::validate
