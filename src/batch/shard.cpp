#include "batch/shard.hpp"

#include <nlohmann/json.hpp>
#include <fmt/format.h>

#include <optional>

#include "core/errors.hpp"

namespace freestand::batch {

namespace {

using nlohmann::json;
using nlohmann::ordered_json;

[[noreturn]] void malformed(const std::string& what) {
    throw InputError(SourceLocation{"", 0, "shards"},
                     fmt::format("a batch shard's contents are malformed ({})", what));
}

ordered_json outcome_json(const report::SummaryOutcome& o) {
    return ordered_json{{"component", o.component},
                        {"verdict_kind", o.verdict_kind},
                        {"verdict", o.verdict},
                        {"governing_level", o.governing_level},
                        {"governing_pga_g", o.governing_pga_g},
                        {"governing_direction", o.governing_direction},
                        {"governing_material", o.governing_material},
                        {"margin", o.margin ? ordered_json(*o.margin) : ordered_json()},
                        {"margin_text", o.margin_text},
                        {"decided_by", o.decided_by},
                        {"recommended_material", o.recommended_material},
                        {"open_conditions", o.open_conditions}};
}

report::SummaryOutcome outcome_from_json(const json& j) {
    report::SummaryOutcome o;
    o.component = j.at("component").get<std::string>();
    o.verdict_kind = j.at("verdict_kind").get<std::string>();
    o.verdict = j.at("verdict").get<std::string>();
    o.governing_level = j.at("governing_level").get<std::string>();
    o.governing_pga_g = j.at("governing_pga_g").get<double>();
    o.governing_direction = j.at("governing_direction").get<std::string>();
    o.governing_material = j.at("governing_material").get<std::string>();
    if (!j.at("margin").is_null()) o.margin = j.at("margin").get<double>();
    o.margin_text = j.at("margin_text").get<std::string>();
    o.decided_by = j.at("decided_by").get<std::string>();
    o.recommended_material = j.at("recommended_material").get<std::string>();
    o.open_conditions = j.at("open_conditions").get<std::vector<std::string>>();
    return o;
}

ordered_json row_json(const report::SummaryRow& r) {
    return ordered_json{{"name", r.name},
                        {"case_file", r.case_file},
                        {"case_sha256", r.case_sha256},
                        {"overrides", r.overrides},
                        {"outcome", r.outcome ? outcome_json(*r.outcome) : ordered_json()},
                        {"error", r.error},
                        {"exit_code", r.exit_code}};
}

report::SummaryRow row_from_json(const json& j) {
    report::SummaryRow r;
    r.name = j.at("name").get<std::string>();
    r.case_file = j.at("case_file").get<std::string>();
    r.case_sha256 = j.at("case_sha256").get<std::string>();
    r.overrides = j.at("overrides").get<std::string>();
    if (!j.at("outcome").is_null()) r.outcome = outcome_from_json(j.at("outcome"));
    r.error = j.at("error").get<std::string>();
    r.exit_code = j.at("exit_code").get<int>();
    return r;
}

// A report file's name as report_files gives it: a plain name, never a path that would
// publish outside the component's folder.
void check_file_name(const std::string& name) {
    if (name.empty() || name == "." || name == ".." || name.find('/') != std::string::npos ||
        name.find('\0') != std::string::npos || name == core::run_marker)
        malformed(fmt::format("\"{}\" cannot name a report file", name));
}

BatchRow batch_row_from_json(const json& j) {
    BatchRow out;
    out.row = row_from_json(j.at("row"));
    for (const json& f : j.at("files")) {
        if (!f.is_array() || f.size() != 2) malformed("a file is not [name, contents]");
        out.files.push_back({f[0].get<std::string>(), f[1].get<std::string>()});
        check_file_name(out.files.back().name);
    }
    return out;
}

}  // namespace

ordered_json shard_run_json(const report::SummaryStamp& stamp, const BatchList& list) {
    std::vector<std::string> names;
    for (const BatchEntry& e : list.entries) names.push_back(e.name);
    return ordered_json{{"stamp",
                         {{"tool_version", stamp.tool_version},
                          {"commit", stamp.commit},
                          {"list", stamp.list},
                          {"list_sha256", stamp.list_sha256}}},
                        {"names", names}};
}

ordered_json shard_record(std::size_t index, const BatchRow& row) {
    ordered_json files = ordered_json::array();
    for (const core::OutputFile& f : row.files) files.push_back({f.name, f.contents});
    return ordered_json{{"index", index}, {"row", row_json(row.row)}, {"files", files}};
}

BatchRun merge_shards(const json& run, const std::vector<json>& records) {
    report::SummaryStamp stamp;
    std::vector<std::string> names;
    std::vector<std::optional<BatchRow>> rows;
    try {
        const json& s = run.at("stamp");
        stamp = {s.at("tool_version").get<std::string>(), s.at("commit").get<std::string>(),
                 s.at("list").get<std::string>(), s.at("list_sha256").get<std::string>()};
        names = run.at("names").get<std::vector<std::string>>();
        // The names become folders: a header that was edited must not publish elsewhere.
        for (const std::string& n : names) check_name(n, SourceLocation{"", 0, "shards"});
        rows.resize(names.size());
        for (const json& rec : records) {
            const auto index = rec.at("index").get<std::size_t>();
            if (index >= names.size())
                malformed(fmt::format("component {} of a list of {}", index + 1, names.size()));
            if (rows[index])
                malformed(fmt::format("component {} ({}) is in two records", index + 1,
                                      names[index]));
            BatchRow row = batch_row_from_json(rec);
            if (row.row.name != names[index])
                malformed(fmt::format("component {} is named \"{}\" in the header and \"{}\" in "
                                      "its record",
                                      index + 1, names[index], row.row.name));
            rows[index] = std::move(row);
        }
    } catch (const json::exception& e) {
        malformed(e.what());
    }
    std::vector<BatchRow> ordered;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        if (!rows[i]) malformed(fmt::format("component {} ({}) is in no shard", i + 1, names[i]));
        ordered.push_back(std::move(*rows[i]));
    }
    return assemble(stamp, std::move(ordered));
}

std::vector<std::size_t> shard_indices(std::size_t count, int k, int n) {
    std::vector<std::size_t> out;
    for (std::size_t i = 0; i < count; ++i)
        if (i % static_cast<std::size_t>(n) == static_cast<std::size_t>(k - 1)) out.push_back(i);
    return out;
}

}  // namespace freestand::batch
