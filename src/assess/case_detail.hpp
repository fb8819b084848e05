#pragma once
/// Internal: the case reader (case.hpp) split by TOML table, one file each: [component] and its
/// two-unit form [[unit]] / [tunnel] (case_component.cpp, case_units.cpp), [site]
/// (case_site.cpp), [options] (case_options.cpp), [uncertainty] (case_uncertainty.cpp); the
/// document and its tables' order (case_reader.cpp). Each reader checks its keys (TableReader)
/// and appends the defaults it takes to the case's assumptions.
#include <toml++/toml.h>

#include <filesystem>
#include <string>
#include <vector>

#include "assess/case.hpp"
#include "assess/toml_reader_detail.hpp"

namespace freestand::assess::case_detail {

/// The table root[name], nullptr when absent; an InputError when the key holds another type.
const toml::table* subtable(const toml::table& root, const std::string& name,
                            const std::string& file);
/// The line a node starts on.
int line_of(const toml::node& n);

/// [component] (or one [[unit]]): geometry, inertia, mode, free-rocking bands, base contact and
/// allowables. g_mps2: the case's gravity (site.g_mps2), which turns a given p_radps into inertia.
Component read_component(TableReader& r, std::vector<std::string>& assumptions, double g_mps2);
/// [[unit]] x 2 and [tunnel] (docs/methods.md s.10), each unit read as a [component], into out.
void read_units(const toml::table& root, const toml::node& units, const std::string& file,
                Case& out, double g_mps2);
/// site.g_mps2: the case's gravity, m/s^2, in Earth's surface range, else the thesis's 9.81.
/// Read on its own too, before [component], whose p_radps needs it.
double read_gravity_mps2(TableReader& r);
/// [site]: design spectrum or target files (relative to case_dir), PGA levels, vertical ratio,
/// energy method and realism ranges.
Site read_site(TableReader& r, std::vector<std::string>& assumptions,
               const std::filesystem::path& case_dir);
/// [options]: histories, seed, seed records (relative to case_dir), simulation and fragility.
Options read_options(TableReader& r, const std::filesystem::path& case_dir);
/// [uncertainty]: the distributions of mu_s and restitution.
Uncertainty read_uncertainty(TableReader& r, const std::string& file);

}  // namespace freestand::assess::case_detail
