#include "batch/shard.hpp"

#include <nlohmann/json.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <type_traits>

#include "assess/verdict.hpp"
#include "batch/list_detail.hpp"
#include "core/errors.hpp"
#include "core/json_fields.hpp"
#include "core/limits.hpp"

namespace freestand::batch {

namespace {

using nlohmann::json;
using nlohmann::ordered_json;

using Fields = core::JsonFields;
constexpr const char* kMalformed = "malformed batch shard";

[[noreturn]] void malformed(const SourceLocation& where, const std::string& what) {
    throw InputError(where, std::string(kMalformed) + ": " + what);
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

std::optional<assess::VerdictKind> verdict_kind(const std::string& name) {
    for (const auto k : {assess::VerdictKind::acceptable,
                         assess::VerdictKind::acceptable_with_clearance,
                         assess::VerdictKind::change_material, assess::VerdictKind::anchor})
        if (name == assess::to_string(k)) return k;
    return std::nullopt;
}

// The verdict's kind, its text and its margin agree as assess::verdict_text and
// assess::margin_text write them; the governing level is a design level in one direction.
void check_outcome(const report::SummaryOutcome& o, const Fields& f) {
    const auto kind = verdict_kind(o.verdict_kind);
    if (!kind)
        malformed(f.at("verdict_kind"),
                  fmt::format("\"{}\"; expected acceptable, acceptable_with_clearance, "
                              "change_material or anchor",
                              o.verdict_kind));
    if (!assess::verdict_text_fits(*kind, o.verdict))
        malformed(f.at("verdict"), fmt::format("\"{}\" is not the text of a verdict of kind {}",
                                               o.verdict, o.verdict_kind));
    require_in_range(o.governing_pga_g, 0.0, core::limits::max_design_level_g,
                     f.at("governing_pga_g"), false, true);
    if (o.governing_direction != "x" && o.governing_direction != "y")
        malformed(f.at("governing_direction"),
                  fmt::format("\"{}\"; expected \"x\" or \"y\"", o.governing_direction));
    const bool text_without_margin = o.margin_text == "no motion" || o.margin_text == "n/a";
    if (!o.margin) {
        if (!text_without_margin)
            malformed(f.at("margin_text"),
                      fmt::format("\"{}\" with no margin; expected \"no motion\" or \"n/a\"",
                                  o.margin_text));
        return;
    }
    require_non_negative(*o.margin, f.at("margin"));
    const std::string shown = fmt::format("{:.2f}", *o.margin);
    if (o.margin_text != shown && o.margin_text != shown + " (no motion)")
        malformed(f.at("margin_text"), fmt::format("\"{}\" for the margin {}; expected \"{}\"",
                                                   o.margin_text, *o.margin, shown));
}

report::SummaryOutcome outcome_from_json(const Fields& f) {
    report::SummaryOutcome o;
    o.component = f.get<std::string>("component");
    o.verdict_kind = f.get<std::string>("verdict_kind");
    o.verdict = f.get<std::string>("verdict");
    o.governing_level = f.get<std::string>("governing_level");
    o.governing_pga_g = f.get<double>("governing_pga_g");
    o.governing_direction = f.get<std::string>("governing_direction");
    o.governing_material = f.get<std::string>("governing_material");
    if (!f.is_null("margin")) o.margin = f.get<double>("margin");
    o.margin_text = f.get<std::string>("margin_text");
    o.decided_by = f.get<std::string>("decided_by");
    o.recommended_material = f.get<std::string>("recommended_material");
    o.open_conditions = f.get<std::vector<std::string>>("open_conditions");
    check_outcome(o, f);
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

bool is_sha256_hex(const std::string& s) {
    return s.size() == 64 && std::all_of(s.begin(), s.end(), [](char c) {
               return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f');
           });
}

// A row is assessed (an outcome, no error, exit code 0) or failed (an error and the exit code of
// its class: 3 input, 4 numerical, 5 I/O, 70 internal), as run_rows makes it.
void check_status(const report::SummaryRow& r, const Fields& f) {
    if (r.outcome) {
        if (r.exit_code != 0)
            malformed(f.at("exit_code"), fmt::format("{} for an assessed component; expected 0",
                                                     r.exit_code));
        if (!r.error.empty())
            malformed(f.at("error"), "an error beside an outcome; expected \"\" for an assessed "
                                     "component");
        if (!is_sha256_hex(r.case_sha256))
            malformed(f.at("case_sha256"),
                      fmt::format("\"{}\"; expected the 64 hex digits of the case's SHA-256",
                                  r.case_sha256));
        return;
    }
    const auto code = static_cast<ExitCode>(r.exit_code);
    if (code != ExitCode::input && code != ExitCode::numerical && code != ExitCode::io &&
        code != ExitCode::internal)
        malformed(f.at("exit_code"),
                  fmt::format("{} for a component that failed; expected 3, 4, 5 or 70",
                              r.exit_code));
    if (r.error.empty()) malformed(f.at("error"), "empty for a component that failed");
    if (!r.case_sha256.empty() && !is_sha256_hex(r.case_sha256))
        malformed(f.at("case_sha256"),
                  fmt::format("\"{}\"; expected \"\" or 64 hex digits", r.case_sha256));
}

report::SummaryRow row_from_json(const Fields& f) {
    report::SummaryRow r;
    r.name = f.get<std::string>("name");
    r.case_file = f.get<std::string>("case_file");
    r.case_sha256 = f.get<std::string>("case_sha256");
    r.overrides = f.get<std::string>("overrides");
    if (!f.is_null("outcome")) r.outcome = outcome_from_json(f.object("outcome"));
    r.error = f.get<std::string>("error");
    r.exit_code = f.get<int>("exit_code");
    check_status(r, f);
    return r;
}

// A report file's name as report_files gives it: a plain name, never a path that would
// publish outside the component's folder, and each once.
void check_file_name(const std::string& name, const std::vector<core::OutputFile>& before,
                     const SourceLocation& where) {
    if (name.empty() || name == "." || name == ".." || name.find('/') != std::string::npos ||
        name.find('\0') != std::string::npos || name == core::run_marker)
        malformed(where, fmt::format("\"{}\" cannot name a report file", name));
    for (const core::OutputFile& f : before)
        if (f.name == name) malformed(where, fmt::format("the report file \"{}\" is listed twice", name));
}

std::vector<core::OutputFile> files_from_json(const Fields& record, bool assessed) {
    const json& files = record.node("files");
    const SourceLocation where = record.at("files");
    if (!files.is_array()) malformed(where, "expected a list of [name, contents]");
    if (assessed == files.empty())
        malformed(where, assessed ? "none for an assessed component; expected its report's files"
                                  : "report files for a component that failed; expected none");
    std::vector<core::OutputFile> out;
    for (const json& f : files) {
        if (!f.is_array() || f.size() != 2 || !f[0].is_string() || !f[1].is_string())
            malformed(where, "an entry that is not [name, contents]");
        check_file_name(f[0].get<std::string>(), out, where);
        out.push_back({f[0].get<std::string>(), f[1].get<std::string>()});
    }
    return out;
}

BatchRow batch_row_from_json(const Fields& record) {
    BatchRow out;
    out.row = row_from_json(record.object("row"));
    out.files = files_from_json(record, out.row.outcome.has_value());
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

BatchRun merge_shards(const json& run, const std::vector<json>& records,
                      const SourceLocation& run_at, const std::vector<SourceLocation>& record_at) {
    const Fields header(run, run_at, "run.", kMalformed);
    const Fields s = header.object("stamp");
    const report::SummaryStamp stamp{s.get<std::string>("tool_version"), s.get<std::string>("commit"),
                                     s.get<std::string>("list"), s.get<std::string>("list_sha256")};
    // The names become folders: a header that was edited must not publish elsewhere, nor two
    // components into one folder.
    BatchList names_checked;
    detail::EntryCollector collect(names_checked);
    for (const std::string& n : header.get<std::vector<std::string>>("names")) {
        BatchEntry e;
        e.name = n;
        collect.add(std::move(e), header.at("names"));
    }
    const std::vector<BatchEntry>& names = names_checked.entries;
    std::vector<std::optional<BatchRow>> rows(names.size());
    for (std::size_t r = 0; r < records.size(); ++r) {
        const Fields rec(records[r], r < record_at.size() ? record_at[r] : SourceLocation{}, "",
                         kMalformed);
        const auto index = rec.get<std::size_t>("index");
        if (index >= names.size())
            malformed(rec.at("index"),
                      fmt::format("component {} of a list of {}", index + 1, names.size()));
        if (rows[index])
            malformed(rec.at("index"), fmt::format("component {} ({}) is in two records", index + 1,
                                                   names[index].name));
        BatchRow row = batch_row_from_json(rec);
        if (row.row.name != names[index].name)
            malformed(rec.at("row.name"),
                      fmt::format("component {} is named \"{}\" in the header and \"{}\" in its "
                                  "record",
                                  index + 1, names[index].name, row.row.name));
        rows[index] = std::move(row);
    }
    std::vector<BatchRow> ordered;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        if (!rows[i])
            malformed(SourceLocation{"", 0, "shards"},
                      fmt::format("component {} ({}) is in no shard", i + 1, names[i].name));
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
