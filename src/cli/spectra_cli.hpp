#pragma once
/// Command-line pieces shared by `freestand spectrum` and `freestand target`: the frequency grid
/// and damping options into a request, and printing PSA tables as CSV.
#include <fmt/format.h>

#include <filesystem>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "api/spectrum.hpp"
#include "cli/options.hpp"
#include "core/errors.hpp"
#include "cli/usage_error.hpp"

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

/// The dampings --damping lists (their values are the request's to check).
inline std::vector<double> dampings_from(const po::variables_map& vm) {
    return parse_double_list(vm["damping"].as<std::string>(), "--damping");
}

/// The frequency grid of --frequencies, or of --fmin/--fmax/--per-decade (their values are the
/// request's to check).
inline api::FrequencyGrid grid_from(const po::variables_map& vm) {
    api::FrequencyGrid grid;
    if (vm.count("frequencies")) {
        for (const char* opt : {"fmin", "fmax", "per-decade"})
            if (!vm[opt].defaulted())
                throw UsageError(
                    fmt::format("--frequencies and --{} exclude each other; give one", opt));
        grid.frequency_hz = parse_double_list(vm["frequencies"].as<std::string>(), "--frequencies");
        return grid;
    }
    grid.fmin_hz = parse_double(vm["fmin"].as<std::string>(), "--fmin");
    grid.fmax_hz = parse_double(vm["fmax"].as<std::string>(), "--fmax");
    grid.per_decade = parse_double(vm["per-decade"].as<std::string>(), "--per-decade");
    return grid;
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

/// CSV: frequency_hz, then psa_g_<damping> per damping.
inline void print_psa_csv(const std::vector<double>& frequency_hz,
                          const std::vector<double>& dampings,
                          const std::vector<std::vector<double>>& psa_g) {
    std::string out = "frequency_hz";
    for (double d : dampings) out += ",psa_g_" + api::damping_key(d);
    out += "\n";
    for (std::size_t i = 0; i < frequency_hz.size(); ++i) {
        out += fmt::format("{}", frequency_hz[i]);
        for (const auto& column : psa_g) out += fmt::format(",{}", column[i]);
        out += "\n";
    }
    std::cout << out;
}

}  // namespace freestand::cli
