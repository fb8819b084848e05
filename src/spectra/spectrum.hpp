#pragma once
/// Pseudo-acceleration spectra: targets (design spectra, user files) and computed ones.
#include <filesystem>
#include <string>
#include <vector>

namespace freestand::spectra {

/// PSA against frequency at one damping. Frequencies strictly increasing, PSA > 0.
struct Spectrum {
    double damping = 0.05;            ///< fraction of critical
    std::vector<double> frequency_hz;
    std::vector<double> psa_g;
    std::string label;                ///< e.g. "RG 1.60 horizontal, PGA 0.3 g, 5%"

    /// PSA at f, interpolated linearly on log-log axes. Below the first point: constant
    /// spectral displacement (PSA ~ f^2); above the last: constant PSA (rigid limit).
    double psa_at(double f_hz) const;
};

/// Frequencies log-spaced from fmin to fmax inclusive, at per_decade points per decade.
std::vector<double> log_frequencies(double fmin_hz, double fmax_hz, int per_decade);

/// Reads the spectrum file format: '#' comment lines, one "# damping: 0.05", then the header
/// "frequency_hz,psa_g", then rows in strictly increasing frequency with PSA > 0. A UTF-8 BOM
/// is accepted, UTF-16 refused, as by the record readers (core::text::utf8_text).
/// Throws InputError naming file and line.
Spectrum read_spectrum_csv(const std::filesystem::path& path);
/// The same on text in memory; file names the file in messages and its stem is the label.
Spectrum parse_spectrum_csv(const std::string& text, const std::string& file);
/// Writes the same format (atomically); comments are written as "# <line>".
void write_spectrum_csv(const Spectrum& s, const std::filesystem::path& path,
                        const std::vector<std::string>& comments);

/// SA_VH = sqrt(SA_H1^2 + 0.16 SA_H2^2), H1 the larger at each frequency (docs/methods.md s.4),
/// on h1's frequencies.
Spectrum combine_vector_horizontal(const Spectrum& h1, const Spectrum& h2);

}  // namespace freestand::spectra
