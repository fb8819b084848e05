#pragma once
/// The fragility outputs (issue 14): fragility.json, samples.csv, report.md and a self-contained
/// report.html with the fragility curves as SVG; and the same section inside an assessment's
/// report when the case asks for it ([options] fragility = true).
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include <mstch/mstch.hpp>

#include "core/publish.hpp"
#include "fragility/fragility.hpp"
#include "report/json.hpp"
#include "report/plots.hpp"

namespace freestand::report {

/// {"levels": [{"pga_g", "n", "events": {"overturn": {"k", "p", "ci"}, "slide", "rock",
/// "any"}}], "fit": {"overturn": {"theta_m_g", "beta", "pga_1pct_g", "pga_5pct_g",
/// "pga_50pct_g", "log_likelihood", "chi2", "dof", "p_value"} | null, ...}, "fit_notes",
/// "inputs", "references", "stamp"}; numbers to 10 significant digits.
nlohmann::ordered_json fragility_json(const fragility::Result& r, const Stamp& stamp);

/// fragility_json without the stamp: what an assessment's result.json carries as "fragility".
nlohmann::ordered_json fragility_body_json(const fragility::Result& r);

/// One row per sample: level, sample, pga_g, motion, mu_s, restitution_x, restitution_y,
/// slide_max_m, rock_max_over_alpha, overturned (RFC 4180, numbers to 10 significant digits).
std::string samples_csv(const fragility::Result& r);

/// The fragility curves: per event, the observed k/n with their intervals as bars and the
/// fitted lognormal.
Figure fragility_figure(const fragility::Result& r);

struct RenderedFragility {
    std::string markdown;
    std::string html;
    std::string json;  ///< fragility.json
    std::string csv;   ///< samples.csv
    Figure figure;
};

RenderedFragility render_fragility(const fragility::Result& r, const Stamp& stamp);

/// Publishes report.md, report.html, fragility.json, samples.csv, the figure and the extra
/// files (report.pdf with `fragility --pdf`) as the whole content of dir (core::publish_folder).
void write_fragility(const std::filesystem::path& dir, const RenderedFragility& rendered,
                     const std::vector<core::OutputFile>& extra = {});

/// The section's template values (frag_*), merged into an assessment report's context.
mstch::map fragility_section_context(const fragility::Result& r, const Figure& figure);

}  // namespace freestand::report
