#pragma once
/// Shared command-line parsing on top of Boost.Program_options: help handling, and the value
/// syntaxes several commands use (comma lists, key=value lists).
#include <boost/program_options.hpp>
#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "sliding/block_spec.hpp"
#include "cli/usage_error.hpp"

namespace freestand::cli {

namespace po = boost::program_options;

/// Parses args against desc (and positional names, in order; a name ending in "..." takes every
/// remaining positional argument). Returns std::nullopt after
/// printing help to stdout when --help was given; throws UsageError naming the option otherwise.
std::optional<po::variables_map> parse_options(const std::string& command, const std::string& usage,
                                               po::options_description desc,
                                               const std::vector<std::string>& args,
                                               const std::vector<std::string>& positional = {});

/// "a,b,,c" -> {"a", "b", "", "c"}: the one comma splitter of option values; empty items are
/// kept so that each caller can name them in its error.
std::vector<std::string> split_list(const std::string& text);

/// "0.05,0.1" -> {0.05, 0.1}; throws UsageError naming option on a bad number.
std::vector<double> parse_double_list(const std::string& text, const std::string& option);

/// PGA levels: "START:STOP:STEP" (inclusive, e.g. 0.1:1.0:0.1, each value rounded to 12
/// decimals so 0.3 prints as 0.3) or a comma list. UsageError naming option on bad syntax, a
/// non-positive step, STOP below START or more than 1000 levels.
std::vector<double> parse_levels(const std::string& text, const std::string& option);

/// "K/N" with 1 <= K <= N <= 100000 -> {K, N}; UsageError naming option otherwise.
std::array<int, 2> parse_shard(const std::string& text, const std::string& option);

/// One finite number (core::text::parse_number); UsageError naming option otherwise.
double parse_double(const std::string& text, const std::string& option);

/// A whole number in [lo, hi] (counts, seeds, thread numbers; "1e2" is 100); UsageError naming
/// option otherwise, so that "2.5" is never truncated to 2.
std::uint64_t parse_whole(const std::string& text, const std::string& option, double lo, double hi);

/// {"ramp=1s", "phase=90"} -> {{"ramp","1s"},{"phase","90"}}: the one key=value parser of
/// option values. UsageError naming option for an item without '=', a key not in allowed, or a
/// key given twice (a repeated key would otherwise silently take its last value).
std::map<std::string, std::string> parse_key_texts(const std::vector<std::string>& items,
                                                   const std::string& option,
                                                   const std::vector<std::string>& allowed);

/// "b=0.15,h=0.6,m=38" -> {{"b",0.15},{"h",0.6},{"m",38}}: parse_key_texts of the comma items,
/// each value a number.
std::map<std::string, double> parse_key_values(const std::string& text, const std::string& option,
                                               const std::vector<std::string>& allowed);

/// The option's text, when given.
inline std::optional<std::string> opt_string(const po::variables_map& vm, const char* name) {
    if (!vm.count(name)) return std::nullopt;
    return vm[name].as<std::string>();
}

/// The option's number (parse_double of its text, UsageError naming --name), when given.
inline std::optional<double> opt_number(const po::variables_map& vm, const char* name) {
    if (!vm.count(name)) return std::nullopt;
    return parse_double(vm[name].as<std::string>(), std::string("--") + name);
}

/// The box of --block b=HALF_WIDTH,h=HALF_HEIGHT[,m=KG], --cg and --inertia, one parser for
/// classify, rock and simulate (the api's requests check it with sliding::make_block: a uniform
/// box unless a CG or an inertia is given; m defaults to 1 kg). --cg is x=OFFSET,h=HEIGHT (x
/// right of the base's centre) or the positional x,y (x from the left edge, y up). UsageError
/// naming the option for bad syntax; InputError (field "block b", "block h") for a missing
/// key. suffix names a second block's options (--block2, --cg2 for "2").
sliding::BoxSpec box_from_options(const std::string& block, const std::optional<std::string>& cg,
                                  std::optional<double> inertia_cg_kgm2,
                                  const std::string& suffix = "");

}  // namespace freestand::cli
