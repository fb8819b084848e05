#include "assess/case.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "assess/materials.hpp"
#include "assess/overrides.hpp"
#include "assess/toml_reader.hpp"
#include "core/file_io.hpp"
#include "core/limits.hpp"
#include "core/units.hpp"
#include "dynamics/flexible.hpp"
#include "spectra/design.hpp"

namespace freestand::assess {

namespace {

constexpr double max_size_m = 100.0;
const Range positive_size{0.0, max_size_m, false, true};
const Range frequency_range{0.0, 1000.0, false, true};

const std::vector<std::string> component_keys{"name",
                                              "description",
                                              "mass_kg",
                                              "cg_height_m",
                                              "cg_to_edge_x_m",
                                              "cg_to_edge_y_m",
                                              "width_m",
                                              "depth_m",
                                              "height_m",
                                              "inertia_cg_x_kgm2",
                                              "inertia_cg_y_kgm2",
                                              "p_radps",
                                              "footprint",
                                              "fixed_base_frequency_hz",
                                              "modal_damping",
                                              "modal_mass_fraction",
                                              "modal_height_m",
                                              "free_rocking_band_hz",
                                              "free_rocking_band_x_hz",
                                              "free_rocking_band_y_hz",
                                              "base_material",
                                              "mu_s",
                                              "mu_k",
                                              "restitution",
                                              "mu_s_range",
                                              "restitution_range",
                                              "allowable_slide_m",
                                              "allowable_relative_m",
                                              "required_overturn_fs",
                                              "assumptions"};
const std::vector<std::string> site_keys{
    "design",        "target_h_file",   "target_h10_file", "target_y_file",   "target_y10_file",
    "target_v_file", "pga_g",           "vertical_ratio",  "sliding_damping", "g_mps2",
    "energy_highpass_hz", "energy_table_displacement_m", "va_range_mps_per_g", "adv2_range",
    "da_max_m_per_g", "dbe_pga_g"};
const std::vector<std::string> option_keys{"histories_per_level", "max_histories_per_level",
                                           "seed", "seed_records",
                                           "simulate", "fragility", "fragility_pga_g", "fragility_samples"};

const toml::table* subtable(const toml::table& root, const std::string& name,
                            const std::string& file) {
    const toml::node* n = root.get(name);
    if (n == nullptr) return nullptr;
    if (!n->is_table()) {
        throw InputError(SourceLocation{file, static_cast<int>(n->source().begin.line), name},
                         "expected a table [" + name + "]");
    }
    return n->as_table();
}

// Geometry: either CG height and distances to the edges (with the body's height when its CG is
// not at mid-height), or a uniform block's box.
void read_geometry(TableReader& r, Component& c) {
    const bool box = r.has("width_m") || r.has("depth_m");
    const bool general = r.has("cg_height_m") || r.has("cg_to_edge_x_m") || r.has("cg_to_edge_y_m");
    if (box && general) {
        r.fail(r.has("width_m") ? "width_m" : "depth_m",
               "give either width_m/depth_m/height_m (uniform block) or cg_height_m with "
               "cg_to_edge_x_m/cg_to_edge_y_m (and optional height_m), not both");
    }
    if (box || (r.has("height_m") && !general)) {
        const double w = r.required_number("width_m", positive_size);
        const double d = r.required_number("depth_m", positive_size);
        const double h = r.required_number("height_m", positive_size);
        c.uniform_block = true;
        c.cg_height_m = h / 2.0;
        c.height_m = h;
        c.x.b_left_m = c.x.b_right_m = w / 2.0;
        c.y.b_left_m = c.y.b_right_m = d / 2.0;
        return;
    }
    c.cg_height_m = r.required_number("cg_height_m", positive_size);
    // Above the CG (the top corners cannot lie below it), within the size limit.
    c.height_m = r.number("height_m", Range{c.cg_height_m, max_size_m, false, true});
    const auto bx = r.numbers("cg_to_edge_x_m", positive_size, 2);
    if (!bx)
        r.fail("cg_to_edge_x_m",
               "missing required key ([left, right] distances in m, each in (0, 100])");
    const auto by = r.numbers("cg_to_edge_y_m", positive_size, 2);
    if (!by)
        r.fail("cg_to_edge_y_m",
               "missing required key ([left, right] distances in m, each in (0, 100])");
    c.x.b_left_m = (*bx)[0];
    c.x.b_right_m = (*bx)[1];
    c.y.b_left_m = (*by)[0];
    c.y.b_right_m = (*by)[1];
}

// I_c of a uniform block filling the footprint and the body's height, about its own centre
// (docs/methods.md s.1); with the CG at mid-height, the block's own I_c.
double uniform_inertia(double mass_kg, const PlanarGeometry& g, double height_m) {
    return block::uniform_inertia_cg_kgm2(mass_kg, (g.b_left_m + g.b_right_m) / 2.0,
                                          height_m / 2.0);
}

// p_radps, one value for both directions or [p_x, p_y]. p^2 = M g R / I_O (docs/methods.md
// s.1), so I_O = M g R / p^2 and I_c = I_O - M R^2 > 0 needs p < sqrt(g / R), R about the
// critical (smaller-alpha) edge of the direction.
std::array<double, 2> read_p(TableReader& r, const Component& c) {
    std::array<double, 2> p_max{};
    for (const Direction d : {Direction::x, Direction::y}) {
        const block::Block b = c.block(d);
        p_max[d == Direction::x ? 0 : 1] = std::sqrt(units::g_mps2 / b.R_m(b.critical_edge()));
    }
    if (!r.holds_array("p_radps")) {
        const double p =
            *r.number("p_radps", Range{0.0, std::min(p_max[0], p_max[1]), false, false});
        return {p, p};
    }
    const std::vector<double> p =
        *r.numbers("p_radps", Range{0.0, std::max(p_max[0], p_max[1]), false, false}, 2);
    for (std::size_t i = 0; i < 2; ++i) {
        if (!(p[i] < p_max[i])) {
            r.fail("p_radps", fmt::format("p_{} = {} rad/s is out of range; expected (0, {:.4f}) "
                                          "(p < sqrt(g / R) of direction {}'s critical edge)",
                                          i == 0 ? "x" : "y", p[i], p_max[i], i == 0 ? "x" : "y"));
        }
    }
    return {p[0], p[1]};
}

void read_inertia(TableReader& r, Component& c, std::vector<std::string>& assumptions) {
    const bool given_i = r.has("inertia_cg_x_kgm2") || r.has("inertia_cg_y_kgm2");
    if (given_i && r.has("p_radps")) {
        r.fail("p_radps", "give either p_radps or inertia_cg_x_kgm2/inertia_cg_y_kgm2, not both");
    }
    if (given_i) {
        const Range range{0.0, 1e9, false, true};
        c.x.inertia_cg_kgm2 = r.required_number("inertia_cg_x_kgm2", range);
        c.y.inertia_cg_kgm2 = r.required_number("inertia_cg_y_kgm2", range);
        c.x.inertia_source = c.y.inertia_source = "case file";
        return;
    }
    if (r.has("p_radps")) {
        const std::array<double, 2> p = read_p(r, c);
        for (const Direction d : {Direction::x, Direction::y}) {
            PlanarGeometry& g = d == Direction::x ? c.x : c.y;
            const double p_d = p[d == Direction::x ? 0 : 1];
            const double b = std::min(g.b_left_m, g.b_right_m);
            const double R2 = b * b + c.cg_height_m * c.cg_height_m;
            const double i_edge = c.mass_kg * units::g_mps2 * std::sqrt(R2) / (p_d * p_d);
            g.inertia_cg_kgm2 = i_edge - c.mass_kg * R2;
            g.inertia_source = fmt::format("from p = {} rad/s: I_O = M g R / p^2", p_d);
        }
        return;
    }
    for (PlanarGeometry* g : {&c.x, &c.y}) {
        g->inertia_cg_kgm2 = uniform_inertia(c.mass_kg, *g, c.body_height_m());
        g->inertia_source = c.height_m && !c.uniform_block
                                ? "uniform block of the height given: I_c = M (b^2 + (H/2)^2) / 3"
                                : "uniform block: I_c = M (b^2 + h^2) / 3";
    }
    if (c.uniform_block) return;
    if (c.height_m) {
        // No parallel-axis term M (H/2 - h)^2: that would describe mass spread evenly over the
        // height, which a body with its CG off mid-height does not have; the centroidal value
        // is the smaller, so p (and the overturning capacity it measures) is not overstated.
        assumptions.push_back(fmt::format(
            "No inertia or p given: I_c taken as that of a uniform block of the same footprint "
            "and the body's height H = {:.3f} m about its own centre, I_c = M (b^2 + (H/2)^2) / "
            "3, with no parallel-axis term for the CG at {:.3f} m.",
            *c.height_m, c.cg_height_m));
    } else {
        assumptions.push_back(
            "No inertia or p given: I_c taken as that of a uniform block of the same footprint and "
            "twice the CG height, I_c = M (b^2 + h^2) / 3.");
    }
}

// A [lower, upper] pair within range, lower <= upper.
std::optional<std::array<double, 2>> read_bounds(TableReader& r, const std::string& key,
                                                 Range range) {
    const auto v = r.numbers(key, range, 2);
    if (!v) return std::nullopt;
    if ((*v)[0] > (*v)[1]) {
        r.fail(key, fmt::format("expected [lower, upper] with lower <= upper, got [{}, {}]",
                                (*v)[0], (*v)[1]));
    }
    return std::array<double, 2>{(*v)[0], (*v)[1]};
}

// Where the friction bounds come from: the case's range (which must hold the nominal value), or
// docs/methods.md s.7's default around the single measurement, stated as an assumption.
void read_friction_bounds(TableReader& r, BaseContact& base, bool mu_given, bool table_range,
                          std::vector<std::string>& assumptions) {
    const auto range = read_bounds(r, "mu_s_range", core::limits::friction);
    if (!range && table_range) {
        assumptions.push_back(fmt::format(
            "Friction bounds of {}: mu_s in [{:.3g}, {:.3g}] ({}); sliding demands use the lower "
            "bound, rocking, overturning and the classification the upper.",
            base.material, base.mu_s_range[0], base.mu_s_range[1], base.mu_s_range_source));
        return;
    }
    if (!range) {
        base.mu_s_range = default_mu_s_range(base.mu_s);
        base.mu_s_range_source = "default 0.8-1.2 x mu_s (docs/methods.md s.7)";
        assumptions.push_back(fmt::format(
            "Friction bounds not given: mu_s in [{:.3g}, {:.3g}], 0.8 and 1.2 times the single "
            "value {:.3g} (docs/methods.md s.7); sliding demands use the lower bound, rocking, "
            "overturning and the classification the upper.",
            base.mu_s_range[0], base.mu_s_range[1], base.mu_s));
        return;
    }
    base.mu_s_range = *range;
    base.mu_s_range_source = "case file (mu_s_range)";
    if (!mu_given) {
        // Only the range is known: its middle is the nominal value the report echoes.
        base.mu_s = (base.mu_s_range[0] + base.mu_s_range[1]) / 2.0;
        base.mu_k = base.mu_s;
    } else if (base.mu_s < base.mu_s_range[0] || base.mu_s > base.mu_s_range[1]) {
        r.fail("mu_s_range", fmt::format("mu_s = {} lies outside [{}, {}]", base.mu_s,
                                         base.mu_s_range[0], base.mu_s_range[1]));
    }
}

void read_base(TableReader& r, Component& c, std::vector<std::string>& assumptions) {
    const Range mu_range = core::limits::friction;
    const Range r_range = core::limits::restitution;
    const bool named = r.has("base_material");
    if (const auto name = r.string("base_material")) {
        const Material* m = find_material(*name);
        if (m == nullptr) {
            r.fail("base_material", fmt::format("unknown material \"{}\"; expected one of {}",
                                                *name, material_names()));
        }
        c.base = material_contact(*m);
    } else if (!r.has("mu_s") && !r.has("mu_s_range")) {
        r.fail("mu_s", fmt::format("missing required key (give base_material, one of {}, mu_s "
                                   "in [0, 2] or mu_s_range)",
                                   material_names()));
    } else {
        c.base.source = "case file";
    }
    const auto mu = r.number("mu_s", mu_range);
    if (mu) {
        if (named) c.base.source += "; mu_s from the case file";
        c.base.mu_s = *mu;
    }
    read_friction_bounds(r, c.base, mu.has_value() || named, named && !mu, assumptions);
    const auto mu_k = r.number("mu_k", Range{0.0, c.base.mu_s});
    c.base.mu_k = mu_k.value_or(c.base.mu_s);
    if (!mu_k) assumptions.push_back("mu_k not given: taken equal to mu_s.");
    if (const auto rest = r.number("restitution", r_range)) c.base.restitution = *rest;
    c.base.restitution_range = read_bounds(r, "restitution_range", r_range);
    if (c.base.restitution_range) {
        const auto& rr = *c.base.restitution_range;
        if (c.base.restitution && (*c.base.restitution < rr[0] || *c.base.restitution > rr[1])) {
            r.fail("restitution_range", fmt::format("restitution = {} lies outside [{}, {}]",
                                                    *c.base.restitution, rr[0], rr[1]));
        }
    } else if (c.base.restitution) {
        assumptions.push_back(fmt::format(
            "Restitution bounds not given: from Housner's r (Housner 1963) of each direction to "
            "the measured "
            "{:.3g} (docs/methods.md s.7); rocking and overturning use the upper bound.",
            *c.base.restitution));
    } else {
        assumptions.push_back(
            "No restitution given or tabulated: Housner's r = 1 - 2 M R^2 sin^2(alpha) / I_O "
            "(Housner 1963; docs/methods.md s.1) is both bounds.");
    }
}

// One free-rocking band [lo, hi], lo < hi.
std::optional<std::array<double, 2>> read_band(TableReader& r, const std::string& key) {
    const auto band = r.numbers(key, frequency_range, 2);
    if (!band) return std::nullopt;
    if ((*band)[0] >= (*band)[1]) {
        r.fail(key,
               fmt::format("expected [lo, hi] with lo < hi, got [{}, {}]", (*band)[0], (*band)[1]));
    }
    return std::array<double, 2>{(*band)[0], (*band)[1]};
}

// The free-rocking bands: one for both directions, or one per direction (measured rocking in
// each plane, e.g. Saraswat 2017 Table 5-2); a direction without one has no band.
void read_free_rocking(TableReader& r, Component& c) {
    const auto both = read_band(r, "free_rocking_band_hz");
    const auto x = read_band(r, "free_rocking_band_x_hz");
    const auto y = read_band(r, "free_rocking_band_y_hz");
    if (both && (x || y)) {
        r.fail(x ? "free_rocking_band_x_hz" : "free_rocking_band_y_hz",
               "give free_rocking_band_hz (both directions) or free_rocking_band_x_hz / "
               "free_rocking_band_y_hz (one per direction), not both");
    }
    c.x.free_rocking_band_hz = both ? both : x;
    c.y.free_rocking_band_hz = both ? both : y;
}

// The flexible body's mode (docs/methods.md s.10): its keys need the fixed-base frequency; the
// defaults are stated as assumptions.
void read_modal(TableReader& r, Component& c, std::vector<std::string>& assumptions) {
    c.modal_damping = r.number("modal_damping", Range{0.0, 1.0, true, false});
    c.modal_mass_fraction = r.number("modal_mass_fraction", Range{0.0, 1.0, false, false});
    c.modal_height_m = r.number("modal_height_m", positive_size);
    for (const char* key : {"modal_damping", "modal_mass_fraction", "modal_height_m"})
        if (r.has(key) && !c.fixed_base_frequency_hz)
            r.fail(key, "needs fixed_base_frequency_hz (the mode it describes)");
    if (!c.fixed_base_frequency_hz) return;
    dynamics::FlexibleMode mode;
    mode.frequency_hz = *c.fixed_base_frequency_hz;
    mode.mass_fraction = c.modal_mass_fraction;
    mode.height_m = c.modal_height_m;
    for (const Direction d : {Direction::x, Direction::y}) {
        try {
            dynamics::make_flexible_model(
                dynamics::make_block_model(c.block(d), 0.0, std::nullopt, std::nullopt,
                                           c.body_height_m()),
                mode);
        } catch (const InputError& e) {
            r.fail(c.modal_height_m ? "modal_height_m" : "modal_mass_fraction",
                   fmt::format("in the {} direction: {}", to_string(d), e.message()));
        }
    }
    std::vector<std::string> defaults;
    if (!c.modal_damping)
        defaults.push_back(fmt::format("modal damping {}", dynamics::default_modal_damping));
    if (!c.modal_mass_fraction)
        defaults.push_back(fmt::format("modal mass {} M (uniform cantilever, first mode)",
                                       dynamics::cantilever_modal_mass_fraction));
    if (!c.modal_height_m)
        defaults.push_back(fmt::format(
            "modal height {} x the body's height, {} = {:.3f} m (uniform cantilever)",
            dynamics::cantilever_modal_height_ratio,
            c.height_m ? fmt::format("{:.3f} m", *c.height_m) : "taken as 2 x the CG height",
            dynamics::cantilever_modal_height_ratio * c.body_height_m()));
    if (!defaults.empty())
        assumptions.push_back(fmt::format(
            "Flexible-body model (run where a flexible-body flag is raised): {}.",
            fmt::join(defaults, "; ")));
}

Component read_component(TableReader& r, std::vector<std::string>& assumptions) {
    Component c;
    // The case's own assumptions (data not published, chosen by the author) come first.
    for (const std::string& a : r.strings("assumptions").value_or(std::vector<std::string>{})) {
        assumptions.push_back("Case: " + a);
    }
    c.name = r.required_string("name");
    c.description = r.string("description").value_or("");
    c.mass_kg = r.required_number("mass_kg", core::limits::mass_kg);
    read_geometry(r, c);
    if (!c.height_m) {
        assumptions.push_back(fmt::format(
            "height_m not given: the body's top taken at twice the CG height, {:.3f} m (the point "
            "of the simulated top acceleration; docs/methods.md s.1).",
            c.body_height_m()));
    }
    read_inertia(r, c, assumptions);
    c.footprint = r.string("footprint").value_or("");
    c.fixed_base_frequency_hz = r.number("fixed_base_frequency_hz", frequency_range);
    read_modal(r, c, assumptions);
    read_free_rocking(r, c);
    read_base(r, c, assumptions);
    c.allowable_slide_m = r.required_number("allowable_slide_m", Range{0.0, 10.0, false, true});
    c.allowable_relative_m = r.number("allowable_relative_m", Range{0.0, 10.0, false, true});
    c.required_overturn_fs = r.number("required_overturn_fs", Range{1.0, 10.0}).value_or(1.5);
    r.finish(component_keys);
    return c;
}

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
    if (std::abs(t.spectrum.damping - expected_damping) > 1e-9) {
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

namespace {

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
    s.g_mps2 = r.number("g_mps2", Range{units::g_mps2, units::g_mps2}).value_or(units::g_mps2);
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

Options read_options(TableReader& r, const std::filesystem::path& case_dir) {
    Options o;
    o.histories_per_level = static_cast<int>(
        r.integer("histories_per_level", 1, histories_limit).value_or(o.histories_per_level));
    // docs/methods.md s.6 step 4: an unsettled level grows in batches of 30 sets up to this
    // cap, never below the sets it starts with.
    o.max_histories_per_level = static_cast<int>(
        r.integer("max_histories_per_level", o.histories_per_level, histories_limit)
            .value_or(std::max(o.histories_per_level, o.max_histories_per_level)));
    o.seed = static_cast<std::uint64_t>(r.integer("seed", 0, max_seed).value_or(1));
    if (const auto records = r.strings("seed_records")) {
        for (const std::string& rec : *records) {
            const std::filesystem::path p(rec);
            o.seed_records.push_back(p.is_absolute() ? p : case_dir / p);
        }
    }
    if (const auto sim = r.string("simulate")) {
        if (*sim == "auto") {
            o.simulate = SimulatePolicy::automatic;
        } else if (*sim == "always") {
            o.simulate = SimulatePolicy::always;
        } else if (*sim == "never") {
            o.simulate = SimulatePolicy::never;
        } else {
            r.fail("simulate", fmt::format("unknown value \"{}\"; expected \"auto\", \"always\" or "
                                           "\"never\"",
                                           *sim));
        }
    }
    o.fragility.enabled = r.boolean("fragility").value_or(false);
    o.fragility.pga_g = r.numbers("fragility_pga_g", core::limits::pga_level_g)
                            .value_or(std::vector<double>{0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7,
                                                          0.8, 0.9, 1.0});
    core::limits::require_pga_levels(o.fragility.pga_g, r.where("fragility_pga_g"));
    o.fragility.samples =
        static_cast<int>(r.integer("fragility_samples", 1, 100000).value_or(100));
    core::limits::require_within(
        static_cast<double>(o.fragility.pga_g.size()) * o.fragility.samples,
        core::limits::max_fragility_samples, r.where("fragility_samples"),
        "the fragility run's samples (levels x fragility_samples)");
    if (!o.fragility.enabled && (r.has("fragility_pga_g") || r.has("fragility_samples")))
        r.fail(r.has("fragility_pga_g") ? "fragility_pga_g" : "fragility_samples",
               "applies only with fragility = true");
    r.finish(option_keys);
    return o;
}

}  // namespace

const char* to_string(SimulatePolicy p) {
    switch (p) {
        case SimulatePolicy::automatic:
            return "auto";
        case SimulatePolicy::always:
            return "always";
        case SimulatePolicy::never:
            return "never";
    }
    return "auto";
}

block::Block Component::block(Direction d) const {
    const PlanarGeometry& g = plane(d);
    if (g.inertia_cg_kgm2 > 0.0) {
        return block::Block::general(g.b_left_m, g.b_right_m, cg_height_m, mass_kg,
                                     g.inertia_cg_kgm2);
    }
    // Before the inertia is known (while reading p_radps) only R and alpha are used.
    return block::Block::general(g.b_left_m, g.b_right_m, cg_height_m, mass_kg,
                                 uniform_inertia(mass_kg, g, body_height_m()));
}

std::array<double, 2> default_mu_s_range(double mu_s) { return {0.8 * mu_s, 1.2 * mu_s}; }

Case with_base_material(Case c, const std::string& material) {
    const Material* m = find_material(material);
    if (m == nullptr) throw std::invalid_argument("with_base_material: unknown " + material);
    // A case's own bounds for its own base stay (docs/methods.md s.6 step 7).
    const Material* own = find_material(c.component.base.material);
    if (own != m) c.component.base = material_contact(*m);
    return c;
}

namespace {

// One uncertain property: { dist = "uniform", lo, hi } or { dist = "lognormal", median, beta }.
core::Distribution read_distribution(TableReader& outer, const std::string& key, Range values,
                                     std::optional<double> truncate_at, const std::string& file) {
    TableReader r(outer.table(key), file, "uncertainty." + key);
    core::Distribution d;
    const std::string dist = r.required_string("dist");
    if (dist == "uniform") {
        d.a = r.required_number("lo", values);
        d.b = r.required_number("hi", values);
        if (d.b < d.a) r.fail("hi", fmt::format("{} is below lo = {}; expected lo <= hi", d.b, d.a));
        r.finish({"dist", "lo", "hi"});
        return d;
    }
    if (dist != "lognormal")
        r.fail("dist", fmt::format("\"{}\"; expected \"uniform\" or \"lognormal\"", dist));
    d.kind = core::Distribution::Kind::lognormal;
    d.a = r.required_number("median", Range{0.0, values.hi, false, true});
    d.b = r.required_number("beta", Range{0.0, 2.0, false, true});
    d.upper = truncate_at;
    r.finish({"dist", "median", "beta"});
    return d;
}

Uncertainty read_uncertainty(TableReader& r, const std::string& file) {
    Uncertainty u;
    // A drawn friction is a case's friction (core::limits::friction): a lognormal law is
    // truncated at its top, as restitution's at 1, so no sample leaves the model's range.
    if (r.has("mu_s"))
        u.mu_s = read_distribution(r, "mu_s", core::limits::friction, core::limits::friction.hi,
                                   file);
    if (r.has("restitution"))
        u.restitution = read_distribution(r, "restitution", Range{0.0, 1.0}, 1.0, file);
    r.finish({"mu_s", "restitution"});
    return u;
}

// Lines beyond core::limits::max_case_line_chars are refused before toml++ sees them.
void check_line_lengths(const std::string& text, const std::string& file_label) {
    int line = 1;
    for (std::size_t start = 0; start <= text.size(); ++line) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        if (end - start > core::limits::max_case_line_chars) {
            throw InputError(SourceLocation{file_label, line, ""},
                             fmt::format("line is {} characters long; a case file's lines are "
                                         "limited to {} (README, Limits)",
                                         end - start, core::limits::max_case_line_chars));
        }
        start = end + 1;
    }
}

int line_of(const toml::node& n) { return static_cast<int>(n.source().begin.line); }

// [[unit]] x 2 and [tunnel] (docs/methods.md s.10), each unit read as a [component].
void read_units(const toml::table& root, const toml::node& units, const std::string& file,
                Case& out) {
    const toml::array* arr = units.as_array();
    if (arr == nullptr || !arr->is_array_of_tables())
        throw InputError(SourceLocation{file, line_of(units), "unit"},
                         "expected [[unit]] tables (an array of tables)");
    if (root.get("component") != nullptr)
        throw InputError(SourceLocation{file, line_of(*root.get("component")), "component"},
                         "[component] and [[unit]] are exclusive: describe one component, or "
                         "two units joined by a [tunnel]");
    if (arr->size() != 2)
        throw InputError(SourceLocation{file, line_of(arr->back()), "unit"},
                         fmt::format("expected exactly two [[unit]] tables, got {}", arr->size()));
    for (std::size_t i = 0; i < arr->size(); ++i) {
        const std::string name = fmt::format("unit[{}]", i + 1);
        TableReader r((*arr)[i].as_table(), file, name);
        if (r.has("allowable_relative_m"))
            r.fail("allowable_relative_m", "give the relative allowable once, in [tunnel]");
        out.units.push_back(read_component(r, out.assumptions));
    }
    const toml::table* tunnel = subtable(root, "tunnel", file);
    if (tunnel == nullptr)
        throw InputError(SourceLocation{file, 0, "tunnel"},
                         "missing required table [tunnel] (height_m, allowable_relative_m) for "
                         "the two [[unit]] tables");
    TableReader rt(tunnel, file, "tunnel");
    Tunnel t;
    t.height_m = rt.required_number("height_m", Range{0.0, 100.0});
    t.allowable_relative_m =
        rt.required_number("allowable_relative_m", Range{0.0, 10.0, false, true});
    rt.finish({"height_m", "allowable_relative_m"});
    out.tunnel = t;
}

}  // namespace

Case parse_case(const std::string& text, const std::string& file_label) {
    return parse_case(text, file_label, CaseOverrides{});
}

Case parse_case(const std::string& text, const std::string& file_label,
                const CaseOverrides& overrides) {
    check_line_lengths(text, file_label);
    toml::table root = parse_toml(text, file_label);
    apply_overrides(root, overrides);
    Case out;
    out.file = file_label;
    for (const auto& [k, node] : root) {
        const std::string key(k.str());
        if (key != "component" && key != "site" && key != "options" && key != "uncertainty" &&
            key != "unit" && key != "tunnel") {
            throw InputError(
                SourceLocation{file_label, static_cast<int>(node.source().begin.line), key},
                "unknown table; allowed tables: [component] (or two [[unit]] and a [tunnel]), "
                "[site], [options], [uncertainty]");
        }
    }
    const toml::table* comp = subtable(root, "component", file_label);
    const toml::table* site = subtable(root, "site", file_label);
    if (const toml::node* units = root.get("unit")) {
        read_units(root, *units, file_label, out);
    } else if (const toml::node* tunnel = root.get("tunnel")) {
        throw InputError(SourceLocation{file_label, line_of(*tunnel), "tunnel"},
                         "[tunnel] joins two [[unit]] tables; a [component] has none (a braced "
                         "pair is one component: give allowable_relative_m there)");
    } else if (comp == nullptr) {
        throw InputError(SourceLocation{file_label, 0, "component"},
                         "missing required table [component] (or two [[unit]] and a [tunnel])");
    }
    if (site == nullptr)
        throw InputError(SourceLocation{file_label, 0, "site"}, "missing required table [site]");
    if (out.units.empty()) {
        TableReader rc(comp, file_label, "component");
        out.component = read_component(rc, out.assumptions);
    }
    TableReader rs(site, file_label, "site");
    out.site = read_site(rs, out.assumptions, std::filesystem::path(file_label).parent_path());
    if (out.site.dbe_pga_g && !out.units.empty())
        rs.fail("dbe_pga_g",
                "the performance goal runs the fragility engine, which takes one "
                "component, not two [[unit]] tables");
    TableReader ro(subtable(root, "options", file_label), file_label, "options");
    out.options = read_options(ro, std::filesystem::path(file_label).parent_path());
    TableReader ru(subtable(root, "uncertainty", file_label), file_label, "uncertainty");
    out.uncertainty = read_uncertainty(ru, file_label);
    return out;
}

Case read_case(const std::filesystem::path& path) {
    return parse_case(core::read_input_file(path), path.string());
}

}  // namespace freestand::assess
