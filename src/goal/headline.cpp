#include <fmt/format.h>

#include "goal/goal.hpp"

namespace freestand::goal {
namespace {

std::string base_text(const assess::BaseContact& b) {
    if (b.material.empty())
        return fmt::format("mu_s {:.3g} as given (bounds {:.3g}-{:.3g})", b.mu_s, b.mu_s_range[0],
                           b.mu_s_range[1]);
    return fmt::format("{} (mu_s {:.3g}-{:.3g})", b.material, b.mu_s_range[0], b.mu_s_range[1]);
}

}  // namespace

std::string percent_text(double p) {
    const double pct = 100.0 * p;
    if (pct == 0.0) return "0%";
    if (pct < 0.01) return "<0.01%";
    return pct >= 10.0 ? fmt::format("{:.0f}%", pct) : fmt::format("{:.2g}%", pct);
}

const char* failure_phrase(fragility::Event e) {
    switch (e) {
        case fragility::Event::overturn:
            return "overturning";
        case fragility::Event::slide:
            return "sliding beyond the allowable";
        case fragility::Event::rock:
            return "rocking FS below the required";
        case fragility::Event::any:
            return "any failure";
    }
    return "";
}

HeadlineCase headline_case(const assess::AssessmentResult& r) {
    if (r.overall_from_trial && r.upgrade.recommended) {
        assess::Case c = assess::with_base_material(r.input, *r.upgrade.recommended);
        const std::string base = base_text(c.component.base);
        return HeadlineCase{std::move(c), "the recommended base material, " + base};
    }
    return HeadlineCase{r.input, "the case's own base, " + base_text(r.input.component.base)};
}

PerformanceGoal evaluate_headline_goal(const assess::AssessmentResult& r,
                                       const assess::RunSettings& run) {
    const HeadlineCase h = headline_case(r);
    PerformanceGoal g = evaluate_goal(h.c, run);
    g.configuration = h.configuration;
    return g;
}

std::string goal_basis(const PerformanceGoal& g) {
    const LimitState& s = g.governing_state();
    const bool at_150 = s.at_150_governs;
    const double p = at_150 ? s.at_150.p : s.at_dbe.p;
    const double target = at_150 ? target_150 : target_dbe;
    const std::string p_text = percent_text(p);
    return fmt::format("P({} at {} {:.2f} g){}{} {} {}", failure_phrase(s.event),
                       at_150 ? "1.5 x DBE" : "DBE", (at_150 ? 1.5 : 1.0) * g.dbe_pga_g,
                       p_text.front() == '<' ? " " : " = ", p_text,
                       p > target ? ">" : "<=", percent_text(target));
}

void apply_goal(assess::AssessmentResult& r, const PerformanceGoal& g) {
    // change_material is the recommended material's pass; anchor is already a failure.
    if (g.passes || r.overall.verdict.kind == assess::VerdictKind::anchor) return;
    const LimitState& s = g.governing_state();
    assess::Verdict v;
    v.kind = assess::VerdictKind::anchor;
    v.failure = assess::Failure::performance_goal;
    v.margin = s.margin;
    v.margin_basis = goal_basis(g);
    v.decided_by = assess::Model::fragility_goal;
    v.conditions = r.overall.verdict.conditions;
    r.overall.verdict = v;
    r.overall.pga_g = (s.at_150_governs ? 1.5 : 1.0) * g.dbe_pga_g;
}

}  // namespace freestand::goal
