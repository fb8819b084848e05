// `freestand simulate --flexible`: the reduced-order flexible body (docs/methods.md s.10).
#include "cli/simulate_flexible.hpp"

#include <fmt/format.h>
#include <iostream>

#include "cli/options.hpp"
#include "cli/series_label.hpp"
#include "core/errors.hpp"
#include "cli/usage_error.hpp"

namespace freestand::cli {

std::string flexible_series_csv(const api::FlexibleRun& run, const std::string& label) {
    const dynamics::FlexibleResult& r = run.result;
    std::string out = fmt::format(
        "# freestand simulate (flexible body): {} integrator, excitation {}\n"
        "# units: time s, slide m (contact point relative to the base), rotation rad (+ on the "
        "right edge), modal displacement m (relative to the base, along the body)\n"
        "time_s,slide_m,rotation_rad,modal_m,mode\n",
        r.summary.base.integrator, one_line_label(label));
    for (const auto& s : r.series)
        out += fmt::format("{:.6f},{:.9g},{:.9g},{:.9g},{}\n", s.time_s, s.slide_m,
                           s.rotation_rad, s.modal_m, dynamics::to_string(s.mode));
    return out;
}

dynamics::FlexibleMode parse_flexible_mode(const std::string& text) {
    const auto kv = parse_key_values(text, "--flexible", {"f", "zeta", "mass", "height"});
    if (!kv.count("f"))
        throw UsageError(fmt::format(
            "--flexible: expected f=HZ[,zeta=RATIO][,mass=FRACTION][,height=M]; got \"{}\"", text));
    dynamics::FlexibleMode m;
    m.frequency_hz = kv.at("f");
    if (kv.count("zeta")) m.damping = kv.at("zeta");
    if (kv.count("mass")) m.mass_fraction = kv.at("mass");
    if (kv.count("height")) m.height_m = kv.at("height");
    return m;
}

void print_flexible(const api::FlexibleRun& run) {
    const dynamics::FlexibleModel& model = run.model;
    const dynamics::FlexibleSummary& s = run.result.summary;
    std::cout << fmt::format(
        "model                 flexible body: f {} Hz, zeta {}, modal mass {} M at {:.4g} m\n"
        "                      {}\n"
        "integrator            {}\n"
        "base uplifted         {}\n"
        "peak modal drift      {:.4g} m = {:.4g} of the modal height\n"
        "peak modal accel      {:.4g} g (PGA {:.4g} g)\n"
        "peak slide            {:.4g} m (residual {:.4g} m)\n"
        "peak rotation         {:.4g} rad = {:.3g} alpha\n"
        "overturned            {}\n"
        "impacts               {}\n"
        "wall time             {:.4g} s\n",
        model.frequency_hz, model.damping, model.mass_fraction, model.height_m,
        api::model_reason(run), s.base.integrator, s.uplifted ? "yes" : "no", s.modal_max_m,
        s.modal_drift_max, s.modal_accel_max_g, s.base.pga_g, s.base.slide_max_m,
        s.base.slide_residual_m, s.base.rock_max_rad, s.base.rock_max_over_alpha,
        s.base.overturned
            ? fmt::format("yes, at {:.4f} s, mode {} ({})", *s.base.overturn_time_s,
                          *s.base.overturn_mode,
                          dynamics::overturn_criterion_name(s.base.overturn_criterion))
            : "no",
        s.base.impacts, s.base.wall_s);
    for (const auto& a : api::assumptions(run, "--top"))
        std::cout << "assumption            " << a << "\n";
}

}  // namespace freestand::cli
