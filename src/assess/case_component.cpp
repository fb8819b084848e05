// [component] of a case file (and each [[unit]]): geometry, inertia, the flexible mode, free-rocking
// bands, the base contact and the allowables (README, "Case files"; docs/methods.md s.1, s.7, s.10).
#include "assess/case_detail.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "assess/materials.hpp"
#include "core/limits.hpp"
#include "core/units.hpp"
#include "dynamics/flexible.hpp"

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
std::array<double, 2> read_p(TableReader& r, const Component& c, double g_mps2) {
    std::array<double, 2> p_max{};
    for (const Direction d : {Direction::x, Direction::y}) {
        const block::Block b = c.block(d);
        p_max[d == Direction::x ? 0 : 1] = std::sqrt(g_mps2 / b.R_m(b.critical_edge()));
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

void read_inertia(TableReader& r, Component& c, std::vector<std::string>& assumptions,
                  double g_mps2) {
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
        const std::array<double, 2> p = read_p(r, c, g_mps2);
        for (const Direction d : {Direction::x, Direction::y}) {
            PlanarGeometry& g = d == Direction::x ? c.x : c.y;
            const double p_d = p[d == Direction::x ? 0 : 1];
            const double b = std::min(g.b_left_m, g.b_right_m);
            const double R2 = b * b + c.cg_height_m * c.cg_height_m;
            const double i_edge = c.mass_kg * g_mps2 * std::sqrt(R2) / (p_d * p_d);
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

}  // namespace

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


namespace case_detail {

Component read_component(TableReader& r, std::vector<std::string>& assumptions, double g_mps2) {
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
    read_inertia(r, c, assumptions, g_mps2);
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

}  // namespace case_detail

}  // namespace freestand::assess
