#include "fragility/serialize.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <utility>

#include "core/errors.hpp"
#include "core/json_fields.hpp"
#include "fragility/runner_detail.hpp"

namespace freestand::fragility {

using nlohmann::ordered_json;

namespace {

constexpr const char* kMalformed = "malformed fragility shard";

// An overturn "past alpha" is found as the root of alpha - theta (dynamics/event_driven.cpp):
// theta there is alpha within the root's tolerance, so theta/alpha may read 1 - 1e-15. A
// thousandfold margin over the integrators' rel_tol 1e-9 still refuses any edited flag.
constexpr double kOverturnRatioTol = 1e-6;

ordered_json to_json(const core::Distribution& d) {
    const bool uniform = d.kind == core::Distribution::Kind::uniform;
    return {{"kind", uniform ? "uniform" : "lognormal"},
            {"a", d.a},
            {"b", d.b},
            {"upper", d.upper ? ordered_json(*d.upper) : ordered_json()}};
}

ordered_json to_json(const Laws& l) {
    return {{"mu_s", to_json(l.mu_s)},
            {"restitution", l.restitution ? to_json(*l.restitution) : ordered_json()},
            {"restitution_bounds", l.restitution_bounds},
            {"kinetic_ratio", l.kinetic_ratio}};
}

// A law as the case reader admits it (assess/case.cpp): uniform lo <= hi within [lo_max,
// hi_max]; lognormal with median in (0, hi_max], beta in (0, 2], truncated above 0 when at all.
core::Distribution distribution_from(const core::JsonFields& f, double hi_max) {
    core::Distribution d;
    const auto kind = f.get<std::string>("kind");
    d.a = f.get<double>("a");
    d.b = f.get<double>("b");
    if (!f.is_null("upper")) d.upper = f.get<double>("upper");
    if (kind == "uniform") {
        require_in_range(d.a, 0.0, hi_max, f.at("a"));
        require_in_range(d.b, d.a, hi_max, f.at("b"));
        if (d.upper) f.fail("upper", "a uniform law has no truncation; expected null");
        return d;
    }
    if (kind != "lognormal") f.fail("kind", fmt::format("\"{}\"; expected uniform or lognormal", kind));
    d.kind = core::Distribution::Kind::lognormal;
    require_in_range(d.a, 0.0, hi_max, f.at("a"), false, true);
    require_in_range(d.b, 0.0, 2.0, f.at("b"), false, true);
    if (d.upper) require_positive(*d.upper, f.at("upper"));
    return d;
}

Laws laws_from(const core::JsonFields& f) {
    Laws l;
    // Friction as [uncertainty] mu_s admits it (up to 10); restitution within [0, 1].
    l.mu_s = distribution_from(f.object("mu_s"), 10.0);
    if (!f.is_null("restitution")) l.restitution = distribution_from(f.object("restitution"), 1.0);
    const auto bounds = f.get<std::vector<std::vector<double>>>("restitution_bounds");
    if (bounds.size() != 2 || bounds[0].size() != 2 || bounds[1].size() != 2)
        f.fail("restitution_bounds", "expected [[x lower, x upper], [y lower, y upper]]");
    for (std::size_t d = 0; d < 2; ++d) {
        require_in_range(bounds[d][0], 0.0, 1.0, f.at("restitution_bounds"));
        require_in_range(bounds[d][1], bounds[d][0], 1.0, f.at("restitution_bounds"));
        l.restitution_bounds[d] = {bounds[d][0], bounds[d][1]};
    }
    l.kinetic_ratio = f.get<double>("kinetic_ratio");
    require_in_range(l.kinetic_ratio, 0.0, 1.0, f.at("kinetic_ratio"));
    return l;
}

Meta meta_from(const core::JsonFields& f) {
    Meta m;
    m.case_name = f.get<std::string>("case_name");
    m.config.pga_g = f.get<std::vector<double>>("pga_g");
    m.config.samples = f.get<int>("samples");
    m.config.seed = f.get<std::uint64_t>("seed");
    m.config.pool = f.get<int>("pool");
    m.config.record_files = f.get<std::vector<std::string>>("record_files");
    m.allowable_slide_m = f.get<double>("allowable_slide_m");
    m.required_overturn_fs = f.get<double>("required_overturn_fs");
    m.laws = laws_from(f.object("laws"));
    m.mu_s_law = f.get<std::string>("mu_s_law");
    m.restitution_law = f.get<std::string>("restitution_law");
    m.motion_source = f.get<std::string>("motion_source");
    m.models = f.get<std::string>("models");
    return m;
}

// The ranges a run can have: the config's (fragility::validate), the case's allowable slide
// (0, 10] m and required factor of safety [1, 10] (assess/case.cpp).
void check_meta(const Meta& m, const core::JsonFields& f) {
    try {
        validate(m.config);
    } catch (const InputError& e) {
        throw InputError(f.at(e.where().field), std::string(kMalformed) + ": " + e.message());
    }
    require_in_range(m.allowable_slide_m, 0.0, 10.0, f.at("allowable_slide_m"), false, true);
    require_in_range(m.required_overturn_fs, 1.0, 10.0, f.at("required_overturn_fs"));
}

// The range a law's draws fall in: a uniform law's bounds; a lognormal's (0, truncation].
std::pair<double, double> support(const core::Distribution& d, double hi_max) {
    if (d.kind == core::Distribution::Kind::uniform) return {d.a, d.b};
    return {0.0, d.upper.value_or(hi_max)};
}

SampleResult sample_from(const core::JsonFields& f) {
    SampleResult s;
    s.level = f.get<int>("level");
    s.sample = f.get<int>("sample");
    s.motion = f.get<std::string>("motion");
    s.mu_s = f.get<double>("mu_s");
    s.restitution_x = f.get<double>("restitution_x");
    s.restitution_y = f.get<double>("restitution_y");
    s.slide_max_m = f.get<double>("slide_max_m");
    s.rock_max_over_alpha = f.get<double>("rock_max_over_alpha");
    s.overturned = f.get<bool>("overturned");
    return s;
}

// A drawn value must be the one the sample's stream draws: equal to the last bit, since the
// shard wrote it in shortest round-trip form.
void require_drawn(double value, double drawn, const SourceLocation& where, const Meta& m,
                   const SampleResult& s) {
    if (value == drawn) return;
    throw InputError(where, fmt::format("{}: {} is not the value {} that sample {} of level {} "
                                        "draws from its stream (seed {})",
                                        kMalformed, value, drawn, s.sample + 1, s.level + 1,
                                        m.config.seed));
}

// Level and sample within the run; motion, friction and restitution as the sample's stream
// draws them from the run's laws (docs/methods.md s.9); peaks finite and >= 0; an overturn
// only from theta = alpha on (docs/methods.md s.4: theta > alpha, or theta = pi/2).
void check_sample(const SampleResult& s, const Meta& m, const core::JsonFields& f) {
    const auto levels = static_cast<int>(m.config.pga_g.size());
    if (s.level < 0 || s.level >= levels)
        f.fail("level", fmt::format("{}; expected 0 to {} (the run's levels)", s.level, levels - 1));
    if (s.sample < 0 || s.sample >= m.config.samples)
        f.fail("sample", fmt::format("{}; expected 0 to {} (the run's samples per level)", s.sample,
                                     m.config.samples - 1));
    const auto [mu_lo, mu_hi] = support(m.laws.mu_s, 10.0);
    require_in_range(s.mu_s, mu_lo, mu_hi, f.at("mu_s"));
    require_in_range(s.restitution_x, 0.0, 1.0, f.at("restitution_x"));
    require_in_range(s.restitution_y, 0.0, 1.0, f.at("restitution_y"));
    const bool records = !m.config.record_files.empty();
    const Draw d = draw(m.laws, m.config.seed, s.level, s.sample,
                        records ? m.config.record_files.size()
                                : static_cast<std::size_t>(m.config.pool));
    const std::string motion =
        records ? std::filesystem::path(m.config.record_files[d.pick]).filename().string()
                : fmt::format("set {}", d.pick + 1);
    if (s.motion != motion)
        f.fail("motion", fmt::format("\"{}\"; sample {} of level {} draws \"{}\" (seed {})", s.motion,
                                     s.sample + 1, s.level + 1, motion, m.config.seed));
    require_drawn(s.mu_s, d.mu_s, f.at("mu_s"), m, s);
    require_drawn(s.restitution_x, d.restitution[0], f.at("restitution_x"), m, s);
    require_drawn(s.restitution_y, d.restitution[1], f.at("restitution_y"), m, s);
    require_non_negative(s.slide_max_m, f.at("slide_max_m"));
    require_non_negative(s.rock_max_over_alpha, f.at("rock_max_over_alpha"));
    if (s.overturned && s.rock_max_over_alpha < 1.0 - kOverturnRatioTol)
        f.fail("overturned", fmt::format("true with theta/alpha {}; an overturn takes the block "
                                         "to theta = alpha (theta/alpha 1, less {} for locating "
                                         "the event) or past it",
                                         s.rock_max_over_alpha, kOverturnRatioTol));
}

}  // namespace

ordered_json to_json(const Meta& m) {
    const Config& c = m.config;
    return {{"case_name", m.case_name},
            {"pga_g", c.pga_g},
            {"samples", c.samples},
            {"seed", c.seed},
            {"pool", c.pool},
            {"record_files", c.record_files},
            {"allowable_slide_m", m.allowable_slide_m},
            {"required_overturn_fs", m.required_overturn_fs},
            {"laws", to_json(m.laws)},
            {"mu_s_law", m.mu_s_law},
            {"restitution_law", m.restitution_law},
            {"motion_source", m.motion_source},
            {"models", m.models}};
}

Meta meta_from_json(const nlohmann::json& j, const SourceLocation& at) {
    const core::JsonFields f(j, at, at.field.empty() ? "" : at.field + ".", kMalformed);
    Meta m = meta_from(f);
    check_meta(m, f);
    return m;
}

ordered_json to_json(const SampleResult& s) {
    return {{"level", s.level},
            {"sample", s.sample},
            {"motion", s.motion},
            {"mu_s", s.mu_s},
            {"restitution_x", s.restitution_x},
            {"restitution_y", s.restitution_y},
            {"slide_max_m", s.slide_max_m},
            {"rock_max_over_alpha", s.rock_max_over_alpha},
            {"overturned", s.overturned}};
}

SampleResult sample_from_json(const nlohmann::json& j) {
    return sample_from(core::JsonFields(j, SourceLocation{}, "", kMalformed));
}

std::vector<SampleResult> samples_from_json(const std::vector<nlohmann::json>& records,
                                            const std::vector<SourceLocation>& at,
                                            const Meta& meta) {
    std::vector<SampleResult> out;
    std::map<std::pair<int, int>, std::size_t> seen;  // (level, sample) -> record
    for (std::size_t r = 0; r < records.size(); ++r) {
        const SourceLocation where = r < at.size() ? at[r] : SourceLocation{};
        const core::JsonFields f(records[r], where, "", kMalformed);
        SampleResult s = sample_from(f);
        check_sample(s, meta, f);
        const auto [it, fresh] = seen.emplace(std::make_pair(s.level, s.sample), r);
        if (!fresh) {
            const SourceLocation& first = it->second < at.size() ? at[it->second] : where;
            f.fail("sample", fmt::format("sample {} of level {} is also at {}:{}", s.sample + 1,
                                         s.level + 1, first.file, first.line));
        }
        out.push_back(std::move(s));
    }
    const auto levels = meta.config.pga_g.size();
    const auto per_level = static_cast<std::size_t>(meta.config.samples);
    if (out.size() != levels * per_level) {
        for (std::size_t i = 0; i < levels * per_level; ++i) {
            const auto key = std::make_pair(static_cast<int>(i / per_level),
                                            static_cast<int>(i % per_level));
            if (!seen.count(key))
                throw InputError(SourceLocation{"", 0, "shards"},
                                 fmt::format("{}: sample {} of level {} is in no shard", kMalformed,
                                             key.second + 1, key.first + 1));
        }
    }
    return out;
}

}  // namespace freestand::fragility
