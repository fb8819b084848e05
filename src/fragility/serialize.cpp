#include "fragility/serialize.hpp"

#include <nlohmann/json.hpp>

namespace freestand::fragility {

using nlohmann::ordered_json;

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
            {"mu_s_law", m.mu_s_law},
            {"restitution_law", m.restitution_law},
            {"motion_source", m.motion_source}};
}

Meta meta_from_json(const nlohmann::json& j) {
    Meta m;
    m.case_name = j.at("case_name").get<std::string>();
    m.config.pga_g = j.at("pga_g").get<std::vector<double>>();
    m.config.samples = j.at("samples").get<int>();
    m.config.seed = j.at("seed").get<std::uint64_t>();
    m.config.pool = j.at("pool").get<int>();
    m.config.record_files = j.at("record_files").get<std::vector<std::string>>();
    m.allowable_slide_m = j.at("allowable_slide_m").get<double>();
    m.required_overturn_fs = j.at("required_overturn_fs").get<double>();
    m.mu_s_law = j.at("mu_s_law").get<std::string>();
    m.restitution_law = j.at("restitution_law").get<std::string>();
    m.motion_source = j.at("motion_source").get<std::string>();
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
    SampleResult s;
    s.level = j.at("level").get<int>();
    s.sample = j.at("sample").get<int>();
    s.motion = j.at("motion").get<std::string>();
    s.mu_s = j.at("mu_s").get<double>();
    s.restitution_x = j.at("restitution_x").get<double>();
    s.restitution_y = j.at("restitution_y").get<double>();
    s.slide_max_m = j.at("slide_max_m").get<double>();
    s.rock_max_over_alpha = j.at("rock_max_over_alpha").get<double>();
    s.overturned = j.at("overturned").get<bool>();
    return s;
}

}  // namespace freestand::fragility
