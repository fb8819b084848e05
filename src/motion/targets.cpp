#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/tolerances.hpp"
#include "core/errors.hpp"
#include "motion/motion.hpp"
#include "spectra/design.hpp"

namespace freestand::motion {
namespace {

// Dense grid plus the RG 1.60 control points, so log-log interpolation (Spectrum::psa_at)
// reproduces the piecewise log-linear design shape exactly.
std::vector<double> design_grid(double control_c_hz) {
    std::vector<double> f = spectra::log_frequencies(0.01, 200.0, 100);
    for (double c : {0.25, control_c_hz, 9.0, 33.0}) f.push_back(c);
    std::sort(f.begin(), f.end());
    // A control point that meets another or a grid point is kept once; the two are the same
    // frequency computed two ways, equal but for rounding.
    constexpr double same_frequency_rel = 1e-12;
    const auto same = [](double a, double b) { return std::abs(a - b) <= same_frequency_rel * b; };
    f.erase(std::unique(f.begin(), f.end(), same), f.end());
    return f;
}

spectra::Spectrum scaled(const spectra::Spectrum& s, double ratio, const std::string& label) {
    spectra::Spectrum out = s;
    for (double& v : out.psa_g) v *= ratio;
    out.label = label;
    return out;
}

}  // namespace

void validate_target(const spectra::Spectrum& s, double expected_damping) {
    const SourceLocation where{"", 0, s.label.empty() ? std::string("target") : s.label};
    if (std::abs(s.damping - expected_damping) > core::tol::damping_equal)
        throw InputError(where,
                         fmt::format("damping {} but the acceptance criteria (SRP 3.7.1) are "
                                     "on the {}-damped spectrum; give a {} target",
                                     s.damping, expected_damping, expected_damping));
    if (s.frequency_hz.size() < 2 || s.frequency_hz.size() != s.psa_g.size())
        throw InputError(where, fmt::format("{} frequencies and {} PSA values; expected the same "
                                            "number, at least 2",
                                            s.frequency_hz.size(), s.psa_g.size()));
    for (std::size_t i = 0; i < s.frequency_hz.size(); ++i) {
        const double f = s.frequency_hz[i];
        const double a = s.psa_g[i];
        if (!(std::isfinite(f) && f > 0.0))
            throw InputError(
                where, fmt::format("point {}: frequency {} Hz; expected finite > 0", i + 1, f));
        if (i > 0 && !(f > s.frequency_hz[i - 1]))
            throw InputError(where,
                             fmt::format("point {}: frequency {} Hz not above the previous {} Hz; "
                                         "frequencies must be strictly increasing",
                                         i + 1, f, s.frequency_hz[i - 1]));
        if (!(std::isfinite(a) && a > 0.0))
            throw InputError(where, fmt::format("point {}: PSA {} g at {} Hz; expected finite > 0",
                                                i + 1, a, f));
    }
}

Target rg160_vertical_target(double pga_g, double zpa_ratio,
                             const std::vector<double>& frequency_hz, double g_mps2) {
    require_positive(pga_g, SourceLocation{"", 0, "pga_g"});
    require_in_range(zpa_ratio, 0.0, 2.0, SourceLocation{"", 0, "vertical_ratio"}, false, true);
    Target t;
    // The shape is linear in the PGA it is drawn for (D scales the ground displacement, itself
    // proportional to the PGA), so scaling the argument scales the whole spectrum.
    t.psa_5pct = spectra::rg160(zpa_ratio * pga_g, 0.05, true, frequency_hz, g_mps2);
    t.psa_10pct = spectra::rg160(zpa_ratio * pga_g, 0.10, true, frequency_hz, g_mps2);
    t.horizontal = false;
    t.g_mps2 = g_mps2;
    t.realism = rg160_realism();
    return t;
}

TargetSet rg160_targets(double pga_g, double vertical_zpa_ratio, double g_mps2) {
    require_positive(pga_g, SourceLocation{"", 0, "pga_g"});
    TargetSet t;
    t.label =
        vertical_zpa_ratio == spectra::rg160_vertical_zpa_ratio
            ? fmt::format("RG 1.60, PGA {} g", pga_g)
            : fmt::format("RG 1.60, PGA {} g, vertical ZPA {} x PGA", pga_g, vertical_zpa_ratio);
    const auto fh = design_grid(2.5);
    t.horizontal.psa_5pct = spectra::rg160(pga_g, 0.05, false, fh, g_mps2);
    t.horizontal.psa_10pct = spectra::rg160(pga_g, 0.10, false, fh, g_mps2);
    t.horizontal.rg160_psd_pga_g = pga_g;
    t.horizontal.realism = rg160_realism();
    t.horizontal.g_mps2 = g_mps2;
    t.vertical = rg160_vertical_target(pga_g, vertical_zpa_ratio, design_grid(3.5), g_mps2);
    return t;
}

TargetSet ratio_targets(std::string label, const spectra::Spectrum& horizontal_5pct,
                        const std::optional<spectra::Spectrum>& horizontal_10pct,
                        double vertical_ratio, double g_mps2) {
    validate_target(horizontal_5pct, 0.05);
    if (horizontal_10pct) validate_target(*horizontal_10pct, 0.10);
    require_in_range(vertical_ratio, 0.0, 2.0, SourceLocation{"", 0, "vertical_ratio"}, false,
                     true);
    TargetSet t;
    t.label = std::move(label);
    t.horizontal.psa_5pct = horizontal_5pct;
    t.horizontal.psa_10pct = horizontal_10pct;
    t.horizontal.g_mps2 = t.vertical.g_mps2 = g_mps2;
    const std::string vlabel = fmt::format("{} x {}", vertical_ratio, horizontal_5pct.label);
    t.vertical.psa_5pct = scaled(horizontal_5pct, vertical_ratio, vlabel);
    t.vertical.horizontal = false;
    if (horizontal_10pct)
        t.vertical.psa_10pct =
            scaled(*horizontal_10pct, vertical_ratio,
                   fmt::format("{} x {}", vertical_ratio, horizontal_10pct->label));
    return t;
}

double zero_period_g(const spectra::Spectrum& psa_5pct) { return psa_5pct.psa_g.back(); }

RealismLimits rg160_realism() {
    RealismLimits r;
    r.va_mps_per_g = Range{0.8, 2.0};
    r.adv2 = Range{2.0, 8.0};
    r.da_max_m_per_g = 1.3;
    return r;
}

namespace {
void validate_range(const Range& r, const char* field) {
    const SourceLocation where{"", 0, field};
    require_positive(r.min, where);
    require_positive(r.max, where);
    if (!(r.min < r.max))
        throw InputError(where, fmt::format("[{}, {}]: expected min < max", r.min, r.max));
}
}  // namespace

void validate_realism(const RealismLimits& r) {
    validate_range(r.pga_over_zpa, "pga_over_zpa_range");
    require_positive(r.d5_75_min_s, SourceLocation{"", 0, "d5_75_min_s"});
    if (r.va_mps_per_g) validate_range(*r.va_mps_per_g, "va_range_mps_per_g");
    if (r.adv2) validate_range(*r.adv2, "adv2_range");
    if (r.da_max_m_per_g) require_positive(*r.da_max_m_per_g, SourceLocation{"", 0, "da_max_m_per_g"});
}

void set_realism(TargetSet& targets, const RealismLimits& limits) {
    validate_realism(limits);
    targets.horizontal.realism = limits;
    targets.vertical.realism = limits;
    if (targets.horizontal_2) targets.horizontal_2->realism = limits;
}

}  // namespace freestand::motion
