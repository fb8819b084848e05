#pragma once
/// The horizontal demand of the sliding method, SA_VH at one damping (docs/methods.md s.4), from
/// spectra given directly (files, design targets) or computed from records.
#include <filesystem>
#include <vector>

#include "core/record.hpp"
#include "spectra/spectrum.hpp"

namespace freestand::sliding {

/// SA_VH from one horizontal spectrum (returned as is) or two (combined by
/// spectra::combine_vector_horizontal, on h1's frequencies). Every spectrum must have the given
/// damping: InputError (field "damping") naming the spectrum otherwise. 1 or 2 spectra.
spectra::Spectrum vector_horizontal(const std::vector<spectra::Spectrum>& components,
                                    double damping);

/// As above, reading each file with spectra::read_spectrum_csv (whose errors name file and
/// line); a damping mismatch names the file.
spectra::Spectrum vector_horizontal_from_files(const std::vector<std::filesystem::path>& files,
                                               double damping);

/// As above, computing each component's PSA at the damping with spectra::response_spectra.
spectra::Spectrum vector_horizontal_from_records(const std::vector<core::Record>& components,
                                                 double damping,
                                                 const std::vector<double>& frequency_hz);

}  // namespace freestand::sliding
