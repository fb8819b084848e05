#include "report/fragility_json.hpp"

#include <nlohmann/json.hpp>
#include <fmt/format.h>

#include <cmath>

namespace freestand::report {

namespace {

using nlohmann::ordered_json;
using fragility::all_events;


ordered_json fit_json(const fragility::EventFit& f) {
    if (!f.fit) return nullptr;
    const fragility::Fit& x = *f.fit;
    return {{"theta_m_g", json_number(x.theta_m_g)},     {"beta", json_number(x.beta)},
            {"pga_1pct_g", json_number(x.pga_1pct_g)},   {"pga_5pct_g", json_number(x.pga_5pct_g)},
            {"pga_50pct_g", json_number(x.pga_50pct_g)}, {"log_likelihood", json_number(x.log_likelihood)},
            {"chi2", json_number(x.chi2)},               {"dof", x.dof},
            {"p_value", x.p_value ? json_number(*x.p_value) : ordered_json(nullptr)}};
}

}  // namespace

std::string event_meaning(fragility::Event e, const fragility::Meta& m) {
    switch (e) {
        case fragility::Event::overturn:
            return "overturned in x or y";
        case fragility::Event::slide:
            return fmt::format("peak slide above the allowable {:.1f} mm", 1000.0 * m.allowable_slide_m);
        case fragility::Event::rock:
            return fmt::format("theta_max / alpha above 1 / FS_required = {:.3f} (or overturned)",
                               1.0 / m.required_overturn_fs);
        case fragility::Event::any:
            return "any of them";
    }
    return "";
}

std::vector<Reference> fragility_references() {
    return references({"docs/methods.md", "FEMA P-58", "Baker 2015", "Clopper & Pearson 1934"});
}

ordered_json fragility_body_json(const fragility::Result& r) {
    ordered_json j;
    ordered_json levels = ordered_json::array();
    for (const fragility::Level& l : r.levels) {
        ordered_json events;
        for (std::size_t e = 0; e < all_events.size(); ++e) {
            const fragility::Count& c = l.events[e];
            events[fragility::event_name(all_events[e])] = {
                {"k", c.k}, {"p", json_number(c.p)}, {"ci", {json_number(c.ci[0]), json_number(c.ci[1])}}};
        }
        levels.push_back({{"pga_g", json_number(l.pga_g)}, {"n", l.n}, {"events", events}});
    }
    j["levels"] = levels;
    ordered_json fits, notes;
    for (std::size_t e = 0; e < all_events.size(); ++e) {
        fits[fragility::event_name(all_events[e])] = fit_json(r.fits[e]);
        notes[fragility::event_name(all_events[e])] =
            r.fits[e].fit ? ordered_json(nullptr) : ordered_json(r.fits[e].note);
    }
    j["fit"] = fits;
    j["fit_notes"] = notes;
    const fragility::Meta& m = r.meta;
    ordered_json events;
    for (const fragility::Event e : all_events)
        events[fragility::event_name(e)] = event_meaning(e, m);
    j["inputs"] = {{"case", m.case_name},
                   {"pga_g", m.config.pga_g},
                   {"samples_per_level", m.config.samples},
                   {"seed", m.config.seed},
                   {"motions", m.motion_source},
                   {"models", m.models},
                   {"mu_s", m.mu_s_law},
                   {"restitution", m.restitution_law},
                   {"allowable_slide_m", json_number(m.allowable_slide_m)},
                   {"required_overturn_fs", json_number(m.required_overturn_fs)},
                   {"events", events},
                   {"methods", "docs/methods.md s.9"}};
    ordered_json refs = ordered_json::array();
    for (const Reference& ref : fragility_references())
        refs.push_back({{"key", ref.key}, {"text", ref.text}});
    j["references"] = refs;
    return j;
}

ordered_json fragility_json(const fragility::Result& r, const Stamp& stamp) {
    ordered_json j = fragility_body_json(r);
    j["stamp"] = stamp_json(stamp);
    return j;
}

}  // namespace freestand::report
