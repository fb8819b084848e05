// `freestand generate`: spectrum-compatible acceleration histories and their acceptance report.
#include <fmt/format.h>

#include <iostream>
#include <nlohmann/json.hpp>

#include "cli/command.hpp"
#include "cli/options.hpp"
#include "core/errors.hpp"
#include "core/file_io.hpp"
#include "core/readers.hpp"
#include "motion/motion.hpp"
#include "report/references.hpp"
#include "spectra/design.hpp"

namespace freestand::cli {
namespace {

const char* const usage =
    "--target rg1.60|asce7|ec8|is1893 [design options] | --target-file F.csv, --out DIR [options]";

std::vector<double> target_grid() { return spectra::log_frequencies(0.01, 200.0, 100); }

double need(const po::variables_map& vm, const std::string& name, const std::string& target) {
    if (!vm.count(name)) throw UsageError(fmt::format("--target {} needs --{}", target, name));
    return parse_double(vm[name].as<std::string>(), "--" + name);
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
    const std::string name = vm["target"].as<std::string>();
    const auto f = target_grid();
    if (name == "rg1.60") {
        const double pga = need(vm, "pga", name);
        motion::TargetSet t = motion::rg160_targets(pga);
        if (!ratio_given) return t;
        motion::TargetSet r =
            motion::ratio_targets(t.label, t.horizontal.psa_5pct, t.horizontal.psa_10pct, ratio);
        r.horizontal.rg160_psd_pga_g = pga;
        return r;
    }
    if (name == "asce7")
        return motion::ratio_targets(
            "ASCE 7",
            spectra::asce7(need(vm, "sds", name), need(vm, "sd1", name), need(vm, "tl", name), f),
            std::nullopt, ratio);
    if (name == "ec8") {
        const double ag = need(vm, "ag", name);
        const std::string type = vm.count("type") ? vm["type"].as<std::string>() : "";
        if (type != "1" && type != "2")
            throw UsageError(fmt::format("--type: \"{}\"; --target ec8 needs --type 1 or 2", type));
        const std::string ground = vm.count("ground") ? vm["ground"].as<std::string>() : "";
        if (ground.size() != 1 || ground[0] < 'A' || ground[0] > 'E')
            throw UsageError(fmt::format(
                "--ground: \"{}\"; --target ec8 needs --ground A, B, C, D or E", ground));
        const auto ty = type == "1" ? spectra::Ec8Type::type1 : spectra::Ec8Type::type2;
        return motion::ratio_targets(fmt::format("EC8 type {} ground {}", type, ground),
                                     spectra::ec8(ag, ty, ground[0], 0.05, f),
                                     spectra::ec8(ag, ty, ground[0], 0.10, f), ratio);
    }
    if (name == "is1893") {
        const double pga = need(vm, "pga", name);
        const std::string soil = vm.count("soil") ? vm["soil"].as<std::string>() : "";
        spectra::Is1893Soil s{};
        if (soil == "rock")
            s = spectra::Is1893Soil::rock;
        else if (soil == "medium")
            s = spectra::Is1893Soil::medium;
        else if (soil == "soft")
            s = spectra::Is1893Soil::soft;
        else
            throw UsageError(
                fmt::format("--soil: \"{}\"; --target is1893 needs rock, medium or soft", soil));
        return motion::ratio_targets("IS 1893 " + soil, spectra::is1893(pga, s, f), std::nullopt,
                                     ratio);
    }
    throw UsageError(
        fmt::format("--target: unknown target \"{}\"; expected rg1.60, asce7, ec8 or is1893 "
                    "(or --target-file F.csv)",
                    name));
}

std::vector<std::string> split(const std::string& text) {
    std::vector<std::string> out;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t comma = text.find(',', start);
        const std::size_t end = comma == std::string::npos ? text.size() : comma;
        out.push_back(text.substr(start, end - start));
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return out;
}

nlohmann::ordered_json optional_number(const std::optional<double>& v) {
    return v ? nlohmann::ordered_json(*v) : nlohmann::ordered_json(nullptr);
}

nlohmann::ordered_json component_json(const motion::GeneratedComponent& c, bool timing) {
    const motion::Acceptance& a = c.acceptance;
    nlohmann::ordered_json j;
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
    j["wall_s"] = timing ? nlohmann::ordered_json(c.wall_s) : nlohmann::ordered_json(nullptr);
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
    return j;
}

// The sources of the targets, the generation and the acceptance rule (docs/methods.md s.8).
nlohmann::ordered_json references_json() {
    nlohmann::ordered_json out = nlohmann::ordered_json::array();
    for (const report::Reference& r :
         report::references({"docs/methods.md", "SRP 3.7.1", "RG 1.60", "ASCE 4-16",
                             "NUREG/CR-6728", "Nigam & Jennings 1969",
                             "Al Atik & Abrahamson 2010"}))
        out.push_back({{"key", r.key}, {"text", r.text}});
    return out;
}

int run(const std::vector<std::string>& args) {
    po::options_description desc("options");
    desc.add_options()("target", po::value<std::string>(), "rg1.60 | asce7 | ec8 | is1893")(
        "target-file", po::value<std::string>(),
        "5%-damped target spectrum CSV (\"# damping: 0.05\")")(
        "target-file-10", po::value<std::string>(),
        "optional 10%-damped target CSV (reported only)")(
        "pga", po::value<std::string>(), "rg1.60, is1893: PGA, g")("sds", po::value<std::string>(),
                                                                   "asce7: SDS, g")(
        "sd1", po::value<std::string>(), "asce7: SD1, g")("tl", po::value<std::string>(),
                                                          "asce7: TL, s")(
        "ag", po::value<std::string>(), "ec8: a_g, g")("type", po::value<std::string>(),
                                                       "ec8: 1 or 2")(
        "ground", po::value<std::string>(), "ec8: A..E")("soil", po::value<std::string>(),
                                                         "is1893: rock | medium | soft")(
        "vertical-ratio", po::value<std::string>(),
        "vertical target = ratio x horizontal (default: RG 1.60 vertical for rg1.60, else 2/3)")(
        "seed-record", po::value<std::vector<std::string>>(),
        "seed record(s) to match, one per component (repeat or comma-separate); default synthetic")(
        "components", po::value<std::string>(),
        "comma list of h1,h2,v (default h1,h2,v; with seed "
        "records, as many as records given)")("duration", po::value<std::string>(),
                                              "synthetic: duration, s (default 20, >= 20)")(
        "dt", po::value<std::string>(), "synthetic: time step, s (default 0.005, <= 0.01)")(
        "seed", po::value<std::string>()->default_value("1"), "random seed (non-negative integer)")(
        "no-timing", po::bool_switch(), "write wall_s as null so match.json is byte-identical too")(
        "out", po::value<std::string>()->required(), "output folder");
    const auto vm = parse_options("generate", usage, desc, args);
    if (!vm) return 0;

    const motion::TargetSet targets = targets_from(*vm);
    motion::GenerateOptions go;
    const double seed = parse_double((*vm)["seed"].as<std::string>(), "--seed");
    if (!(seed >= 0.0 && seed < 9.0e15 &&
          seed == static_cast<double>(static_cast<std::uint64_t>(seed))))
        throw UsageError(fmt::format("--seed: {}; expected a non-negative integer", seed));
    go.seed = static_cast<std::uint64_t>(seed);
    if (vm->count("seed-record")) {
        for (const std::string& group : (*vm)["seed-record"].as<std::vector<std::string>>())
            for (const std::string& file : split(group))
                go.seed_records.push_back(core::read_record(file));
        for (const char* opt : {"duration", "dt"})
            if (vm->count(opt))
                throw UsageError(fmt::format(
                    "--{} applies to synthetic records; a seed record keeps its own", opt));
        const std::vector<std::string> all{"h1", "h2", "v"};
        go.components.assign(all.begin(), all.begin() + static_cast<long>(std::min<std::size_t>(
                                                            3, go.seed_records.size())));
    }
    if (vm->count("components")) go.components = split((*vm)["components"].as<std::string>());
    if (vm->count("duration"))
        go.duration_s = parse_double((*vm)["duration"].as<std::string>(), "--duration");
    if (vm->count("dt")) go.dt_s = parse_double((*vm)["dt"].as<std::string>(), "--dt");

    const motion::GeneratedSet set = motion::generate_set(targets, go);
    const std::filesystem::path out = (*vm)["out"].as<std::string>();
    const bool timing = !(*vm)["no-timing"].as<bool>();
    nlohmann::ordered_json j;
    j["target"] = targets.label;
    j["passed"] = set.passed;
    j["components"] = nlohmann::ordered_json::array();
    for (const motion::GeneratedComponent& c : set.components) {
        core::write_csv_g(c.record, out / (c.record.component + ".csv"));
        j["components"].push_back(component_json(c, timing));
    }
    j["correlations"] = nlohmann::ordered_json::array();
    for (const motion::Correlation& c : set.correlations)
        j["correlations"].push_back({{"a", c.a}, {"b", c.b}, {"rho", c.rho}});
    j["notes"] = set.notes;
    j["conventions"] = {
        {"criteria",
         "SRP 3.7.1 Option 1 Approach 2: 5% ratio at >= 100 points/decade 0.1-50 Hz (or Nyquist), "
         ">= 0.9, <= 9 adjacent below 1.0, <= 1.3 in 0.2-25 Hz, PSD >= 0.8 target (RG 1.60 "
         "horizontal) in 0.3-24 Hz, |v_end| < 1e-4 m/s, |d_end| < 1e-4 m, dt <= 0.01 s, "
         "duration >= 20 s, |rho| <= 0.16"},
        {"psd",
         "S(f) = |X(f)|^2 / (pi T_D), X = dt FFT(a), T_D = D5-75, averaged over f(1 -+ 0.2): "
         "one-sided "
         "per rad/s, compared with the SRP 3.7.1 App. A target in the same convention"},
        {"wall_s", "the only field that varies between identical runs (null with --no-timing)"}};
    j["methods"] = "docs/methods.md s.8";
    j["references"] = references_json();
    j["freestand_version"] = FREESTAND_VERSION;
    core::write_file_atomic(out / "match.json", j.dump(2) + "\n");
    std::cout << fmt::format("{} component(s) written to {}: {}\n", set.components.size(),
                             out.string(),
                             set.passed ? "all pass SRP 3.7.1" : "FAILING, see match.json");
    return set.passed ? 0 : static_cast<int>(ExitCode::failure);
}

const CommandRegistrar reg{
    {"generate", "spectrum-compatible acceleration histories (h1, h2, v) + match.json", &run}};

}  // namespace
}  // namespace freestand::cli
