#include "cli/options.hpp"

#include "sliding/block_spec.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <iostream>

#include "core/errors.hpp"
#include "core/limits.hpp"
#include "core/text_parse.hpp"
#include "cli/usage_error.hpp"

namespace freestand::cli {

std::optional<po::variables_map> parse_options(const std::string& command, const std::string& usage,
                                               po::options_description desc,
                                               const std::vector<std::string>& args,
                                               const std::vector<std::string>& positional) {
    desc.add_options()("help,h", "print this help and exit");
    po::positional_options_description pos;
    for (const auto& name : positional) {
        const bool many = name.size() > 3 && name.compare(name.size() - 3, 3, "...") == 0;
        pos.add(many ? name.substr(0, name.size() - 3).c_str() : name.c_str(), many ? -1 : 1);
    }
    po::variables_map vm;
    try {
        po::store(po::command_line_parser(args).options(desc).positional(pos).run(), vm);
        if (vm.count("help")) {
            std::cout << "usage: freestand " << command << " " << usage << "\n\n" << desc << "\n";
            return std::nullopt;
        }
        po::notify(vm);
    } catch (const po::error& e) {
        throw UsageError(fmt::format("{} (see freestand {} --help)", e.what(), command));
    }
    return vm;
}

double parse_double(const std::string& text, const std::string& option) {
    const std::optional<double> value = core::text::parse_number(text);
    if (!value)
        throw UsageError(fmt::format("{}: expected a finite number; got \"{}\"", option, text));
    return *value;
}

std::uint64_t parse_whole(const std::string& text, const std::string& option, double lo, double hi) {
    const double value = parse_double(text, option);
    if (!(value >= lo && value <= hi && value == std::floor(value)))
        throw UsageError(fmt::format("{}: expected a whole number in [{:g}, {:g}]; got \"{}\"", option,
                                     lo, hi, text));
    return static_cast<std::uint64_t>(value);
}

std::vector<std::string> split_list(const std::string& text) {
    return core::text::split(text, ',');
}

std::vector<double> parse_double_list(const std::string& text, const std::string& option) {
    std::vector<double> values;
    for (const std::string& item : split_list(text)) values.push_back(parse_double(item, option));
    return values;
}

std::vector<double> parse_levels(const std::string& text, const std::string& option) {
    if (text.find(':') == std::string::npos) return parse_double_list(text, option);
    const std::vector<std::string> parts = core::text::split(text, ':');
    if (parts.size() != 3)
        throw UsageError(fmt::format("{}: expected START:STOP:STEP or a comma list; got \"{}\"",
                                     option, text));
    const double first = parse_double(parts[0], option);
    const double last = parse_double(parts[1], option);
    const double step = parse_double(parts[2], option);
    if (!(step > 0.0) || last < first)
        throw UsageError(fmt::format("{}: \"{}\" needs STEP > 0 and STOP >= START", option, text));
    const double count = core::limits::pga_range_count(first, last, step);
    if (count > core::limits::max_pga_levels)
        throw UsageError(fmt::format("{}: \"{}\" gives {} levels; at most {} (README, Limits)",
                                     option, text, count, core::limits::max_pga_levels));
    return core::limits::pga_range_levels(first, step, count);
}

std::array<int, 2> parse_shard(const std::string& text, const std::string& option) {
    const std::size_t slash = text.find('/');
    int k = 0, n = 0;
    if (slash == std::string::npos || !core::text::parse_integer(text.substr(0, slash), k) ||
        !core::text::parse_integer(text.substr(slash + 1), n) || n < 1 || n > 100000 || k < 1 ||
        k > n)
        throw UsageError(
            fmt::format("{}: expected K/N with 1 <= K <= N <= 100000; got \"{}\"", option, text));
    return {k, n};
}

std::map<std::string, std::string> parse_key_texts(const std::vector<std::string>& items,
                                                   const std::string& option,
                                                   const std::vector<std::string>& allowed) {
    std::map<std::string, std::string> out;
    for (const std::string& item : items) {
        const std::size_t eq = item.find('=');
        if (eq == std::string::npos)
            throw UsageError(fmt::format("{}: expected key=value; got \"{}\"", option, item));
        const std::string key = item.substr(0, eq);
        if (std::find(allowed.begin(), allowed.end(), key) == allowed.end())
            throw UsageError(fmt::format("{}: unknown key \"{}\"; allowed: {}", option, key,
                                         fmt::join(allowed, ", ")));
        if (!out.emplace(key, item.substr(eq + 1)).second)
            throw UsageError(fmt::format("{}: key \"{}\" given twice", option, key));
    }
    return out;
}

std::map<std::string, double> parse_key_values(const std::string& text, const std::string& option,
                                               const std::vector<std::string>& allowed) {
    std::map<std::string, double> out;
    if (text.empty()) return out;
    for (const auto& [key, value] : parse_key_texts(split_list(text), option, allowed))
        out[key] = parse_double(value, option + " " + key);
    return out;
}

sliding::BoxSpec box_from_options(const std::string& block, const std::optional<std::string>& cg,
                                  std::optional<double> inertia_cg_kgm2, const std::string& suffix) {
    const std::string block_option = "--block" + suffix, cg_option = "--cg" + suffix;
    const auto box = parse_key_values(block, block_option, {"b", "h", "m"});
    std::map<std::string, double> cg_kv;
    if (cg && cg->find('=') != std::string::npos) {
        cg_kv = parse_key_values(*cg, cg_option, {"x", "h"});
    } else if (cg) {
        // Positional x,y: x from the left edge, y up; the same point as x = x - b, h = y.
        const auto xy = parse_double_list(*cg, cg_option);
        if (xy.size() != 2) throw UsageError(cg_option + ": expected x,y or x=OFFSET,h=HEIGHT (m)");
        if (!box.count("b"))
            throw InputError(SourceLocation{"", 0, "block" + suffix + " b"}, "missing key b");
        cg_kv["x"] = xy[0] - box.at("b");
        cg_kv["h"] = xy[1];
    }
    return sliding::box_spec(box, cg_kv, inertia_cg_kgm2);
}

}  // namespace freestand::cli
