#pragma once
/// The fragility outputs (docs/methods.md s.9): fragility.json, samples.csv, report.md and a
/// self-contained report.html with the fragility curves as SVG; and the same section inside an
/// assessment's report when the case asks for it ([options] fragility = true).
#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include <mstch/mstch.hpp>

#include "core/publish.hpp"
#include "fragility/fragility.hpp"
#include "report/fragility_json.hpp"
#include "report/json.hpp"
#include "report/plots.hpp"

namespace freestand::report {

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
