#pragma once
/// Shared command-line parsing on top of Boost.Program_options: help handling, and the value
/// syntaxes several commands use (comma lists, key=value lists).
#include <boost/program_options.hpp>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace freestand::cli {

namespace po = boost::program_options;

/// Parses args against desc (and positional names, in order). Returns std::nullopt after
/// printing help to stdout when --help was given; throws UsageError naming the option otherwise.
std::optional<po::variables_map> parse_options(const std::string& command, const std::string& usage,
                                               po::options_description desc,
                                               const std::vector<std::string>& args,
                                               const std::vector<std::string>& positional = {});

/// "0.05,0.1" -> {0.05, 0.1}; throws UsageError naming option on a bad number.
std::vector<double> parse_double_list(const std::string& text, const std::string& option);

/// One number; accepts a trailing unit suffix listed in allowed_suffixes ("g", "Hz", "s").
double parse_double(const std::string& text, const std::string& option);

/// "b=0.15,h=0.6,m=38" -> {{"b",0.15},{"h",0.6},{"m",38}}; keys must be in allowed.
std::map<std::string, double> parse_key_values(const std::string& text, const std::string& option,
                                               const std::vector<std::string>& allowed);

}  // namespace freestand::cli
