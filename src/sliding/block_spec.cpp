#include "sliding/block_spec.hpp"

#include <cmath>
#include <fmt/format.h>
#include <map>

#include "core/errors.hpp"

namespace freestand::sliding {

namespace {

// block::Block names its own quantities; a box's caller gave them as these fields. A uniform
// box's CG height is its half-height.
std::string box_field(const std::string& block_field, bool uniform) {
    static const std::map<std::string, std::string> general{
        {"b (half-width, m)", "box.half_width_m"},
        {"h (CG height, m)", "box.cg_height_m"},
        {"m (mass, kg)", "box.mass_kg"},
        {"I_c (inertia about CG, kg m^2)", "box.inertia_cg_kgm2"},
        {"b_left (CG to left edge, m)", "box.cg_offset_m"},
        {"b_right (CG to right edge, m)", "box.cg_offset_m"},
    };
    if (uniform && block_field == "h (CG height, m)") return "box.half_height_m";
    const auto it = general.find(block_field);
    return it == general.end() ? block_field : it->second;
}

block::Block checked_block(const BoxSpec& spec) {
    require_positive(spec.half_width_m, SourceLocation{"", 0, "box.half_width_m"});
    require_positive(spec.half_height_m, SourceLocation{"", 0, "box.half_height_m"});
    const bool has_cg = spec.cg_offset_m || spec.cg_height_m;
    if (!has_cg && !spec.inertia_cg_kgm2)
        return block::Block::uniform(spec.half_width_m, spec.half_height_m,
                                     spec.mass_kg.value_or(1.0));
    if (!spec.inertia_cg_kgm2)
        throw InputError(SourceLocation{"", 0, "box.inertia_cg_kgm2"},
                         "a CG position away from the box centre needs the inertia I_c about the "
                         "CG (kg m^2); a uniform-box default would be wrong");
    if (!spec.mass_kg)
        throw InputError(SourceLocation{"", 0, "box.mass_kg"},
                         "an explicit inertia needs the mass m (kg): I_O = I_c + M R^2");
    const double x = spec.cg_offset_m.value_or(0.0);
    require_in_range(x, -spec.half_width_m, spec.half_width_m,
                     SourceLocation{"", 0, "box.cg_offset_m"}, false, false);
    const double h = spec.cg_height_m.value_or(spec.half_height_m);
    require_positive(h, SourceLocation{"", 0, "box.cg_height_m"});
    return block::Block::general(spec.half_width_m + x, spec.half_width_m - x, h, *spec.mass_kg,
                                 *spec.inertia_cg_kgm2);
}

}  // namespace

block::Block make_block(const BoxSpec& spec) {
    try {
        return checked_block(spec);
    } catch (const InputError& e) {
        const SourceLocation& w = e.where();
        if (!w.file.empty() || w.line != 0) throw;
        const bool uniform = !spec.cg_offset_m && !spec.cg_height_m && !spec.inertia_cg_kgm2;
        const std::string field = box_field(w.field, uniform);
        if (field == w.field) throw;
        throw InputError(SourceLocation{"", 0, field}, e.message());
    }
}

namespace {

std::optional<double> key(const std::map<std::string, double>& m, const std::string& k) {
    const auto it = m.find(k);
    return it == m.end() ? std::nullopt : std::optional<double>(it->second);
}

double required_key(const std::map<std::string, double>& m, const std::string& k,
                    const char* what) {
    const auto v = key(m, k);
    if (!v) throw InputError(SourceLocation{"", 0, "block " + k}, fmt::format("missing; expected {}", what));
    return *v;
}

}  // namespace

BoxSpec box_spec(const std::map<std::string, double>& box, const std::map<std::string, double>& cg,
                 std::optional<double> inertia_cg_kgm2) {
    BoxSpec s;
    s.half_width_m = required_key(box, "b", "the half-width b=... (m)");
    s.half_height_m = required_key(box, "h", "the half-height h=... (m)");
    s.mass_kg = key(box, "m");
    s.cg_offset_m = key(cg, "x");
    s.cg_height_m = key(cg, "h");
    s.inertia_cg_kgm2 = inertia_cg_kgm2;
    return s;
}

}  // namespace freestand::sliding
