#include "api/slide.hpp"

#include <cmath>

#include "core/errors.hpp"
#include "core/limits.hpp"
#include "sliding/spectrum_input.hpp"

namespace freestand::api {
namespace slide_detail {

SourceLocation field(const char* name) { return SourceLocation{"", 0, name}; }

sliding::SlidingInput checked_input(const SlideRequest& r) {
    sliding::SlidingInput in;
    in.mu_s = r.mu_s;
    core::limits::require_in(in.mu_s, core::limits::friction, field("mu_s"));
    in.av_g = r.av_g;
    require_in_range(in.av_g, 0.0, 2.5, field("av_g"), true, false);
    in.pgd_m = r.pgd_m;
    if (in.pgd_m) require_in_range(*in.pgd_m, 0.0, HUGE_VAL, field("pgd_m"), true, false);
    in.pga_h_g = r.pga_h_g;
    if (in.pga_h_g) require_in_range(*in.pga_h_g, 0.0, HUGE_VAL, field("pga_h_g"), true, false);
    return in;
}

}  // namespace slide_detail

SlideResult slide(const SlideRequest& r) {
    using slide_detail::field;
    if (r.fes_hz.has_value() == !r.spectrum10_files.empty())
        throw InputError(field("fes_hz"), "expected exactly one of fes_hz and spectrum10_files");
    const sliding::SlidingInput in = slide_detail::checked_input(r);
    if (r.fes_hz) {
        require_positive(*r.fes_hz, field("fes_hz"));
        return {r, sliding::estimate_sliding(in, *r.fes_hz)};
    }
    return {r, sliding::estimate_sliding(
                   in, sliding::vector_horizontal_from_files(r.spectrum10_files,
                                                             sliding::asce_sliding_damping))};
}

json to_json(const SlideResult& result) {
    const SlideRequest& in = result.request;
    const sliding::SlidingEstimate& e = result.estimate;
    // A number, or null plus "<key>_reason".
    const auto put = [](json& j, const std::string& key, const std::optional<double>& v,
                        const std::string& why) {
        j[key] = number_or_null(v);
        if (!v) j[key + "_reason"] = why;
    };
    json j;
    j["method"] =
        "ASCE 4 equivalent-linear (ASCE 4-16) and energy-conservation (Saraswat 2017) sliding "
        "(docs/methods.md s.4)";
    j["mu_s"] = in.mu_s;
    j["av_g"] = in.av_g;
    j["mu_e"] = e.mu_e;
    j["c_s_mps2"] = e.c_s_mps2;
    put(j, "f_es_hz", e.f_es_hz, e.f_es_reason);
    j["f_es_source"] = e.f_es_source;
    j["slides"] = e.slides;
    put(j, "slide_asce_m", e.slide_asce_m, e.slide_asce_reason);
    j["pgd_m"] = number_or_null(in.pgd_m);
    put(j, "slide_energy_m", e.slide_energy_m, e.slide_energy_reason);
    return j;
}

}  // namespace freestand::api
