#include "rocking/summary.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "core/errors.hpp"

namespace freestand::rocking {

using block::Block;
using block::Edge;

namespace {

// Damping at which the Housner spectral velocity and the flexible screen read the spectra.
constexpr double design_damping = 0.05;

EdgeChecks geometry(const Block& blk, Edge e, const RockingInput& in, double pga_v_g) {
    EdgeChecks c;
    c.edge = e;
    c.alpha_rad = blk.alpha_rad(e);
    c.tan_alpha = blk.tan_alpha(e);
    c.R_m = blk.R_m(e);
    c.p_radps = blk.p_radps(e);
    c.inertia_edge_kgm2 = blk.inertia_edge_kgm2(e);
    c.restitution = in.restitution.value_or(blk.housner_restitution(e));
    c.uplift_a_g = uplift_threshold_g(blk, e, pga_v_g);
    c.ishiyama_v_mps = ishiyama_velocity_mps(blk, e);
    c.e_ot_jpkg = overturning_energy_jpkg(blk, e);
    return c;
}

void resolve_peaks(const RockingInput& in, RockingChecks& out) {
    if (in.pga_h_g) {
        require_in_range(*in.pga_h_g, 0.0, HUGE_VAL, SourceLocation{"", 0, "pga_h_g"}, true, false);
        out.pga_h_g = in.pga_h_g;
        out.pga_h_source = "given";
    } else if (in.horizontal) {
        out.pga_h_g = in.horizontal->zpa_g();
        const double f = in.horizontal->zpa_frequency_hz();
        // Below the rigid frequency the last point may still be amplified: say so.
        out.pga_h_source =
            f >= rigid_frequency_hz
                ? "spectrum ZPA"
                : fmt::format("spectrum PSA at its highest frequency, {} Hz < {} Hz: may exceed "
                              "the PGA; give the PGA explicitly",
                              f, rigid_frequency_hz);
    }
    if (in.pga_v_g) {
        out.pga_v_g = *in.pga_v_g;
        out.pga_v_source = "given";
    } else if (in.vertical.spectra) {
        out.pga_v_g = in.vertical.spectra->zpa_g();
        out.pga_v_source = "vertical spectrum ZPA";
    } else if (in.vertical.ratio > 0.0 && out.pga_h_g) {
        out.pga_v_g = in.vertical.ratio * *out.pga_h_g;
        out.pga_v_source = fmt::format("{} x PGA_h", in.vertical.ratio);
    } else {
        out.pga_v_source = "none given";
    }
    require_in_range(out.pga_v_g, 0.0, 1.0, SourceLocation{"", 0, "pga_v_g"}, true, false);
}

void spectral_checks(const Block& blk, const RockingInput& in, RockingChecks& out) {
    if (!in.horizontal) {
        out.spectral_reason = "needs a horizontal spectrum";
        out.flexible_reason = "needs a horizontal spectrum";
        return;
    }
    const DampedDemand d5 = in.horizontal->at(design_damping);
    out.housner_sv_mps = peak_pseudo_velocity_mps(d5);
    ElOptions o;
    o.pga_h_g = out.pga_h_g;
    o.pga_v_g = out.pga_v_g;
    o.restitution = in.restitution;
    o.fs_required = in.fs_required;
    const ElBlockResult el = equivalent_linear_rocking(blk, *in.horizontal, in.vertical, o);
    out.left.el = el.left;
    out.right.el = el.right;
    out.left.housner = housner_energy(blk, Edge::left, *out.housner_sv_mps);
    out.right.housner = housner_energy(blk, Edge::right, *out.housner_sv_mps);
    out.governing_edge = el.governing_edge;
    if (!in.fixed_base_hz && !in.rock_band_lo_hz && !in.rock_band_hi_hz) {
        out.flexible_reason = "needs a fixed-base frequency or a free-rocking band";
        return;
    }
    FlexibleInput fi;
    fi.fixed_base_hz = in.fixed_base_hz;
    fi.rock_band_lo_hz = in.rock_band_lo_hz;
    fi.rock_band_hi_hz = in.rock_band_hi_hz;
    fi.uplift_threshold_g = std::min(out.left.uplift_a_g, out.right.uplift_a_g);
    fi.pga_h_g = out.pga_h_g.value_or(0.0);
    spectra::Spectrum s5 = d5.lo;
    // The screen reads psa_at on a spectrum: rebuild the 5% demand on its own points.
    for (std::size_t i = 0; i < s5.frequency_hz.size(); ++i) s5.psa_g[i] = d5.psa_g(s5.frequency_hz[i]);
    s5.damping = design_damping;
    out.flexible = flexible_screen(s5, fi);
}

}  // namespace

RockingChecks rocking_checks(const Block& blk, const RockingInput& in) {
    RockingChecks out;
    resolve_peaks(in, out);
    out.left = geometry(blk, Edge::left, in, out.pga_v_g);
    out.right = geometry(blk, Edge::right, in, out.pga_v_g);
    out.governing_edge = blk.critical_edge();
    spectral_checks(blk, in, out);
    if (in.pgv_mps) {
        require_in_range(*in.pgv_mps, 0.0, HUGE_VAL, SourceLocation{"", 0, "pgv_mps"}, true, false);
        // The bound of the edge that overturns most easily.
        out.pgv_below_ishiyama =
            *in.pgv_mps < std::min(out.left.ishiyama_v_mps, out.right.ishiyama_v_mps);
    } else {
        out.pgv_reason = "needs the peak ground velocity";
    }
    if (in.mu_s && out.pga_h_g) {
        out.initiation = sliding::classify_peak(blk, *in.mu_s, *out.pga_h_g, out.pga_v_g);
        const auto& gi = out.initiation->governing();
        out.amplification_warning = amplification_warning(gi.mode, *in.mu_s, gi.A);
    } else {
        out.initiation_reason = in.mu_s ? "needs the peak horizontal acceleration (or a spectrum)"
                                        : "needs the static friction mu";
    }
    return out;
}

}  // namespace freestand::rocking
