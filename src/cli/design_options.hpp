#pragma once
/// The design-spectrum options `freestand target --design NAME` and `freestand generate
/// --target NAME` share: one set of option names, one validation, one builder.
#include <string>
#include <vector>

#include "cli/options.hpp"
#include "spectra/spectrum.hpp"

namespace freestand::cli {

/// Adds --pga, --sds, --sd1, --tl, --ag, --type, --ground, --soil.
void add_design_options(po::options_description& desc);

/// Throws UsageError unless `design` is rg1.60, asce7, ec8 or is1893 and no option of another
/// design was given. `selector` is the option that named the design ("--design", "--target").
void check_design_options(const po::variables_map& vm, const std::string& selector,
                          const std::string& design);

/// The value of --NAME, required by `design` and > 0 (UsageError when missing, InputError when
/// not positive).
double required_positive(const po::variables_map& vm, const std::string& selector,
                         const std::string& design, const std::string& name);

/// The design spectrum at one damping (horizontal unless `vertical`, which only RG 1.60 has):
/// UsageError for a missing or malformed option, InputError naming the option for a value out
/// of range (a non-positive level, TL not above SD1/SDS).
spectra::Spectrum design_spectrum(const po::variables_map& vm, const std::string& selector,
                                  const std::string& design, double damping, bool vertical,
                                  const std::vector<double>& frequency_hz);

}  // namespace freestand::cli
