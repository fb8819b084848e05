#include "report/summary.hpp"

#include <nlohmann/json.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <mstch/mstch.hpp>

#include "assess/verdict.hpp"
#include "core/printable.hpp"
#include "core/csv_table.hpp"
#include "report/template_render.hpp"
#include "report/json.hpp"
#include "report/render.hpp"

namespace freestand::report {

// Defined in the generated templates_embedded.cpp (src/report/CMakeLists.txt).
extern const char* const template_summary_md;
extern const char* const template_summary_html;

namespace {

using nlohmann::ordered_json;

std::string status_text(const SummaryRow& r) {
    return r.outcome ? std::string("ok") : fmt::format("error: {}", r.error);
}

std::size_t assessed_count(const Summary& s) {
    std::size_t n = 0;
    for (const SummaryRow& r : s.rows) n += r.outcome ? 1 : 0;
    return n;
}

// The cells every format shows, "" where a failed row has nothing.
struct Cells {
    std::string component, verdict_kind, verdict, governing, pga, direction, material, margin,
        decided_by, recommended, conditions;
};

Cells cells(const SummaryRow& r) {
    if (!r.outcome) return Cells{};
    const SummaryOutcome& o = *r.outcome;
    return Cells{o.component,
                 o.verdict_kind,
                 o.verdict,
                 o.governing_level,
                 fmt::format("{}", round10(o.governing_pga_g)),
                 o.governing_direction,
                 o.governing_material,
                 o.margin_text,
                 o.decided_by,
                 o.recommended_material,
                 fmt::format("{}", fmt::join(o.open_conditions, "; "))};
}

mstch::map row_context(const SummaryRow& r) {
    const Cells c = cells(r);
    // Table cells are one line: names' line breaks are shown, not obeyed.
    return mstch::map{{"name", core::printable_name(r.name)},
                      {"case_file", core::printable_name(r.case_file)},
                      {"component", core::printable_name(c.component)},
                      {"verdict", c.verdict},
                      {"verdict_kind", c.verdict_kind},
                      {"governing", c.governing},
                      {"margin", c.margin},
                      {"decided_by", c.decided_by},
                      {"material", c.recommended},
                      {"conditions", c.conditions},
                      {"status", status_text(r)},
                      {"exit_code", std::to_string(r.exit_code)},
                      {"assessed", r.outcome.has_value()},
                      {"overrides", r.overrides},
                      {"has_overrides", !r.overrides.empty()},
                      {"sha256", r.case_sha256.empty() ? std::string("(not read)") : r.case_sha256}};
}

mstch::map context(const Summary& s) {
    mstch::array rows;
    for (const SummaryRow& r : s.rows) rows.push_back(row_context(r));
    const std::size_t assessed = assessed_count(s);
    return mstch::map{
        {"list", s.stamp.list},
        {"components", std::to_string(s.rows.size())},
        {"assessed", std::to_string(assessed)},
        {"failed", std::to_string(s.rows.size() - assessed)},
        {"rows", rows},
        {"stamp_version", s.stamp.tool_version},
        {"stamp_commit", s.stamp.commit},
        {"stamp_list", s.stamp.list},
        {"stamp_list_sha256", s.stamp.list_sha256.empty()
                                  ? std::string("(a folder: each case file is hashed below)")
                                  : s.stamp.list_sha256},
    };
}

const std::vector<std::string> csv_header{
    "name",         "case_file",    "component",     "verdict",         "verdict_text",
    "governing_pga_g", "governing_direction", "governing_material", "governing_level", "margin",
    "decided_by",   "recommended_material", "open_conditions", "overrides", "status",
    "exit_code",    "case_sha256"};

std::string summary_csv(const Summary& s) {
    std::string out = core::csv_record(csv_header);
    for (const SummaryRow& r : s.rows) {
        const Cells c = cells(r);
        out += core::csv_record({r.name, r.case_file, c.component, c.verdict_kind, c.verdict,
                                 c.pga, c.direction, c.material, c.governing, c.margin,
                                 c.decided_by, c.recommended, c.conditions, r.overrides,
                                 status_text(r), std::to_string(r.exit_code), r.case_sha256});
    }
    return out;
}

ordered_json text_or_null(const std::string& s) { return s.empty() ? ordered_json() : ordered_json(s); }

ordered_json row_json(const SummaryRow& r) {
    ordered_json j;
    j["name"] = r.name;
    j["case_file"] = r.case_file;
    j["case_sha256"] = text_or_null(r.case_sha256);
    j["overrides"] = text_or_null(r.overrides);
    j["status"] = r.outcome ? "ok" : "error";
    j["error"] = text_or_null(r.error);
    j["exit_code"] = r.exit_code;
    if (!r.outcome) {
        j["outcome"] = nullptr;
        return j;
    }
    const SummaryOutcome& o = *r.outcome;
    j["outcome"] = {{"component", o.component},
                    {"verdict_kind", o.verdict_kind},
                    {"verdict", o.verdict},
                    {"governing", {{"pga_g", round10(o.governing_pga_g)},
                                   {"direction", o.governing_direction},
                                   {"material", text_or_null(o.governing_material)}}},
                    {"governing_level", o.governing_level},
                    {"margin", o.margin ? ordered_json(round10(*o.margin)) : ordered_json()},
                    {"margin_text", o.margin_text},
                    {"decided_by", o.decided_by},
                    {"recommended_material", text_or_null(o.recommended_material)},
                    {"open_conditions", o.open_conditions}};
    return j;
}

}  // namespace

SummaryOutcome summary_outcome(const assess::AssessmentResult& r) {
    const assess::Verdict& v = r.overall.verdict;
    const std::string trial_material =
        v.material.empty() ? r.upgrade.recommended.value_or("") : v.material;
    return SummaryOutcome{r.input.component.name,
                          assess::to_string(v.kind),
                          assess::verdict_text(v),
                          headline_level(r),
                          r.overall.pga_g,
                          assess::to_string(r.overall.direction),
                          r.overall_from_trial ? trial_material : std::string(),
                          v.margin,
                          assess::margin_text(v),
                          assess::to_string(v.decided_by),
                          r.upgrade.recommended.value_or(""),
                          v.conditions};
}

ordered_json summary_json(const Summary& s) {
    ordered_json j;
    j["list"] = s.stamp.list;
    const std::size_t assessed = assessed_count(s);
    j["counts"] = {{"components", s.rows.size()},
                   {"assessed", assessed},
                   {"failed", s.rows.size() - assessed}};
    ordered_json rows = ordered_json::array();
    for (const SummaryRow& r : s.rows) rows.push_back(row_json(r));
    j["rows"] = rows;
    j["stamp"] = {{"tool", "freestand"},
                  {"version", s.stamp.tool_version},
                  {"commit", s.stamp.commit},
                  {"list", s.stamp.list},
                  {"list_sha256", text_or_null(s.stamp.list_sha256)}};
    return j;
}

RenderedSummary render_summary(const Summary& s) {
    RenderedSummary out;
    const mstch::map ctx = context(s);
    out.markdown = render_markdown(template_summary_md, ctx);
    out.html = render_html(template_summary_html, ctx);
    out.csv = summary_csv(s);
    out.json = summary_json(s).dump(2) + "\n";
    return out;
}

}  // namespace freestand::report
