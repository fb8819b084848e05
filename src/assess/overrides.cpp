#include "assess/overrides.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "assess/materials.hpp"
#include "assess/toml_reader_detail.hpp"
#include "core/limits.hpp"

namespace freestand::assess {

namespace {

// The case file's keys of the base description a material replaces (case.cpp read_base).
const std::vector<std::string> base_keys{"base_material", "mu_s", "mu_k", "restitution",
                                         "mu_s_range", "restitution_range"};

// The table named key of root, created when absent; nullptr when key holds something else
// (the case reader then reports it).
toml::table* table_of(toml::table& root, const std::string& key) {
    if (!root.contains(key)) root.insert(key, toml::table{});
    return root.get(key)->as_table();
}

void check_integer(long long v, long long lo, long long hi, const SourceLocation& where) {
    if (v < lo || v > hi) {
        throw InputError(where, fmt::format("value {} is out of range; expected an integer in "
                                            "[{}, {}]",
                                            v, lo, hi));
    }
}

}  // namespace

void check_overrides(const CaseOverrides& o,
                     const std::function<SourceLocation(const std::string& key)>& where) {
    if (o.pga_g) {
        core::limits::require_pga_levels(*o.pga_g, where("pga_g"));
    }
    if (o.base_material && find_material(*o.base_material) == nullptr) {
        throw InputError(where("base_material"),
                         fmt::format("unknown material \"{}\"; expected one of {}",
                                     *o.base_material, material_names()));
    }
    if (o.seed) check_integer(*o.seed, 0, max_seed, where("seed"));
    if (o.histories_per_level)
        check_integer(*o.histories_per_level, 1, histories_limit,
                      where("histories_per_level"));
}

void apply_overrides(toml::table& root, const CaseOverrides& o) {
    if (o.base_material) {
        if (toml::table* c = table_of(root, "component")) {
            for (const std::string& k : base_keys) c->erase(k);
            c->insert("base_material", *o.base_material);
        }
    }
    if (o.pga_g) {
        if (toml::table* s = table_of(root, "site")) {
            toml::array levels;
            for (double p : *o.pga_g) levels.push_back(p);
            s->insert_or_assign("pga_g", std::move(levels));
        }
    }
    if (o.seed || o.histories_per_level) {
        if (toml::table* opt = table_of(root, "options")) {
            if (o.seed) opt->insert_or_assign("seed", static_cast<std::int64_t>(*o.seed));
            if (o.histories_per_level)
                opt->insert_or_assign("histories_per_level",
                                      static_cast<std::int64_t>(*o.histories_per_level));
        }
    }
}

std::string describe(const CaseOverrides& o) {
    std::vector<std::string> parts;
    if (o.pga_g) parts.push_back(fmt::format("pga_g = [{}]", fmt::join(*o.pga_g, ", ")));
    if (o.base_material) parts.push_back(fmt::format("base_material = \"{}\"", *o.base_material));
    if (o.seed) parts.push_back(fmt::format("seed = {}", *o.seed));
    if (o.histories_per_level)
        parts.push_back(fmt::format("histories_per_level = {}", *o.histories_per_level));
    return fmt::format("{}", fmt::join(parts, "; "));
}

}  // namespace freestand::assess
