#pragma once
/// Command-line pieces shared by `freestand spectrum` and `freestand target`: the frequency grid
/// and damping options, and printing PSA tables as CSV or JSON.
#include <fmt/format.h>

#include <filesystem>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli/options.hpp"
#include "core/errors.hpp"
#include "core/limits.hpp"
#include "spectra/spectrum.hpp"

namespace freestand::cli {

/// Adds --fmin, --fmax, --per-decade, --frequencies and --damping (default text given).
inline void add_spectrum_grid_options(po::options_description& desc,
                                      const std::string& damping_default,
                                      const std::string& damping_help) {
    desc.add_options()("damping", po::value<std::string>()->default_value(damping_default),
                       damping_help.c_str())("fmin", po::value<std::string>()->default_value("0.1"),
                                             "lowest frequency, Hz (> 0)")(
        "fmax", po::value<std::string>()->default_value("100"), "highest frequency, Hz (> fmin)")(
        "per-decade", po::value<std::string>()->default_value("100"),
        "log-spaced points per decade (integer >= 1)")(
        "frequencies", po::value<std::string>(),
        "explicit frequency list, Hz, comma-separated, strictly increasing (instead of "
        "--fmin/--fmax/--per-decade)");
}

/// Dampings from --damping: each in (0, 1), no repeats.
inline std::vector<double> dampings_from(const po::variables_map& vm) {
    std::vector<double> d = parse_double_list(vm["damping"].as<std::string>(), "--damping");
    for (std::size_t i = 0; i < d.size(); ++i) {
        require_in_range(d[i], 0.0, 1.0, SourceLocation{"", 0, "--damping"}, false, false);
        for (std::size_t j = 0; j < i; ++j)
            if (d[j] == d[i])
                throw UsageError(
                    fmt::format("--damping: {} given twice; expected distinct values", d[i]));
    }
    return d;
}

/// Frequencies from --frequencies, or log-spaced from --fmin/--fmax/--per-decade.
inline std::vector<double> frequencies_from(const po::variables_map& vm) {
    if (vm.count("frequencies")) {
        for (const char* opt : {"fmin", "fmax", "per-decade"})
            if (!vm[opt].defaulted())
                throw UsageError(
                    fmt::format("--frequencies and --{} exclude each other; give one", opt));
        auto f = parse_double_list(vm["frequencies"].as<std::string>(), "--frequencies");
        for (std::size_t i = 0; i < f.size(); ++i) {
            require_positive(f[i], SourceLocation{"", 0, "--frequencies"});
            if (i > 0 && !(f[i] > f[i - 1]))
                throw InputError(
                    SourceLocation{"", 0, "--frequencies"},
                    fmt::format("{} Hz follows {} Hz; expected strictly increasing values", f[i],
                                f[i - 1]));
        }
        return f;
    }
    const double fmin = parse_double(vm["fmin"].as<std::string>(), "--fmin");
    const double fmax = parse_double(vm["fmax"].as<std::string>(), "--fmax");
    const double per = parse_double(vm["per-decade"].as<std::string>(), "--per-decade");
    require_positive(fmin, SourceLocation{"", 0, "--fmin"});
    require_positive(fmax, SourceLocation{"", 0, "--fmax"});
    // The grid's ends are checked as the options they came from, not as its frequencies.
    core::limits::require_at_least(fmin, core::limits::min_frequency_hz,
                                   SourceLocation{"", 0, "--fmin"},
                                   "a response-spectrum frequency (Hz)");
    core::limits::require_within(fmax, core::limits::max_frequency_hz,
                                 SourceLocation{"", 0, "--fmax"},
                                 "a response-spectrum frequency (Hz)");
    if (!(fmax > fmin))
        throw InputError(SourceLocation{"", 0, "--fmax"},
                         fmt::format("{} Hz must be greater than --fmin {} Hz", fmax, fmin));
    if (!(per >= 1.0 && per <= 100000.0 && per == static_cast<double>(static_cast<int>(per))))
        throw InputError(SourceLocation{"", 0, "--per-decade"},
                         fmt::format("{}; expected an integer in [1, 100000]", per));
    return spectra::log_frequencies(fmin, fmax, static_cast<int>(per));
}

/// Spectrum file paths from a comma-separated option value ("H1.csv,H2.csv"); an empty entry
/// (",x.csv", "x.csv,") is a usage error naming the option.
inline std::vector<std::filesystem::path> spectrum_paths(const std::string& text,
                                                         const std::string& option) {
    std::vector<std::filesystem::path> out;
    for (const std::string& item : split_list(text)) {
        if (item.empty())
            throw UsageError(fmt::format("{}: empty file name in \"{}\"; expected FILE[,FILE...]",
                                         option, text));
        out.emplace_back(item);
    }
    return out;
}

/// Column/key name of a damping: shortest round-trip text, e.g. 0.05 -> "0.05".
inline std::string damping_key(double damping) { return fmt::format("{}", damping); }

/// CSV: frequency_hz, then psa_g_<damping> per damping.
inline void print_psa_csv(const std::vector<double>& frequency_hz,
                          const std::vector<double>& dampings,
                          const std::vector<std::vector<double>>& psa_g) {
    std::string out = "frequency_hz";
    for (double d : dampings) out += ",psa_g_" + damping_key(d);
    out += "\n";
    for (std::size_t i = 0; i < frequency_hz.size(); ++i) {
        out += fmt::format("{}", frequency_hz[i]);
        for (const auto& column : psa_g) out += fmt::format(",{}", column[i]);
        out += "\n";
    }
    std::cout << out;
}

/// {"<damping>": [values...], ...}
inline nlohmann::ordered_json by_damping(const std::vector<double>& dampings,
                                         const std::vector<std::vector<double>>& values) {
    nlohmann::ordered_json j = nlohmann::ordered_json::object();
    for (std::size_t d = 0; d < dampings.size(); ++d) j[damping_key(dampings[d])] = values[d];
    return j;
}

}  // namespace freestand::cli
