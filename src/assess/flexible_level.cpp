#include "assess/flexible_level.hpp"

#include <algorithm>
#include <array>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <vector>

#include "assess/level.hpp"
#include "assess/level_runs.hpp"
#include "assess/run_cache.hpp"

namespace freestand::assess {

std::optional<std::string> flexible_model_blocker(const Case& c) {
    if (!c.component.fixed_base_frequency_hz)
        return "the flag comes from the free-rocking band alone; the flexible-body model needs "
               "component.fixed_base_frequency_hz";
    if (c.options.simulate == SimulatePolicy::never)
        return "options.simulate = \"never\" forbids the flexible-body simulation";
    return std::nullopt;
}

bool flexible_model_decides(const Case& c, const FlexibleFlag& flag) {
    return flag.raised && !flexible_model_blocker(c);
}

dynamics::FlexibleModel flexible_model(const Component& comp, const ContactBound& contact,
                                       Direction d) {
    dynamics::FlexibleMode mode;
    mode.frequency_hz = comp.fixed_base_frequency_hz.value_or(0.0);
    mode.damping = comp.modal_damping.value_or(dynamics::default_modal_damping);
    mode.mass_fraction = comp.modal_mass_fraction;
    mode.height_m = comp.modal_height_m;
    return dynamics::make_flexible_model(block_model(comp, contact, d), mode);
}

namespace {

std::string model_reason(const LevelResult& level, const dynamics::FlexibleModel& m) {
    std::vector<std::string> defaults;
    if (m.mass_fraction_default) defaults.push_back("modal mass");
    if (m.height_default) defaults.push_back("modal height");
    return fmt::format(
        "the flexible-body flag is raised ({}): a body whose fixed-base frequency lies in the "
        "seismic band can uplift below g tan(alpha) (frequency-induced rocking), which a rigid "
        "block cannot show, so the flexible model decides and the rigid planar simulation is "
        "reported beside it; mode {:.3g} Hz, damping {:.3g}, modal mass {:.3g} M at {:.3g} m{}",
        level.flexible.basis, m.frequency_hz, m.damping, m.mass_fraction, m.height_m,
        defaults.empty() ? ""
                         : fmt::format(" ({}: uniform cantilever defaults)",
                                       fmt::join(defaults, " and ")));
}

}  // namespace

void simulate_flexible_level(const Case& c, LevelResult& level, double pga_g, HistoryBank& bank,
                             bool rocking_mode) {
    const Direction d = level.direction;
    const dynamics::FlexibleModel probe = flexible_model(c.component, level.bounds.rocking, d);
    // Slot bound_slots k + slot of history k's run at a bound slot (level.hpp HistoryRunner).
    constexpr auto slots = static_cast<std::size_t>(bound_slots);
    std::vector<dynamics::FlexibleSummary> runs(slots * bank.sets().size());
    std::vector<char> ran(runs.size(), 0);
    std::array<RunTable<dynamics::FlexibleSummary>*, slots> kept{};
    if (bank.level_runs())
        for (std::size_t b = 0; b < slots; ++b)
            kept[b] = &bank.level_runs()->flexible(d, static_cast<int>(b), bank.sets().size());
    const HistoryRunner run = [&](std::size_t k, int bound, const dynamics::BlockModel& rigid,
                                  const dynamics::Excitation& ex, const dynamics::Options& opt) {
        const auto b = static_cast<std::size_t>(bound);
        const std::size_t slot = slots * k + b;
        runs[slot] = remembered(kept[b], k, [&] {
            dynamics::FlexibleModel m = probe;
            m.rigid = rigid;
            return flexible_run(bank.run().run_cache, m, ex,
                                bank.excitation_key(k, static_cast<int>(d), pga_g, ex), opt);
        });
        ran[slot] = 1;
        return runs[slot].base;
    };
    FlexibleSimulation out;
    out.sim = simulate_level(c, level.bounds, d, pga_g, bank, rocking_mode, run);
    std::vector<double> modal, accel;
    for (std::size_t k = 0; k + slots <= runs.size(); k += slots) {
        double q = 0.0, a = 0.0;
        bool up = false;
        for (std::size_t j = k; j < k + slots; ++j) {
            if (!ran[j]) continue;
            q = std::max(q, runs[j].modal_max_m);
            a = std::max(a, runs[j].modal_accel_max_g);
            up = up || runs[j].uplifted;
        }
        modal.push_back(q);
        accel.push_back(a);
        if (up) ++out.uplifted;
    }
    out.modal_m = stats_of(modal);
    out.modal_accel_g = stats_of(accel);
    out.frequency_hz = probe.frequency_hz;
    out.damping = probe.damping;
    out.mass_fraction = probe.mass_fraction;
    out.height_m = probe.height_m;
    level.flexible_simulation = out;
    level.model = flexible_model_name;
    level.model_reason = model_reason(level, probe);
    level.simulation_reason =
        level.screen.passed
            ? "simulated because the flexible-body flag is raised: the flexible-body model runs "
              "over the level's histories and decides (docs/methods.md s.10); the rigid planar "
              "simulation is reported beside it"
            : "simulated: the screen failed and the flexible-body flag is raised, so the "
              "flexible-body model decides (docs/methods.md s.10); the rigid planar simulation "
              "is reported beside it";
}

}  // namespace freestand::assess
