#include <algorithm>
#include <stdexcept>

#include "core/statistics.hpp"
#include "fragility/fit.hpp"
#include "fragility/fragility.hpp"

namespace freestand::fragility {
namespace {

bool failed(const SampleResult& s, Event e, const Meta& m) {
    const bool overturn = s.overturned;
    const bool slide = s.slide_max_m > m.allowable_slide_m;
    // theta/alpha above 1/FS_required is the equivalent of alpha/theta below FS (s.5a, s.9).
    const bool rock = overturn || s.rock_max_over_alpha > 1.0 / m.required_overturn_fs;
    switch (e) {
        case Event::overturn:
            return overturn;
        case Event::slide:
            return slide;
        case Event::rock:
            return rock;
        case Event::any:
            return overturn || slide || rock;
    }
    return false;
}

}  // namespace

Result aggregate(const Meta& meta, std::vector<SampleResult> samples) {
    const std::size_t levels = meta.config.pga_g.size();
    const auto per_level = static_cast<std::size_t>(meta.config.samples);
    std::sort(samples.begin(), samples.end(), [](const SampleResult& a, const SampleResult& b) {
        return a.level != b.level ? a.level < b.level : a.sample < b.sample;
    });
    if (samples.size() != levels * per_level)
        throw std::invalid_argument("fragility: expected " + std::to_string(levels * per_level) +
                                    " samples, got " + std::to_string(samples.size()));
    for (std::size_t i = 0; i < samples.size(); ++i) {
        if (static_cast<std::size_t>(samples[i].level) != i / per_level ||
            static_cast<std::size_t>(samples[i].sample) != i % per_level)
            throw std::invalid_argument("fragility: sample " + std::to_string(i / per_level) +
                                        "/" + std::to_string(i % per_level) +
                                        " missing or repeated");
    }
    Result r;
    r.meta = meta;
    for (std::size_t j = 0; j < levels; ++j) {
        Level l;
        l.pga_g = meta.config.pga_g[j];
        l.n = static_cast<int>(per_level);
        for (std::size_t e = 0; e < all_events.size(); ++e) {
            Count& c = l.events[e];
            c.n = l.n;
            for (std::size_t i = j * per_level; i < (j + 1) * per_level; ++i)
                c.k += failed(samples[i], all_events[e], meta) ? 1 : 0;
            c.p = static_cast<double>(c.k) / static_cast<double>(c.n);
            c.ci = core::clopper_pearson(c.k, c.n);
        }
        r.levels.push_back(l);
    }
    for (std::size_t e = 0; e < all_events.size(); ++e) {
        std::vector<int> k, n;
        for (const Level& l : r.levels) {
            k.push_back(l.events[e].k);
            n.push_back(l.events[e].n);
        }
        r.fits[e] = fit_lognormal(meta.config.pga_g, k, n);
    }
    r.samples = std::move(samples);
    return r;
}

}  // namespace freestand::fragility
