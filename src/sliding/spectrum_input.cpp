#include "sliding/spectrum_input.hpp"

#include <cmath>
#include <fmt/format.h>

#include "core/tolerances.hpp"
#include "core/errors.hpp"
#include "spectra/response.hpp"

namespace freestand::sliding {

namespace {

void require_count(std::size_t n) {
    if (n < 1 || n > 2)
        throw InputError(SourceLocation{"", 0, "horizontal components"},
                         fmt::format("{} horizontal components given; expected 1 or 2", n));
}

void require_damping(const spectra::Spectrum& s, double damping, const std::string& file) {
    if (std::abs(s.damping - damping) > core::tol::damping_equal)
        throw InputError(SourceLocation{file, 0, "damping"},
                         fmt::format("spectrum \"{}\" has damping {}; expected {}", s.label,
                                     s.damping, damping));
}

}  // namespace

spectra::Spectrum vector_horizontal(const std::vector<spectra::Spectrum>& components,
                                    double damping) {
    require_count(components.size());
    for (const auto& s : components) require_damping(s, damping, "");
    if (components.size() == 1) return components.front();
    return spectra::combine_vector_horizontal(components[0], components[1]);
}

spectra::Spectrum vector_horizontal_from_files(const std::vector<std::filesystem::path>& files,
                                               double damping) {
    require_count(files.size());
    std::vector<spectra::Spectrum> comps;
    for (const auto& f : files) {
        comps.push_back(spectra::read_spectrum_csv(f));
        require_damping(comps.back(), damping, f.string());
    }
    return vector_horizontal(comps, damping);
}

spectra::Spectrum vector_horizontal_from_records(const std::vector<core::Record>& components,
                                                 double damping,
                                                 const std::vector<double>& frequency_hz) {
    require_count(components.size());
    std::vector<spectra::Spectrum> comps;
    for (const auto& r : components) {
        spectra::Spectrum s = spectra::response_spectra(r, {damping}, frequency_hz).spectrum(0);
        s.label = fmt::format("{} {}, {}% damped", r.name, r.component, 100.0 * damping);
        comps.push_back(std::move(s));
    }
    return vector_horizontal(comps, damping);
}

}  // namespace freestand::sliding
