#include "report/validation.hpp"

#include <nlohmann/json.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <mstch/mstch.hpp>
#include <set>

#include "core/file_io.hpp"
#include "core/publish.hpp"
#include "report/template_render.hpp"
#include "report/references.hpp"
#include "report/render.hpp"
#include "core/sha256.hpp"
#include "validate/thesis.hpp"
#include "core/version.hpp"

namespace freestand::report {

// Defined in the generated templates_embedded.cpp (src/report/CMakeLists.txt).
extern const char* const template_validation_md;
extern const char* const template_validation_html;

namespace {

using nlohmann::ordered_json;
using validate::Agreement;

const char* const title = "freestand against the thesis: validation";
// The references a validation report cites (keys of report::references()).
const std::set<std::string> cited{"docs/methods.md", "Saraswat 2017", "ASCE 4-16",
                                  "Housner 1963", "Ishiyama 1982", "RG 1.60"};

ordered_json optional_number(const std::optional<double>& v) {
    return v ? ordered_json(round10(*v)) : ordered_json(nullptr);
}

ordered_json fact_json(const validate::Fact& f) {
    return {{"key", f.key},
            {"value", optional_number(f.value)},
            {"unit", f.unit},
            {"text", f.text},
            {"where", f.cite.where},
            {"line", f.cite.line},
            {"quote", f.cite.quote}};
}

// The thesis places a row cites, each once, in the row's order.
std::string sources_text(const std::vector<std::string>& keys) {
    std::string out;
    std::set<std::string> seen;
    for (const std::string& k : keys) {
        const validate::Citation& c = validate::fact(k).cite;
        const std::string place = fmt::format("{} (l.{})", c.where, c.line);
        if (!seen.insert(place).second) continue;
        out += (out.empty() ? "" : "; ") + place;
    }
    return out;
}

// "outcome: 70 of 80 agree (16 not runnable on the thesis's table)": agreements counted among
// the rows that compare; the rest named apart.
std::string tally_text(const validate::Tally& t) {
    std::string out =
        fmt::format("{}: {} of {} agree", validate::to_string(t.kind), t.agrees, t.compared());
    std::vector<std::string> apart;
    if (t.not_comparable > 0) apart.push_back(fmt::format("{} not comparable", t.not_comparable));
    if (t.not_runnable > 0)
        apart.push_back(fmt::format("{} not runnable on the thesis's table", t.not_runnable));
    if (!apart.empty()) out += " (" + fmt::format("{}", fmt::join(apart, ", ")) + ")";
    return out;
}

std::string summary_text(const validate::Validation& v) {
    std::vector<std::string> parts;
    for (const validate::Tally& t : validate::tally(v.rows)) parts.push_back(tally_text(t));
    return fmt::format("{} rows; {}", v.rows.size(), fmt::join(parts, "; "));
}

ordered_json tally_json(const validate::Tally& t) {
    return {{"kind", validate::to_string(t.kind)},
            {"rows", t.rows},
            {"agrees", t.agrees},
            {"differs", t.differs},
            {"not_comparable", t.not_comparable},
            {"not_runnable", t.not_runnable}};
}

// The thesis facts the rows cite, in the order of thesis.hpp.
std::vector<const validate::Fact*> cited_facts(const validate::Validation& v) {
    std::set<std::string> keys;
    for (const validate::Row& r : v.rows) keys.insert(r.sources.begin(), r.sources.end());
    std::vector<const validate::Fact*> out;
    for (const validate::Fact& f : validate::facts()) {
        if (keys.count(f.key)) out.push_back(&f);
    }
    return out;
}

mstch::map row_context(const validate::Row& r) {
    return mstch::map{{"id", r.id},
                      {"kind", std::string(validate::to_string(r.kind))},
                      {"test", r.test},
                      {"thesis", r.thesis},
                      {"predicted", r.predicted},
                      {"difference", r.difference},
                      {"agreement", std::string(validate::to_string(r.agreement))},
                      {"agreement_class",
                       std::string(r.agreement == Agreement::agrees         ? "agrees"
                                   : r.agreement == Agreement::differs      ? "differs"
                                   : r.agreement == Agreement::not_runnable ? "not-runnable"
                                                                            : "not-comparable")},
                      {"reason", r.reason},
                      {"sources", sources_text(r.sources)}};
}

mstch::map context(const validate::Validation& v, const Stamp& stamp) {
    mstch::array groups;
    for (const validate::Group& g : v.groups) {
        mstch::array rows;
        for (const validate::Row& r : v.rows) {
            if (r.group == g.key) rows.push_back(row_context(r));
        }
        groups.push_back(mstch::map{{"title", g.title},
                                    {"method", g.method},
                                    {"tolerance", g.tolerance},
                                    {"assumptions", text_list(g.assumptions)},
                                    {"rows", rows}});
    }
    mstch::array facts;
    for (const validate::Fact* f : cited_facts(v)) {
        facts.push_back(mstch::map{
            {"key", f->key},
            {"value", f->value ? fmt::format("{:g}", *f->value) : std::string("-")},
            {"unit", f->unit},
            {"text", f->text},
            {"where", f->cite.where},
            {"line", std::to_string(f->cite.line)},
            {"quote", f->cite.quote}});
    }
    std::vector<Reference> refs;
    for (const Reference& r : references())
        if (cited.count(r.key)) refs.push_back(r);
    return mstch::map{{"title", std::string(title)},
                      {"summary", summary_text(v)},
                      {"groups", groups},
                      {"notes", text_list(v.notes)},
                      {"facts", facts},
                      {"references", reference_items(refs)},
                      {"stamp_version", stamp.tool_version},
                      {"stamp_commit", stamp.commit},
                      {"stamp_inputs", stamp_input_items(stamp)}};
}

}  // namespace

Stamp validation_stamp(const validate::Validation& v, const std::string& commit) {
    Stamp s{core::version(), commit, "", "", 0, {}};
    for (const std::filesystem::path& p : v.case_files)
        s.inputs.push_back({p.string(), core::sha256_hex(core::read_text_file(p))});
    return s;
}

ordered_json validation_json(const validate::Validation& v, const Stamp& stamp) {
    ordered_json j;
    j["title"] = title;
    ordered_json kinds = ordered_json::array();
    for (const validate::Tally& t : validate::tally(v.rows)) kinds.push_back(tally_json(t));
    j["summary"] = {{"rows", v.rows.size()}, {"text", summary_text(v)}, {"kinds", kinds}};
    ordered_json groups = ordered_json::array();
    for (const validate::Group& g : v.groups) {
        groups.push_back({{"key", g.key},
                          {"title", g.title},
                          {"method", g.method},
                          {"tolerance", g.tolerance},
                          {"assumptions", g.assumptions}});
    }
    j["groups"] = groups;
    ordered_json rows = ordered_json::array();
    for (const validate::Row& r : v.rows) {
        rows.push_back({{"group", r.group},
                        {"id", r.id},
                        {"kind", validate::to_string(r.kind)},
                        {"test", r.test},
                        {"thesis", r.thesis},
                        {"thesis_value", optional_number(r.thesis_value)},
                        {"predicted", r.predicted},
                        {"predicted_value", optional_number(r.predicted_value)},
                        {"unit", r.unit},
                        {"difference", r.difference},
                        {"difference_value", optional_number(r.difference_value)},
                        {"agreement", validate::to_string(r.agreement)},
                        {"reason", r.reason},
                        {"sources", r.sources}});
    }
    j["rows"] = rows;
    j["notes"] = v.notes;
    ordered_json facts = ordered_json::array();
    for (const validate::Fact* f : cited_facts(v)) facts.push_back(fact_json(*f));
    j["thesis"] = {{"reference", "Saraswat 2017"},
                   {"text_file", std::string("shared/thesis/") + validate::thesis_text_file},
                   {"values", facts}};
    j["stamp"] = {{"tool", "freestand"},
                  {"version", stamp.tool_version},
                  {"commit", stamp.commit},
                  {"inputs", inputs_json(stamp.inputs)}};
    return j;
}

ValidationReport render_validation(const validate::Validation& v, const Stamp& stamp) {
    ValidationReport out;
    const mstch::map ctx = context(v, stamp);
    out.markdown = render_markdown(template_validation_md, ctx);
    out.html = render_html(template_validation_html, ctx);
    out.json = validation_json(v, stamp).dump(2) + "\n";
    return out;
}

std::string validation_text(const validate::Validation& v) {
    std::string out = fmt::format("{}\nthesis: Saraswat 2017 (PhD thesis, HBNI / BARC); {}\n",
                                  title, summary_text(v));
    for (const validate::Group& g : v.groups) {
        out += fmt::format("\n== {}\n   tolerance: {}\n", g.title, g.tolerance);
        for (const validate::Row& r : v.rows) {
            if (r.group != g.key) continue;
            out += fmt::format("\n[{}, {}] {}: {}\n", validate::to_string(r.agreement),
                               validate::to_string(r.kind), r.id, r.test);
            out += fmt::format("   thesis:     {}\n", r.thesis);
            out += fmt::format("   freestand:  {}\n", r.predicted);
            out += fmt::format("   difference: {}\n", r.difference);
            if (!r.reason.empty()) out += fmt::format("   reason:     {}\n", r.reason);
        }
    }
    out += "\nnotes\n";
    for (const std::string& n : v.notes) out += "- " + n + "\n";
    return out;
}

void write_validation(const std::filesystem::path& dir, const ValidationReport& report) {
    core::publish_folder(dir, {{"report.md", report.markdown},
                               {"report.html", report.html},
                               {"result.json", report.json}});
}

}  // namespace freestand::report
