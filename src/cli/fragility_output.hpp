#pragma once
/// What `fragility` and `merge` share: a shard's run descriptor and writing the outputs.
#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <optional>

#include "assess/case.hpp"
#include "fragility/fragility.hpp"
#include "report/json.hpp"

namespace freestand::cli {

/// The run descriptor of a shard header: {"meta", "stamp"}.
nlohmann::ordered_json fragility_run_json(const fragility::Meta& meta, const report::Stamp& stamp);

/// Renders and publishes the outputs into out, prints the summary (or fragility.json with
/// print_json) to stdout. With pdf_converter (report::find_pdf_converter) report.pdf, made from
/// report.html, is published with them.
void write_fragility_outputs(const fragility::Result& r, const report::Stamp& stamp,
                             const std::filesystem::path& out, bool print_json,
                             const std::optional<std::filesystem::path>& pdf_converter = {});

}  // namespace freestand::cli
