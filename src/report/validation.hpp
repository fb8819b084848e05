#pragma once
/// The validation report (docs/methods.md s.13): a validate::Validation as Markdown, self-contained
/// HTML and result.json (templates/validation.{md,html}.mustache, compiled in), and the plain-text
/// table `freestand validate` prints. Reports only read the validation.
#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <string>

#include "report/json.hpp"
#include "validate/validate.hpp"

namespace freestand::report {

struct ValidationReport {
    std::string markdown;
    std::string html;  ///< self-contained: inline CSS, no external resources
    std::string json;  ///< result.json, 2-space indented, trailing newline
};

/// The stamp of a validation run: tool version, the build's commit and every case file read,
/// hashed (IoError if one cannot be read).
Stamp validation_stamp(const validate::Validation& v, const std::string& commit);

/// Every row, group, note and cited thesis value; numbers rounded to 10 significant digits,
/// absent values null; the stamp under "stamp" (ignored by regress).
nlohmann::ordered_json validation_json(const validate::Validation& v, const Stamp& stamp);

/// Renders the three documents.
ValidationReport render_validation(const validate::Validation& v, const Stamp& stamp);

/// The table as plain text: per group its rows, each with the thesis's value, freestand's,
/// the difference, the agreement and the reason, then the notes. Deterministic.
std::string validation_text(const validate::Validation& v);

/// Publishes report.md, report.html and result.json as the whole content of dir
/// (core::publish_folder). Throws IoError naming the path.
void write_validation(const std::filesystem::path& dir, const ValidationReport& report);

}  // namespace freestand::report
