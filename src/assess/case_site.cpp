// [site] of a case file: the design spectrum or target files, PGA levels, the vertical ratio, the
// energy method's displacement and the histories' realism ranges (docs/methods.md s.4, s.8).
#include "assess/case_detail.hpp"

#include <fmt/format.h>

#include <cmath>

#include "core/limits.hpp"
#include "core/tolerances.hpp"
#include "core/units.hpp"
#include "spectra/design.hpp"

namespace freestand::assess {

namespace {

const std::vector<std::string> site_keys{
    "design",        "target_h_file",   "target_h10_file", "target_y_file",   "target_y10_file",
    "target_v_file", "pga_g",           "vertical_ratio",  "sliding_damping", "g_mps2",
    "energy_highpass_hz", "energy_table_displacement_m", "va_range_mps_per_g", "adv2_range",
    "da_max_m_per_g", "dbe_pga_g"};

// Reads one target file named by key (path relative to the case's folder) and checks its
// damping; any problem is reported at the case's key with the file's own message.
std::optional<TargetFile> read_target(TableReader& r, const std::string& key,
                                      double expected_damping,
                                      const std::filesystem::path& case_dir) {
    const auto given = r.string(key);
    if (!given) return std::nullopt;
    const std::filesystem::path p(*given);
    TargetFile t;
    t.given = *given;
    try {
        t.spectrum = spectra::read_spectrum_csv(p.is_absolute() ? p : case_dir / p);
    } catch (const Error& e) {
        r.fail(key, fmt::format("cannot use target file \"{}\": {}", *given, e.what()));
    }
    if (std::abs(t.spectrum.damping - expected_damping) > core::tol::damping_equal) {
        r.fail(key, fmt::format("target file \"{}\" has damping {}; expected {}", *given,
                                t.spectrum.damping, expected_damping));
    }
    return t;
}

// Direction y's files pair with x's: the 10% files come for both directions or for neither,
// so SA_VH combines the two directions at the same dampings.
void check_y_keys(TableReader& r) {
    if (r.has("target_y10_file") && !r.has("target_y_file")) {
        r.fail("target_y10_file", "needs target_y_file (the 5% target of direction y)");
    }
    if (r.has("target_y10_file") && !r.has("target_h10_file")) {
        r.fail("target_y10_file", "needs target_h10_file (the 10% target of direction x)");
    }
    if (r.has("target_y_file") && r.has("target_h10_file") && !r.has("target_y10_file")) {
        r.fail("target_y_file", "target_h10_file is given, so direction y needs its 10% file "
                                "target_y10_file too");
    }
}

std::optional<UserTargets> read_targets(TableReader& r, const std::filesystem::path& case_dir) {
    const bool any = r.has("target_h_file") || r.has("target_h10_file") ||
                     r.has("target_y_file") || r.has("target_y10_file") || r.has("target_v_file");
    if (!any) return std::nullopt;
    if (r.has("design")) {
        r.fail("design", "design and target files are not used together; give either design = "
                         "\"rg1.60\" or target_h_file (with optional target_h10_file, "
                         "target_v_file)");
    }
    if (!r.has("target_h_file")) {
        r.fail("target_h_file",
               "missing required key: target_h10_file / target_y_file / target_y10_file / "
               "target_v_file need the 5% horizontal target_h_file");
    }
    check_y_keys(r);
    UserTargets u;
    u.h5 = *read_target(r, "target_h_file", 0.05, case_dir);
    u.h10 = read_target(r, "target_h10_file", 0.10, case_dir);
    u.v = read_target(r, "target_v_file", 0.05, case_dir);
    u.y5 = read_target(r, "target_y_file", 0.05, case_dir);
    u.y10 = read_target(r, "target_y10_file", 0.10, case_dir);
    u.zpa_h_g = u.h5.spectrum.psa_g.back();
    if (u.v && r.has("vertical_ratio")) {
        r.fail("vertical_ratio", "vertical_ratio and target_v_file are not used together (the "
                                 "vertical file sets the vertical/horizontal ratio)");
    }
    return u;
}

// DeltaD of the energy method: a table per level, or the histories high-passed at a corner.
void read_energy_displacement(TableReader& r, Site& s, std::vector<std::string>& assumptions) {
    const auto corner = r.number("energy_highpass_hz", Range{0.0, 10.0, false, true});
    s.energy_highpass_hz = corner.value_or(0.5);
    s.energy_table_displacement_m =
        r.numbers("energy_table_displacement_m", Range{0.0, 10.0, false, true});
    if (s.energy_table_displacement_m) {
        if (corner) {
            r.fail("energy_highpass_hz", "energy_highpass_hz and energy_table_displacement_m "
                                         "are not used together (the table replaces the "
                                         "high-passed histories)");
        }
        if (s.energy_table_displacement_m->size() != s.pga_g.size()) {
            r.fail("energy_table_displacement_m",
                   fmt::format("expected one displacement per PGA level ({}), got {}",
                               s.pga_g.size(), s.energy_table_displacement_m->size()));
        }
        return;
    }
    if (!corner) {
        assumptions.push_back(
            "energy_highpass_hz not given: the energy method's DeltaD is the mean of the "
            "histories' peak displacements after a zero-phase 0.5 Hz high-pass (the lower edge "
            "of the thesis's 0.5-50 Hz test band, Saraswat 2017; docs/methods.md s.4).");
    }
}

// The realism ranges of the histories: RG 1.60's for the RG 1.60 design, none of the ratio
// ranges for target files (the earthquakes behind them are not known), each key overriding.
void read_realism(TableReader& r, Site& s, std::vector<std::string>& assumptions) {
    s.realism = s.targets ? motion::RealismLimits{} : motion::rg160_realism();
    const Range positive{0.0, 1e3, false, true};
    const auto range = [&](const char* key) -> std::optional<motion::Range> {
        const auto v = r.numbers(key, positive, 2);
        if (!v) return std::nullopt;
        if (!((*v)[0] < (*v)[1]))
            r.fail(key, fmt::format("[{}, {}]: expected [min, max] with min < max", (*v)[0],
                                    (*v)[1]));
        return motion::Range{(*v)[0], (*v)[1]};
    };
    if (const auto va = range("va_range_mps_per_g")) s.realism.va_mps_per_g = va;
    if (const auto adv2 = range("adv2_range")) s.realism.adv2 = adv2;
    if (const auto da = r.number("da_max_m_per_g", positive)) s.realism.da_max_m_per_g = da;
    if (s.targets && !r.has("va_range_mps_per_g") && !r.has("adv2_range") &&
        !r.has("da_max_m_per_g")) {
        assumptions.push_back(
            "Realism of the histories against target files: PGA within 1.0-1.1 x the target's "
            "zero-period acceleration and D5-75 >= 6 s are checked; V/A, AD/V^2 and D/A are "
            "reported, not checked, until [site] va_range_mps_per_g, adv2_range, "
            "da_max_m_per_g give the ranges of the earthquakes behind the targets "
            "(docs/methods.md s.8).");
    }
}


// The RG 1.60 vertical target, as the report states it (docs/methods.md s.8).
std::string rg160_vertical_assumption(bool ratio_given, double ratio) {
    const std::string shape =
        "RG 1.60's vertical design spectrum (2/3 of the horizontal below 0.25 Hz, equal to it "
        "above 3.5 Hz; RG 1.60 Rev. 2, docs/methods.md s.8)";
    if (ratio_given) {
        return fmt::format(
            "Vertical histories matched to {} scaled to a zero-period "
            "acceleration of vertical_ratio = {:.4f} x the horizontal PGA.",
            shape, ratio);
    }
    return fmt::format(
        "vertical_ratio not given: vertical histories matched to {}, whose "
        "zero-period acceleration is the horizontal PGA: vertical PGA = {:.4g} x "
        "horizontal.",
        shape, ratio);
}

}  // namespace

std::optional<std::string> weightless_level(const std::vector<double>& pga_g,
                                            double vertical_ratio) {
    for (double pga : pga_g) {
        if (pga * vertical_ratio < 1.0) continue;
        return fmt::format("PGA {} g with a vertical/horizontal ratio of {:.4g} gives a vertical "
                           "PGA of {:.4g} g; at 1 g or more, taken downward as the static checks "
                           "take it, the block is weightless: each level needs pga_g x ratio < 1",
                           pga, vertical_ratio, pga * vertical_ratio);
    }
    return std::nullopt;
}

namespace case_detail {

double read_gravity_mps2(TableReader& r) {
    // Earth's surface gravity runs from 9.780 m/s^2 at the equator to 9.832 at the poles
    // (docs/methods.md, Conventions): anything outside is a typo or another unit.
    return r.number("g_mps2", Range{9.78, 9.84}).value_or(units::g_mps2);
}

Site read_site(TableReader& r, std::vector<std::string>& assumptions,
               const std::filesystem::path& case_dir) {
    Site s;
    s.targets = read_targets(r, case_dir);
    if (s.targets) s.design = "user target files";
    if (const auto design = r.string("design")) {
        if (*design != "rg1.60") {
            r.fail("design",
                   fmt::format("unknown design spectrum \"{}\"; expected \"rg1.60\"", *design));
        }
        s.design = *design;
    }
    const auto pga = r.numbers("pga_g", core::limits::pga_level_g);
    if (!pga)
        r.fail("pga_g", fmt::format("missing required key (a non-empty array of numbers in {})",
                                    describe(core::limits::pga_level_g)));
    core::limits::require_pga_levels(*pga, r.where("pga_g"));
    s.pga_g = *pga;
    // (0, 1.5]: the vertical history is matched to a target scaled by the ratio, so 0 leaves it
    // nothing to match.
    const Range ratio_range{0.0, 1.5, false, true};
    const auto ratio = r.number("vertical_ratio", ratio_range);
    s.vertical_ratio = ratio.value_or(s.targets ? 2.0 / 3.0 : spectra::rg160_vertical_zpa_ratio);
    if (s.targets && s.targets->v) {
        // The vertical file's rigid-limit PSA over the horizontal one's is the PGA ratio.
        s.vertical_ratio = s.targets->v->spectrum.psa_g.back() / s.targets->zpa_h_g;
        if (!(s.vertical_ratio > ratio_range.lo && s.vertical_ratio <= ratio_range.hi)) {
            r.fail("target_v_file",
                   fmt::format("the vertical file's last PSA over the horizontal file's gives a "
                               "vertical/horizontal PGA ratio of {:.4g}; expected {} as for "
                               "vertical_ratio",
                               s.vertical_ratio, describe(ratio_range)));
        }
    } else if (s.targets && !ratio) {
        assumptions.push_back("vertical_ratio not given: vertical PGA = 2/3 of horizontal.");
    } else if (!s.targets) {
        assumptions.push_back(rg160_vertical_assumption(ratio.has_value(), s.vertical_ratio));
    }
    if (const auto bad = weightless_level(s.pga_g, s.vertical_ratio)) {
        r.fail("pga_g", *bad + (s.targets || ratio ? ""
                                                   : " (RG 1.60's vertical ZPA equals "
                                                     "the horizontal PGA; vertical_ratio "
                                                     "scales its vertical spectrum)"));
    }
    // RG 1.60 tabulates 0.5% to 10%; the design function interpolates inside that range only.
    s.sliding_damping = r.number("sliding_damping", Range{0.005, 0.10}).value_or(0.10);
    s.g_mps2 = read_gravity_mps2(r);
    read_energy_displacement(r, s, assumptions);
    read_realism(r, s, assumptions);
    s.dbe_pga_g = r.number("dbe_pga_g", core::limits::pga_level_g);
    if (s.dbe_pga_g)
        assumptions.push_back(fmt::format(
            "Design-basis earthquake (DBE) PGA {:g} g (site.dbe_pga_g): the ASCE 43-05 s.1.3 "
            "performance goal is checked at the DBE and at 1.5 x DBE (docs/methods.md s.6 step "
            "5).",
            *s.dbe_pga_g));
    r.finish(site_keys);
    return s;
}

}  // namespace case_detail

}  // namespace freestand::assess
