#pragma once
/// What `fragility` and `merge` share: publishing a whole run's outputs.
#include <filesystem>
#include <optional>

#include "fragility/fragility.hpp"
#include "report/json.hpp"

namespace freestand::cli {

/// Renders and publishes the outputs into out, prints the summary (or fragility.json with
/// print_json) to stdout. With pdf_converter (report::find_pdf_converter) report.pdf, made from
/// report.html, is published with them.
void write_fragility_outputs(const fragility::Result& r, const report::Stamp& stamp,
                             const std::filesystem::path& out, bool print_json,
                             const std::optional<std::filesystem::path>& pdf_converter = {});

}  // namespace freestand::cli
