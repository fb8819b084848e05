#pragma once
/// Validation against the thesis (docs/methods.md s.13): its shake-table tests and worked examples
/// run through freestand's own models with the thesis's stated inputs, side by side with what the
/// thesis measured or computed. Nothing here is tuned to agree: where the two differ, the row says
/// so and gives the likely reason.
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
    /// The thesis's stated input lies beyond what its shake table can play (a sine whose table
    /// travel exceeds the stroke): shown, but neither an agreement nor a difference.
    not_runnable,
};
/// "agrees", "differs", "not comparable", "not runnable".
const char* to_string(Agreement a);

/// What a row's agreement can show, so that agreements are counted apart.
enum class Kind {
    /// The prediction is made from the thesis's own numbers (a friction taken from the very
    /// observation compared, the thesis's inputs through the thesis's formula): agreement is
    /// expected and is no evidence that the model predicts the test; a difference points at
    /// arithmetic.
    by_construction,
    /// The outcome only: rest, slide, rock or overturn; integrity kept or lost.
    outcome,
    /// A number freestand predicts from its own inputs beside one the thesis measured or
    /// computed, within a tolerance the row's group states.
    quantitative,
};
/// "by construction", "outcome", "quantitative".
const char* to_string(Kind k);

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
    Kind kind = Kind::quantitative;         ///< every row builder sets it
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

/// The rows of one kind by their agreement.
struct Tally {
    Kind kind = Kind::quantitative;
    int rows = 0;
    int agrees = 0;
    int differs = 0;
    int not_comparable = 0;
    int not_runnable = 0;
    /// Rows that compare: agrees + differs.
    int compared() const { return agrees + differs; }
};

/// One tally per kind, in the order of Kind, each present even when it has no row.
std::vector<Tally> tally(const std::vector<Row>& rows);

/// The shipped cases the glove-box rows assess, by file name.
const std::vector<std::string>& case_names();

/// True when cases_dir holds every file of case_names().
bool has_cases(const std::filesystem::path& cases_dir);

/// Runs every comparison. The glove-box rows assess case_names() read from cases_dir (IoError
/// when one cannot be read). Deterministic.
Validation run(const std::filesystem::path& cases_dir);

}  // namespace freestand::validate
