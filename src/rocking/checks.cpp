#include "rocking/checks.hpp"

#include <algorithm>
#include <cmath>
#include <vector>
#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/units.hpp"

namespace freestand::rocking {

using block::Block;
using block::Edge;

double uplift_threshold_g(const Block& blk, Edge e, double av_g) {
    require_in_range(av_g, 0.0, 1.0, SourceLocation{"", 0, "av_g"}, true, false);
    return blk.tan_alpha(e) * (1.0 - av_g);
}

double ishiyama_velocity_mps(const Block& blk, Edge e, double g_mps2) {
    const double c = std::cos(blk.alpha_rad(e));
    return 0.4 * std::sqrt(8.0 * g_mps2 * blk.R_m(e) * (1.0 - c) / (3.0 * c));
}

double overturning_energy_jpkg(const Block& blk, Edge e, double g_mps2) {
    return g_mps2 * blk.R_m(e) * (1.0 - std::cos(blk.alpha_rad(e)));
}

HousnerEstimate housner_energy(const Block& blk, Edge e, double sv_mps, double g_mps2) {
    require_in_range(sv_mps, 0.0, HUGE_VAL, SourceLocation{"", 0, "sv_mps"}, true, false);
    const double r = blk.R_m(e);
    const double ratio = blk.mass_kg * r * r / blk.inertia_edge_kgm2(e);  // M R^2 / I_O
    HousnerEstimate h;
    h.sv_mps = sv_mps;
    h.alpha_rad = blk.alpha_rad(e);
    h.alpha_required_rad = std::sqrt(ratio) * sv_mps / std::sqrt(g_mps2 * r);
    h.e_ot_jpkg = overturning_energy_jpkg(blk, e, g_mps2);
    h.e_in_jpkg = 0.5 * ratio * sv_mps * sv_mps;
    h.survives = h.alpha_rad > h.alpha_required_rad;
    return h;
}

double peak_pseudo_velocity_mps(const spectra::Spectrum& s, double g_mps2) {
    if (s.frequency_hz.empty() || s.frequency_hz.size() != s.psa_g.size())
        throw InputError(SourceLocation{"", 0, "spectrum"},
                         fmt::format("spectrum \"{}\" has {} frequencies and {} PSA values",
                                     s.label, s.frequency_hz.size(), s.psa_g.size()));
    double best = 0.0;
    for (std::size_t i = 0; i < s.frequency_hz.size(); ++i)
        best = std::max(best, s.psa_g[i] * g_mps2 / units::hz_to_radps(s.frequency_hz[i]));
    return best;
}

double peak_pseudo_velocity_mps(const DampedDemand& d, double g_mps2) {
    std::vector<double> fs = d.lo.frequency_hz;
    if (d.weight_hi > 0.0) fs.insert(fs.end(), d.hi.frequency_hz.begin(), d.hi.frequency_hz.end());
    double best = 0.0;
    for (double f : fs) best = std::max(best, d.psa_g(f) * g_mps2 / units::hz_to_radps(f));
    return best;
}

std::string amplification_warning(sliding::Mode mode, double mu_s, double A) {
    switch (mode) {
        case sliding::Mode::rest:
        case sliding::Mode::flight: return "";
        case sliding::Mode::slide:
            return fmt::format(
                "sliding caps the horizontal acceleration transmitted to the body at about mu (g + "
                "a_v): attenuation ~ mu / A = {:.3g}",
                A > 0.0 ? mu_s / A : 1.0);
        case sliding::Mode::rock:
        case sliding::Mode::slide_rock:
            return "rocking amplifies accelerations at the top of the body through impacts: "
                   "factors of 1.3 to 11 were measured on rigid specimens; check attached "
                   "equipment and contents";
    }
    return "";
}

}  // namespace freestand::rocking
