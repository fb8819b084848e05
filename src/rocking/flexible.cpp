#include "rocking/flexible.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <vector>

#include "core/errors.hpp"

namespace freestand::rocking {

namespace {

struct Band {
    double lo = 0.0;
    double hi = 0.0;
};

// The bands to screen (free-rocking, fixed-base, or both: screened as their union, not the
// span between them), or none with the reason when nothing falls in the seismic range.
std::vector<Band> screen_bands(const FlexibleInput& in, std::string& reason) {
    if (!in.fixed_base_hz && !in.rock_band_lo_hz && !in.rock_band_hi_hz)
        throw InputError(SourceLocation{"", 0, "flexible"},
                         "expected a fixed-base frequency or a free-rocking band");
    if (in.rock_band_lo_hz.has_value() != in.rock_band_hi_hz.has_value())
        throw InputError(SourceLocation{"", 0, "rock band"},
                         "expected both ends of the free-rocking band (lo,hi Hz)");
    std::vector<Band> bands;
    if (in.rock_band_lo_hz) {
        require_positive(*in.rock_band_lo_hz, SourceLocation{"", 0, "rock band lo_hz"});
        require_positive(*in.rock_band_hi_hz, SourceLocation{"", 0, "rock band hi_hz"});
        if (!(*in.rock_band_hi_hz > *in.rock_band_lo_hz))
            throw InputError(SourceLocation{"", 0, "rock band"},
                             fmt::format("band {},{} Hz: expected lo < hi", *in.rock_band_lo_hz,
                                         *in.rock_band_hi_hz));
        bands.push_back(Band{*in.rock_band_lo_hz, *in.rock_band_hi_hz});
    }
    if (in.fixed_base_hz) {
        const double f = *in.fixed_base_hz;
        require_positive(f, SourceLocation{"", 0, "fixed-base frequency"});
        if (f < rigid_frequency_hz) {
            bands.push_back(Band{f / band_broadening, f * band_broadening});
        } else if (bands.empty()) {
            reason = fmt::format("fixed-base frequency {} Hz >= {} Hz: rigid, screen not needed", f,
                                 rigid_frequency_hz);
        }
    }
    return bands;
}

std::string describe(const std::vector<Band>& bands) {
    std::vector<std::string> parts;
    for (const Band& b : bands) parts.push_back(fmt::format("{:.4g}-{:.4g} Hz", b.lo, b.hi));
    return fmt::format("{}", fmt::join(parts, " and "));
}

}  // namespace

FlexibleScreen flexible_screen(const spectra::Spectrum& s, const FlexibleInput& in) {
    require_positive(in.uplift_threshold_g, SourceLocation{"", 0, "uplift_threshold_g"});
    require_in_range(in.pga_h_g, 0.0, HUGE_VAL, SourceLocation{"", 0, "pga_h_g"}, true, false);
    FlexibleScreen out;
    out.threshold_g = in.uplift_threshold_g;
    const std::vector<Band> bands = screen_bands(in, out.reason);
    if (bands.empty()) return out;
    out.applies = true;
    out.band_lo_hz = bands.front().lo;
    out.band_hi_hz = bands.front().hi;
    // psa_at is a power law between points, so a band's maximum is at an end or a point.
    std::vector<double> fs;
    for (const Band& band : bands) {
        out.band_lo_hz = std::min(out.band_lo_hz, band.lo);
        out.band_hi_hz = std::max(out.band_hi_hz, band.hi);
        fs.push_back(band.lo);
        fs.push_back(band.hi);
        for (double f : s.frequency_hz)
            if (f > band.lo && f < band.hi) fs.push_back(f);
    }
    for (double f : fs) {
        const double a = s.psa_at(f);
        if (a > out.peak_psa_g || (a == out.peak_psa_g && f < out.peak_f_hz)) {
            out.peak_psa_g = a;
            out.peak_f_hz = f;
        }
    }
    // Strong content raises the flag whatever the PGA: a rigid classification that already
    // predicts uplift, or one that predicts sliding only (friction below tan(alpha)), says
    // nothing about the body's own mode, which can lift the base at its frequency either way
    // (docs/methods.md s.2, s.6 step 1).
    out.flagged = out.peak_psa_g >= out.threshold_g;
    const std::string where = fmt::format("peak PSA {:.4g} g at {:.4g} Hz in {}", out.peak_psa_g,
                                          out.peak_f_hz, describe(bands));
    if (!out.flagged)
        out.reason = fmt::format("{} < static uplift threshold {:.4g} g: no strong content",
                                 where, out.threshold_g);
    else if (in.pga_h_g >= out.threshold_g)
        out.reason = fmt::format("{} >= static uplift threshold {:.4g} g, and PGA {:.4g} g "
                                 "reaches it too: the body's own mode can lift the base beyond "
                                 "what the rigid classification shows",
                                 where, out.threshold_g, in.pga_h_g);
    else
        out.reason = fmt::format("{} >= static uplift threshold {:.4g} g while PGA {:.4g} g is "
                                 "below it: possible frequency-induced rocking of a flexible body",
                                 where, out.threshold_g, in.pga_h_g);
    return out;
}

}  // namespace freestand::rocking
