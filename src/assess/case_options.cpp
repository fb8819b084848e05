// [options] of a case file: histories per level, seeds, the simulation policy and the fragility
// run (docs/methods.md s.6).
#include "assess/case_detail.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>

#include "assess/overrides.hpp"
#include "core/limits.hpp"

namespace freestand::assess {

namespace {

const std::vector<std::string> option_keys{"histories_per_level", "max_histories_per_level",
                                           "seed", "seed_records",
                                           "simulate", "fragility", "fragility_pga_g", "fragility_samples"};

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

namespace case_detail {

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

}  // namespace case_detail

}  // namespace freestand::assess
