// `generate`: its options, the targets and generation options they give, and match.json
// (cli/documents.hpp).
#include <fmt/format.h>

#include "cli/design_options.hpp"
#include "cli/documents.hpp"
#include "core/errors.hpp"
#include "core/readers.hpp"
#include "report/history_json.hpp"
#include "report/references.hpp"
#include "spectra/design.hpp"
#include "core/version.hpp"

namespace freestand::cli {
namespace {

std::vector<double> target_grid() { return spectra::log_frequencies(0.01, 200.0, 100); }

motion::TargetSet design_targets(const po::variables_map& vm, double vertical_ratio,
                                 bool ratio_given) {
    const std::string name = vm["target"].as<std::string>();
    check_design_options(vm, "--target", name);
    if (name == "rg1.60") {
        const double pga = required_positive(vm, "--target", name, "pga");
        // RG 1.60's vertical spectrum, scaled to the ratio's ZPA when one is given (as assess).
        return motion::rg160_targets(
            pga, ratio_given ? vertical_ratio : spectra::rg160_vertical_zpa_ratio);
    }
    const auto f = target_grid();
    const spectra::Spectrum h5 = design_spectrum(vm, "--target", name, 0.05, false, f);
    std::optional<spectra::Spectrum> h10;
    if (name == "ec8") h10 = design_spectrum(vm, "--target", name, 0.10, false, f);
    std::string label = name == "asce7"    ? "ASCE 7"
                        : name == "ec8"    ? fmt::format("EC8 type {} ground {}",
                                                         vm["type"].as<std::string>(),
                                                         vm["ground"].as<std::string>())
                                           : "IS 1893 " + vm["soil"].as<std::string>();
    return motion::ratio_targets(std::move(label), h5, h10, vertical_ratio);
}

motion::TargetSet targets_from(const po::variables_map& vm) {
    const bool ratio_given = vm.count("vertical-ratio") > 0;
    const double ratio =
        ratio_given ? parse_double(vm["vertical-ratio"].as<std::string>(), "--vertical-ratio")
                    : 2.0 / 3.0;
    if (vm.count("target-file")) {
        if (vm.count("target"))
            throw UsageError("--target and --target-file exclude each other; give one");
        const std::string file = vm["target-file"].as<std::string>();
        spectra::Spectrum h5 = spectra::read_spectrum_csv(file);
        if (h5.label.empty()) h5.label = file;
        std::optional<spectra::Spectrum> h10;
        if (vm.count("target-file-10"))
            h10 = spectra::read_spectrum_csv(vm["target-file-10"].as<std::string>());
        return motion::ratio_targets(fmt::format("user spectrum {}", file), h5, h10, ratio);
    }
    if (!vm.count("target")) throw UsageError("give --target NAME or --target-file F.csv");
    return design_targets(vm, ratio, ratio_given);
}

// --va-range, --adv2-range, --da-max: each sets its realism range (the RG 1.60 target has all
// three by default; other targets none, their ratios then reported and not checked).
void apply_realism_options(const po::variables_map& vm, motion::TargetSet& targets) {
    motion::RealismLimits lim = targets.horizontal.realism;
    const auto range = [&](const char* option) {
        const std::vector<double> v = parse_double_list(vm[option].as<std::string>(),
                                                        std::string("--") + option);
        if (v.size() != 2)
            throw UsageError(fmt::format("--{}: expected MIN,MAX (two numbers), got {}", option,
                                         v.size()));
        return motion::Range{v[0], v[1]};
    };
    if (vm.count("va-range")) lim.va_mps_per_g = range("va-range");
    if (vm.count("adv2-range")) lim.adv2 = range("adv2-range");
    if (vm.count("da-max")) lim.da_max_m_per_g = parse_double(vm["da-max"].as<std::string>(), "--da-max");
    motion::set_realism(targets, lim);
}

json optional_number(const std::optional<double>& v) {
    return v ? json(*v) : json(nullptr);
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
    j["psd_min_ratio"] = optional_number(a.psd_min_ratio);
    j["ratio_10pct_min"] = optional_number(a.ratio_10pct_min);
    j["ratio_10pct_max"] = optional_number(a.ratio_10pct_max);
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

}  // namespace

po::options_description generate_options() {
    po::options_description desc("options");
    desc.add_options()("target", po::value<std::string>(), "rg1.60 | asce7 | ec8 | is1893")(
        "target-file", po::value<std::string>(),
        "5%-damped target spectrum CSV (\"# damping: 0.05\")")(
        "target-file-10", po::value<std::string>(),
        "optional 10%-damped target CSV (reported only)");
    add_design_options(desc);
    desc.add_options()(
        "vertical-ratio", po::value<std::string>(),
        "vertical PGA / horizontal: rg1.60 scales its vertical spectrum to this ZPA (default 1, "
        "RG 1.60's own); other targets: ratio x horizontal (default 2/3)")(
        "seed-record", po::value<std::vector<std::string>>(),
        "seed record(s) to match, one per component (repeat or comma-separate); default synthetic")(
        "components", po::value<std::string>(),
        "comma list of h1,h2,v (default h1,h2,v; with seed "
        "records, as many as records given)")("duration", po::value<std::string>(),
                                              "synthetic: duration, s (default 20, >= 20)")(
        "dt", po::value<std::string>(), "synthetic: time step, s (default 0.005, <= 0.01)")(
        "seed", po::value<std::string>()->default_value("1"), "random seed (non-negative integer)")(
        "va-range", po::value<std::string>(),
        "realism: PGV/PGA range MIN,MAX, m/s per g (rg1.60 default 0.8,2.0; others unchecked)")(
        "adv2-range", po::value<std::string>(),
        "realism: PGA PGD/PGV^2 range MIN,MAX (rg1.60 default 2,8; others unchecked)")(
        "da-max", po::value<std::string>(),
        "realism: largest PGD/PGA, m per g (rg1.60 default 1.3; others unchecked)");
    return desc;
}

GenerateRequest generate_request(const po::variables_map& vm) {
    motion::TargetSet targets = targets_from(vm);
    apply_realism_options(vm, targets);
    motion::GenerateOptions go;
    go.seed = parse_whole(vm["seed"].as<std::string>(), "--seed", 0, 9.0e15);
    if (vm.count("seed-record")) {
        for (const std::string& group : vm["seed-record"].as<std::vector<std::string>>())
            for (const std::string& file : split_list(group))
                go.seed_records.push_back(core::read_record(file));
        for (const char* opt : {"duration", "dt"})
            if (vm.count(opt))
                throw UsageError(fmt::format(
                    "--{} applies to synthetic records; a seed record keeps its own", opt));
        const std::vector<std::string> all{"h1", "h2", "v"};
        go.components.assign(all.begin(), all.begin() + static_cast<long>(std::min<std::size_t>(
                                                            3, go.seed_records.size())));
    }
    if (vm.count("components")) go.components = split_list(vm["components"].as<std::string>());
    if (vm.count("duration"))
        go.duration_s = parse_double(vm["duration"].as<std::string>(), "--duration");
    if (vm.count("dt")) go.dt_s = parse_double(vm["dt"].as<std::string>(), "--dt");

    return {std::move(targets), std::move(go)};
}

json match_document(const motion::TargetSet& targets, const motion::GeneratedSet& set,
                    bool timing) {
    json j;
    j["target"] = targets.label;
    j["passed"] = set.passed;
    j["components"] = json::array();
    for (const motion::GeneratedComponent& c : set.components)
        j["components"].push_back(component_json(c, timing));
    j["correlations"] = json::array();
    for (const motion::Correlation& c : set.correlations)
        j["correlations"].push_back({{"a", c.a}, {"b", c.b}, {"rho", c.rho}});
    j["notes"] = set.notes;
    j["conventions"] = {
        {"criteria",
         "SRP 3.7.1 Option 1 Approach 2: 5% ratio at >= 100 points/decade 0.1-50 Hz (or Nyquist), "
         ">= 0.9, <= 9 adjacent below 1.0, <= 1.3 in 0.2-25 Hz, PSD >= 0.8 target (RG 1.60 "
         "horizontal) in 0.3-24 Hz, |v_end| < 1e-4 m/s, |d_end| < 1e-4 m, dt <= 0.01 s, "
         "duration >= 20 s, |rho| <= 0.16"},
        {"realism",
         "PGA within pga_over_zpa_range x the target's zero-period acceleration, D5-75 >= "
         "d5_75_min_s; on horizontals V/A, AD/V^2 and D/A within their ranges where set "
         "(rg1.60: 0.8-2.0 m/s/g, 2-8, <= 1.3 m/g; --va-range, --adv2-range, --da-max); "
         "docs/methods.md s.8"},
        {"psd",
         "S(f) = |X(f)|^2 / (pi T_D), X = dt FFT(a), T_D = D5-75, averaged over f(1 -+ 0.2): "
         "one-sided "
         "per rad/s, compared with the SRP 3.7.1 App. A target in the same convention"},
        {"wall_s", "the only field that varies between identical runs (null with --no-timing)"}};
    j["methods"] = "docs/methods.md s.8";
    j["references"] = references_json();
    j["freestand_version"] = core::version();
    return j;
}

}  // namespace freestand::cli
