#pragma once
/// What `fragility` and `merge` share: the run's stamp and writing its outputs.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>

#include "assess/case.hpp"
#include "fragility/fragility.hpp"
#include "report/json.hpp"

namespace freestand::cli {

/// The stamp of a fragility run: the case's bytes, the seed, the case's other inputs and the
/// records of a user suite, each hashed.
report::Stamp fragility_stamp(const std::string& case_bytes, const std::string& case_file,
                              const assess::Case& c, const fragility::Config& config);

/// The run descriptor of a shard header: {"meta", "stamp"}.
nlohmann::ordered_json fragility_run_json(const fragility::Meta& meta, const report::Stamp& stamp);

/// Renders and publishes the outputs into out, prints the summary (or fragility.json with
/// json) to stdout. With pdf_converter (report::find_pdf_converter) report.pdf, made from
/// report.html, is published with them.
void write_fragility_outputs(const fragility::Result& r, const report::Stamp& stamp,
                             const std::filesystem::path& out, bool json,
                             const std::optional<std::filesystem::path>& pdf_converter = {});

}  // namespace freestand::cli
