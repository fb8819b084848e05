#include "report/joined.hpp"

#include <nlohmann/json.hpp>
#include <fmt/format.h>

#include "assess/joined.hpp"
#include "assess/verdict.hpp"
#include "core/printable.hpp"
#include "core/contract.hpp"
#include "report/template_render.hpp"

namespace freestand::report {

extern const char* const template_joined_md;
extern const char* const template_joined_html;

namespace {

std::string mm(double m) { return fmt::format("{:.1f}", m * 1000.0); }

// The pair's names as one line (a title, a headline): their line breaks shown, not obeyed.
std::string pair_name(const assess::JoinedResult& j) {
    return core::printable_name(j.units[0].input.component.name + " + " +
                                j.units[1].input.component.name);
}

std::string between(const std::string& text, const std::string& open, const std::string& close,
                    bool inclusive) {
    const auto a = text.find(open);
    const auto b = text.find(close, a == std::string::npos ? 0 : a);
    if (a == std::string::npos || b == std::string::npos) return "";
    return inclusive ? text.substr(a, b + close.size() - a)
                     : text.substr(a + open.size(), b - a - open.size());
}

// A unit's figures renamed unit<i>-<file>, and its Markdown's links to them.
void prefix_figures(Rendered& unit, std::size_t i) {
    const std::string prefix = fmt::format("unit{}-", i + 1);
    for (Figure& f : unit.figures) {
        const std::string renamed = prefix + f.file;
        std::string::size_type at = 0;
        const std::string link = "(" + f.file + ")";
        while ((at = unit.markdown.find(link, at)) != std::string::npos) {
            unit.markdown.replace(at, link.size(), "(" + renamed + ")");
            at += renamed.size() + 2;
        }
        f.file = renamed;
    }
}

mstch::array level_items(const assess::JoinedResult& j) {
    mstch::array out;
    for (const assess::TunnelLevel& l : j.levels) {
        const assess::TunnelDirection& g = l.directions[l.governing_direction];
        out.push_back(mstch::map{
            {"pga", fmt::format("{:.3f}", l.pga_g)},
            {"histories", std::to_string(l.histories)},
            {"settled", fmt::format("{:.1f}%{}", 100.0 * l.settling.settled_fraction,
                                    l.settling.settled ? "" : " (not settled)")},
            {"statistic", std::string("84th percentile")},
            {"direction", std::string(assess::to_string(g.direction))},
            {"relative", fmt::format("{} / {} / {}", mm(g.relative_m.mean), mm(g.relative_m.p84),
                                     mm(g.relative_m.max))},
            {"common", fmt::format("{} / {}", mm(g.relative_common_m.mean),
                                   mm(g.relative_common_m.max))},
            {"allowable", mm(j.tunnel.allowable_relative_m)},
            {"margin", l.margin ? fmt::format("{:.2f}", *l.margin) : std::string("no relative motion")},
            {"overturned", fmt::format("{} / {}", g.overturned, l.histories)},
            {"result", (l.passes ? "passes: " : "FAILS: ") + l.text},
        });
    }
    return out;
}

mstch::map context(const assess::JoinedResult& j, const std::array<Rendered, 2>& units,
                   bool html) {
    mstch::array unit_items;
    for (std::size_t i = 0; i < 2; ++i) {
        unit_items.push_back(mstch::map{
            {"index", std::to_string(i + 1)},
            {"name", core::printable_name(j.units[i].input.component.name)},
            {"verdict", assess::verdict_text(j.units[i].overall.verdict)},
            {"body", html ? between(units[i].html, "<body>", "</body>", false) : std::string()},
        });
    }
    const assess::TunnelLevel& g = j.levels.at(j.governing_level);
    return mstch::map{
        {"pair_name", pair_name(j)},
        {"verdict", j.verdict},
        {"verdict_kind", std::string(j.passes ? "acceptable" : "anchor")},
        {"style", html ? between(units[0].html, "<style>", "</style>", true) : std::string()},
        {"tunnel_height_mm", mm(j.tunnel.height_m)},
        {"allowable_mm", mm(j.tunnel.allowable_relative_m)},
        {"tunnel_summary",
         fmt::format("{} (governing PGA {:.3f} g: {})",
                     j.tunnel_passes ? "keeps its seat at every level" : "FAILS", g.pga_g,
                     g.text)},
        {"has_remedy", !j.remedy.empty()},
        {"remedy", j.remedy},
        {"units", unit_items},
        {"model", std::string(assess::pair_model_name)},
        {"model_reason", g.model_reason},
        {"bounds", j.bounds},
        {"levels", level_items(j)},
    };
}

nlohmann::ordered_json pair_json(const assess::JoinedResult& j) {
    nlohmann::ordered_json p;
    p["verdict"] = j.verdict;
    p["passes"] = j.passes;
    p["tunnel_passes"] = j.tunnel_passes;
    p["remedy"] = j.remedy.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(j.remedy);
    p["tunnel_height_m"] = round10(j.tunnel.height_m);
    p["allowable_relative_m"] = round10(j.tunnel.allowable_relative_m);
    p["model"] = assess::pair_model_name;
    p["bounds"] = j.bounds;
    p["governing_level"] = j.governing_level;
    nlohmann::ordered_json levels = nlohmann::ordered_json::array();
    for (const assess::TunnelLevel& l : j.levels) {
        nlohmann::ordered_json lj;
        lj["pga_g"] = round10(l.pga_g);
        lj["histories"] = l.histories;
        lj["n_sets"] = l.settling.n_sets;
        lj["settled_fraction"] = json_number(l.settling.settled_fraction);
        lj["settling"] = settling_json(l.settling);
        lj["governing_statistic"] = "p84";
        lj["model"] = l.model;
        lj["model_reason"] = l.model_reason;
        lj["governing_direction"] = assess::to_string(l.directions[l.governing_direction].direction);
        lj["relative_demand_m"] = round10(l.demand_m);
        lj["allowable_relative_m"] = round10(j.tunnel.allowable_relative_m);
        lj["margin"] = l.margin ? nlohmann::ordered_json(round10(*l.margin)) : nlohmann::ordered_json(nullptr);
        lj["passes"] = l.passes;
        lj["text"] = l.text;
        nlohmann::ordered_json dirs = nlohmann::ordered_json::array();
        for (const assess::TunnelDirection& d : l.directions) {
            nlohmann::ordered_json dj;
            dj["direction"] = assess::to_string(d.direction);
            dj["relative_m"] = {{"mean", round10(d.relative_m.mean)},
                                {"p84", round10(d.relative_m.p84)},
                                {"max", round10(d.relative_m.max)}};
            dj["relative_common_lower_m"] = {{"mean", round10(d.relative_common_m.mean)},
                                             {"p84", round10(d.relative_common_m.p84)},
                                             {"max", round10(d.relative_common_m.max)}};
            dj["overturned"] = d.overturned;
            dj["governing_history"] = d.governing_history + 1;
            dirs.push_back(dj);
        }
        lj["directions"] = dirs;
        levels.push_back(lj);
    }
    p["levels"] = levels;
    return p;
}

}  // namespace

Rendered render_joined(const assess::AssessmentResult& r, const Stamp& stamp) {
    FREESTAND_EXPECT(r.joined != nullptr, "a two-unit result");
    const assess::JoinedResult& j = *r.joined;
    std::array<Rendered, 2> units{render(j.units[0], stamp), render(j.units[1], stamp)};
    Rendered out;
    for (std::size_t i = 0; i < 2; ++i) {
        prefix_figures(units[i], i);
        for (const Figure& f : units[i].figures) out.figures.push_back(f);
    }
    out.markdown = render_markdown(template_joined_md, context(j, units, false));
    for (const Rendered& u : units) out.markdown += "---\n\n" + u.markdown;
    out.html = render_html(template_joined_html, context(j, units, true));
    nlohmann::ordered_json json;
    json["verdict"] = j.verdict;
    json["pair"] = pair_json(j);
    nlohmann::ordered_json unit_list = nlohmann::ordered_json::array();
    for (const assess::AssessmentResult& u : j.units) {
        nlohmann::ordered_json uj = to_json(u, stamp);
        uj.erase("stamp");
        unit_list.push_back(uj);
    }
    json["units"] = unit_list;
    json["stamp"] = stamp_json(stamp);
    out.json = json.dump(2) + "\n";
    return out;
}

std::string joined_verdict_line(const assess::AssessmentResult& r) {
    FREESTAND_EXPECT(r.joined != nullptr, "a two-unit result");
    return pair_name(*r.joined) + ": " + r.joined->verdict;
}

}  // namespace freestand::report
