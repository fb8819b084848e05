#include "api/generate.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "core/errors.hpp"
#include "core/readers.hpp"
#include "core/version.hpp"
#include "report/history_json.hpp"
#include "report/references.hpp"
#include "spectra/design.hpp"

namespace freestand::api {

namespace generate_detail {

/// The grid design targets are tabulated on: 0.01-200 Hz, 100 points per decade.
std::vector<double> target_grid() { return spectra::log_frequencies(0.01, 200.0, 100); }

motion::TargetSet design_targets(const GenerateRequest& r) {
    const std::string& name = r.target;
    check_design("target", name, r.design);
    if (name == "rg1.60") {
        const spectra::Spectrum h5 =
            design_spectrum("target", name, r.design, 0.05, false, target_grid());
        // RG 1.60's vertical spectrum, scaled to the ratio's ZPA when one is given (as assess).
        return motion::rg160_targets(*r.design.pga_g,
                                     r.vertical_ratio.value_or(spectra::rg160_vertical_zpa_ratio));
    }
    const auto f = target_grid();
    const spectra::Spectrum h5 = design_spectrum("target", name, r.design, 0.05, false, f);
    std::optional<spectra::Spectrum> h10;
    if (name == "ec8") h10 = design_spectrum("target", name, r.design, 0.10, false, f);
    std::string label = name == "asce7" ? "ASCE 7"
                        : name == "ec8" ? fmt::format("EC8 type {} ground {}", *r.design.type,
                                                      *r.design.ground)
                                        : "IS 1893 " + *r.design.soil;
    return motion::ratio_targets(std::move(label), h5, h10, r.vertical_ratio.value_or(2.0 / 3.0));
}

motion::TargetSet file_targets(const GenerateRequest& r) {
    const std::string file = r.target_file.string();
    spectra::Spectrum h5 = spectra::read_spectrum_csv(r.target_file);
    if (h5.label.empty()) h5.label = file;
    std::optional<spectra::Spectrum> h10;
    if (!r.target_file_10.empty()) h10 = spectra::read_spectrum_csv(r.target_file_10);
    return motion::ratio_targets(fmt::format("user spectrum {}", file), h5, h10,
                                 r.vertical_ratio.value_or(2.0 / 3.0));
}

motion::TargetSet targets_of(const GenerateRequest& r) {
    if (!r.target_file.empty()) {
        if (!r.target.empty())
            throw InputError(SourceLocation{"", 0, "target_file"},
                             "excludes a design target; give one");
        return file_targets(r);
    }
    if (r.target.empty())
        throw InputError(SourceLocation{"", 0, "target"},
                         "no target; expected a design (rg1.60, asce7, ec8, is1893) or a target "
                         "spectrum file");
    return design_targets(r);
}

// Each realism range given replaces the target's (RG 1.60 has all three by default; other
// targets none, their ratios then reported and not checked).
void apply_realism(const GenerateRequest& r, motion::TargetSet& targets) {
    motion::RealismLimits lim = targets.horizontal.realism;
    if (r.va_range_mps_per_g) lim.va_mps_per_g = r.va_range_mps_per_g;
    if (r.adv2_range) lim.adv2 = r.adv2_range;
    if (r.da_max_m_per_g) lim.da_max_m_per_g = r.da_max_m_per_g;
    motion::set_realism(targets, lim);
}

motion::GenerateOptions options_of(const GenerateRequest& r) {
    motion::GenerateOptions go;
    go.seed = r.seed;
    if (!r.seed_records.empty()) {
        for (const std::filesystem::path& file : r.seed_records)
            go.seed_records.push_back(core::read_record(file));
        if (r.duration_s)
            throw InputError(SourceLocation{"", 0, "duration_s"},
                             "applies to synthetic records; a seed record keeps its own");
        if (r.dt_s)
            throw InputError(SourceLocation{"", 0, "dt_s"},
                             "applies to synthetic records; a seed record keeps its own");
        const std::vector<std::string> all{"h1", "h2", "v"};
        go.components.assign(all.begin(), all.begin() + static_cast<long>(std::min<std::size_t>(
                                                            3, go.seed_records.size())));
    }
    if (!r.components.empty()) go.components = r.components;
    if (r.duration_s) go.duration_s = *r.duration_s;
    if (r.dt_s) go.dt_s = *r.dt_s;
    return go;
}

json component_json(const motion::GeneratedComponent& c, bool timing) {
    const motion::Acceptance& a = c.acceptance;
    json j;
    j["component"] = c.record.component;
    j["passed"] = a.passed;
    j["min_ratio"] = a.min_ratio;
    j["max_ratio"] = a.max_ratio;
    j["mean_ratio"] = a.mean_ratio;
    j["max_adjacent_below"] = a.max_adjacent_below;
    j["pga_g"] = a.pga_g;
    j["pgv_mps"] = a.pgv_mps;
    j["pgd_m"] = a.pgd_m;
    j["final_velocity_mps"] = a.final_velocity_mps;
    j["final_displacement_m"] = a.final_displacement_m;
    j["d5_75_s"] = a.d5_75_s;
    j["iterations"] = c.iterations;
    j["wall_s"] = timing ? json(c.wall_s) : json(nullptr);
    j["reason"] = a.reason;
    j["stop"] = c.stop;
    j["method"] = c.method;
    j["seed"] = c.seed;
    j["attempts"] = c.attempts;
    j["check_points"] = a.check_points;
    j["max_ratio_0p2_25hz"] = a.max_ratio_cap_band;
    j["psd_min_ratio"] = number_or_null(a.psd_min_ratio);
    j["ratio_10pct_min"] = number_or_null(a.ratio_10pct_min);
    j["ratio_10pct_max"] = number_or_null(a.ratio_10pct_max);
    j["d5_95_s"] = a.d5_95_s;
    j["duration_s"] = a.duration_s;
    j["dt_s"] = a.dt_s;
    j["file"] = c.record.component + ".csv";
    j["measures"] = report::measures_json(a);
    j["realism"] = report::realism_json(a);
    return j;
}

// The sources of the targets, the generation and the acceptance rule (docs/methods.md s.8).
json references_json() {
    json out = json::array();
    for (const report::Reference& r :
         report::references({"docs/methods.md", "SRP 3.7.1", "RG 1.60", "ASCE 4-16",
                             "NUREG/CR-6728", "Nigam & Jennings 1969",
                             "Al Atik & Abrahamson 2010"}))
        out.push_back({{"key", r.key}, {"text", r.text}});
    return out;
}

json conventions_json() {
    return {
        {"criteria",
         "SRP 3.7.1 Option 1 Approach 2: 5% ratio at >= 100 points/decade 0.1-50 Hz (or Nyquist), "
         ">= 0.9, <= 9 adjacent below 1.0, <= 1.3 in 0.2-25 Hz, PSD >= 0.8 target (RG 1.60 "
         "horizontal) in 0.3-24 Hz, |v_end| < 1e-4 m/s, |d_end| < 1e-4 m, dt <= 0.01 s, "
         "duration >= 20 s, |rho| <= 0.16"},
        {"realism",
         "PGA within pga_over_zpa_range x the target's zero-period acceleration, D5-75 >= "
         "d5_75_min_s; on horizontals V/A, AD/V^2 and D/A within their ranges where set "
         "(rg1.60: 0.8-2.0 m/s/g, 2-8, <= 1.3 m/g; the request's va_range_mps_per_g, adv2_range, "
         "da_max_m_per_g); "
         "docs/methods.md s.8"},
        {"psd",
         "S(f) = |X(f)|^2 / (pi T_D), X = dt FFT(a), T_D = D5-75, averaged over f(1 -+ 0.2): "
         "one-sided "
         "per rad/s, compared with the SRP 3.7.1 App. A target in the same convention"},
        {"wall_s", "the only field that varies between identical runs (null when the run is not timed)"}};
}

}  // namespace generate_detail

GenerateResult generate(const GenerateRequest& request) {
    motion::TargetSet targets = generate_detail::targets_of(request);
    generate_detail::apply_realism(request, targets);
    const motion::GenerateOptions options = generate_detail::options_of(request);
    motion::GeneratedSet set = motion::generate_set(targets, options);
    return {request, std::move(targets), std::move(set)};
}

json to_json(const GenerateResult& result) {
    const motion::GeneratedSet& set = result.set;
    json j;
    j["target"] = result.targets.label;
    j["passed"] = set.passed;
    j["components"] = json::array();
    for (const motion::GeneratedComponent& c : set.components)
        j["components"].push_back(generate_detail::component_json(c, result.request.timing));
    j["correlations"] = json::array();
    for (const motion::Correlation& c : set.correlations)
        j["correlations"].push_back({{"a", c.a}, {"b", c.b}, {"rho", c.rho}});
    j["notes"] = set.notes;
    j["conventions"] = generate_detail::conventions_json();
    j["methods"] = "docs/methods.md s.8";
    j["references"] = generate_detail::references_json();
    j["freestand_version"] = core::version();
    return j;
}

}  // namespace freestand::api
