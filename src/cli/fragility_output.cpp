#include "cli/fragility_output.hpp"

#include <fmt/format.h>

#include <iostream>

#include "core/file_io.hpp"
#include "core/printable.hpp"
#include "report/fragility_report.hpp"
#include "report/pdf.hpp"

namespace freestand::cli {

void write_fragility_outputs(const fragility::Result& r, const report::Stamp& stamp,
                             const std::filesystem::path& out, bool print_json,
                             const std::optional<std::filesystem::path>& pdf_converter) {
    const report::RenderedFragility rendered = report::render_fragility(r, stamp);
    std::vector<core::OutputFile> extra;
    if (pdf_converter)
        extra.push_back({"report.pdf", report::html_to_pdf(*pdf_converter, rendered.html)});
    report::write_fragility(out, rendered, extra);
    if (print_json) {
        std::cout << rendered.json;
        return;
    }
    std::cout << fmt::format("{}: fragility over {} levels x {} samples written to {}\n",
                             core::printable_name(r.meta.case_name), r.levels.size(),
                             r.meta.config.samples, core::printable_name(out.string()));
    for (std::size_t e = 0; e < fragility::all_events.size(); ++e) {
        const auto& f = r.fits[e];
        const char* name = fragility::event_name(fragility::all_events[e]);
        if (f.fit)
            std::cout << fmt::format("  {:<8} theta_m {:.3g} g, beta {:.3g}; PGA at 1% {:.3g} g, "
                                     "5% {:.3g} g, 50% {:.3g} g\n",
                                     name, f.fit->theta_m_g, f.fit->beta, f.fit->pga_1pct_g,
                                     f.fit->pga_5pct_g, f.fit->pga_50pct_g);
        else
            std::cout << fmt::format("  {:<8} no fit: {}\n", name, f.note);
    }
}

}  // namespace freestand::cli
