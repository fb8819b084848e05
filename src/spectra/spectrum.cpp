#include "spectra/spectrum.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string_view>

#include "core/errors.hpp"
#include "core/limits.hpp"
#include "core/steps.hpp"
#include "core/file_io.hpp"
#include "core/text_parse.hpp"

namespace freestand::spectra {

double Spectrum::psa_at(double f_hz) const {
    if (frequency_hz.empty() || frequency_hz.size() != psa_g.size())
        throw InputError(
            SourceLocation{"", 0, "spectrum"},
            fmt::format("spectrum \"{}\" has {} frequencies and {} PSA values; expected "
                        "the same number, at least one",
                        label, frequency_hz.size(), psa_g.size()));
    if (!(std::isfinite(f_hz) && f_hz > 0.0))
        throw InputError(SourceLocation{"", 0, "f_hz"},
                         fmt::format("frequency {} Hz must be finite and > 0", f_hz));
    // Constant spectral displacement below the first point: SD = PSA / omega^2 fixed.
    if (f_hz <= frequency_hz.front()) {
        const double r = f_hz / frequency_hz.front();
        return psa_g.front() * r * r;
    }
    if (f_hz >= frequency_hz.back()) return psa_g.back();
    const auto hi = static_cast<std::size_t>(
        std::upper_bound(frequency_hz.begin(), frequency_hz.end(), f_hz) - frequency_hz.begin());
    const std::size_t lo = hi - 1;
    const double t =
        std::log(f_hz / frequency_hz[lo]) / std::log(frequency_hz[hi] / frequency_hz[lo]);
    return psa_g[lo] * std::pow(psa_g[hi] / psa_g[lo], t);
}

std::vector<double> log_frequencies(double fmin_hz, double fmax_hz, int per_decade) {
    require_positive(fmin_hz, SourceLocation{"", 0, "fmin_hz"});
    require_positive(fmax_hz, SourceLocation{"", 0, "fmax_hz"});
    if (!(fmax_hz > fmin_hz))
        throw InputError(
            SourceLocation{"", 0, "fmax_hz"},
            fmt::format("fmax {} Hz must be greater than fmin {} Hz", fmax_hz, fmin_hz));
    if (per_decade < 1)
        throw InputError(SourceLocation{"", 0, "per_decade"},
                         fmt::format("{} points per decade; expected an integer >= 1", per_decade));
    // Equal log spacing with at least per_decade points per decade and both ends exact; the
    // tolerance keeps an exact number of decades (0.1-100 Hz: 300 intervals) from rounding up.
    const double decades = std::log10(fmax_hz / fmin_hz);
    const double intervals_wanted =
        std::max(1.0, core::steps_covering(decades * static_cast<double>(per_decade)));
    // The grid's size is per_decade's doing: the limit names it, before the grid is allocated.
    core::limits::require_within(intervals_wanted + 1.0, core::limits::max_frequencies,
                                 SourceLocation{"", 0, "per_decade"},
                                 "the spectrum's frequencies (decades x per decade + 1)");
    const auto intervals = static_cast<std::size_t>(intervals_wanted);
    // Exponents on log10 so that whole decades come out exact (10^0 = 1, 10^1 = 10).
    const double lo = std::log10(fmin_hz);
    const double step = (std::log10(fmax_hz) - lo) / static_cast<double>(intervals);
    std::vector<double> f(intervals + 1);
    for (std::size_t k = 0; k <= intervals; ++k)
        f[k] = std::pow(10.0, lo + step * static_cast<double>(k));
    f.front() = fmin_hz;
    f.back() = fmax_hz;
    return f;
}

namespace {

using core::text::trim;

double parse_number(std::string_view text, const SourceLocation& where, const char* expected) {
    const std::string_view t = trim(text);
    double value = 0.0;
    if (!core::text::parse_double(t, value) || !std::isfinite(value))
        throw InputError(where, fmt::format("expected {}; got \"{}\"", expected, t));
    return value;
}

/// State of the line-by-line reader: what has been seen so far.
struct ReadState {
    Spectrum s;
    bool have_damping = false;
    bool have_header = false;
};

void read_comment(std::string_view body, const std::string& file, int line, ReadState& st) {
    const std::string_view b = trim(body);
    const auto colon = b.find(':');
    if (colon == std::string_view::npos) return;
    const std::string_view key = trim(b.substr(0, colon));
    const std::string_view value = trim(b.substr(colon + 1));
    if (key == "damping") {
        const SourceLocation where{file, line, "damping"};
        if (st.have_damping)
            throw InputError(where, "damping given twice; expected one \"# damping:\" line");
        st.s.damping = parse_number(value, where, "a damping ratio in (0, 1), e.g. 0.05");
        require_in_range(st.s.damping, 0.0, 1.0, where, false, false);
        st.have_damping = true;
    } else if (key == "label") {
        st.s.label = std::string(value);
    }
}

void read_row(std::string_view text, const std::string& file, int line, ReadState& st) {
    const auto comma = text.find(',');
    if (comma == std::string_view::npos || text.find(',', comma + 1) != std::string_view::npos)
        throw InputError(
            SourceLocation{file, line, ""},
            fmt::format("expected two columns \"frequency_hz,psa_g\"; got \"{}\"", text));
    const SourceLocation at_f{file, line, "frequency_hz"};
    const SourceLocation at_psa{file, line, "psa_g"};
    const double f = parse_number(text.substr(0, comma), at_f, "a frequency in Hz");
    const double psa = parse_number(text.substr(comma + 1), at_psa, "a PSA in g");
    if (!(f > 0.0)) throw InputError(at_f, fmt::format("frequency {} Hz must be > 0", f));
    if (!st.s.frequency_hz.empty() && !(f > st.s.frequency_hz.back()))
        throw InputError(at_f,
                         fmt::format("frequency {} Hz does not increase (previous row {} Hz); "
                                     "expected strictly increasing frequencies",
                                     f, st.s.frequency_hz.back()));
    if (!(psa > 0.0)) throw InputError(at_psa, fmt::format("PSA {} g must be > 0", psa));
    st.s.frequency_hz.push_back(f);
    st.s.psa_g.push_back(psa);
}

}  // namespace

Spectrum read_spectrum_csv(const std::filesystem::path& path) {
    return parse_spectrum_csv(core::read_input_file(path), path.string());
}

Spectrum parse_spectrum_csv(const std::string& whole, const std::string& file) {
    const std::string_view text = core::text::utf8_text(whole, file);
    ReadState st;
    st.s.label = std::filesystem::path(file).stem().string();
    int line = 0;
    std::size_t pos = 0;
    while (pos < text.size()) {
        const auto nl = text.find('\n', pos);
        const std::size_t end = nl == std::string::npos ? text.size() : nl;
        const std::string_view raw = trim(text.substr(pos, end - pos));
        pos = end + 1;
        ++line;
        if (raw.empty()) continue;
        if (raw.front() == '#') {
            if (st.have_header)
                throw InputError(SourceLocation{file, line, ""},
                                 "comment after the header; expected '#' lines only before "
                                 "\"frequency_hz,psa_g\"");
            read_comment(raw.substr(1), file, line, st);
            continue;
        }
        if (!st.have_header) {
            if (!st.have_damping)
                throw InputError(SourceLocation{file, line, "damping"},
                                 "no \"# damping: <ratio>\" line before the header; expected one, "
                                 "e.g. \"# damping: 0.05\"");
            if (raw != "frequency_hz,psa_g")
                throw InputError(
                    SourceLocation{file, line, "header"},
                    fmt::format("expected the header \"frequency_hz,psa_g\"; got \"{}\"", raw));
            st.have_header = true;
            continue;
        }
        read_row(raw, file, line, st);
    }
    if (!st.have_damping)
        throw InputError(SourceLocation{file, line, "damping"},
                         "no \"# damping: <ratio>\" line; expected one, e.g. \"# damping: 0.05\"");
    if (!st.have_header)
        throw InputError(SourceLocation{file, line, "header"},
                         "no header line; expected \"frequency_hz,psa_g\" after the comments");
    if (st.s.frequency_hz.size() < 2)
        throw InputError(
            SourceLocation{file, line, ""},
            fmt::format("{} data rows; expected at least 2", st.s.frequency_hz.size()));
    return st.s;
}

void write_spectrum_csv(const Spectrum& s, const std::filesystem::path& path,
                        const std::vector<std::string>& comments) {
    if (s.frequency_hz.size() != s.psa_g.size() || s.frequency_hz.size() < 2)
        throw InputError(
            SourceLocation{path.string(), 0, "spectrum"},
            fmt::format("{} frequencies and {} PSA values; expected the same number, >= 2",
                        s.frequency_hz.size(), s.psa_g.size()));
    std::string out;
    for (const auto& c : comments) out += "# " + c + "\n";
    if (!s.label.empty()) out += "# label: " + s.label + "\n";
    // Shortest round-trip representation: reading the file back gives the same doubles.
    out += fmt::format("# damping: {}\nfrequency_hz,psa_g\n", s.damping);
    for (std::size_t i = 0; i < s.frequency_hz.size(); ++i)
        out += fmt::format("{},{}\n", s.frequency_hz[i], s.psa_g[i]);
    core::write_file_atomic(path, out);
}

Spectrum combine_vector_horizontal(const Spectrum& h1, const Spectrum& h2) {
    // The components' spectra are computed at, or read with, one stated damping: equal to
    // their last digits, a far tighter test than core::tol::damping_equal's against a method.
    constexpr double same_damping = 1e-12;
    if (std::abs(h1.damping - h2.damping) > same_damping)
        throw InputError(SourceLocation{"", 0, "damping"},
                         fmt::format("cannot combine spectra at dampings {} and {}; expected equal",
                                     h1.damping, h2.damping));
    Spectrum out;
    out.damping = h1.damping;
    out.label = fmt::format("vector horizontal of {} and {}", h1.label, h2.label);
    out.frequency_hz = h1.frequency_hz;
    out.psa_g.resize(h1.frequency_hz.size());
    for (std::size_t i = 0; i < h1.frequency_hz.size(); ++i) {
        const double a = h1.psa_g[i];
        const double b = h2.psa_at(h1.frequency_hz[i]);
        const double big = std::max(a, b);
        const double small = std::min(a, b);
        out.psa_g[i] = std::sqrt(big * big + 0.16 * small * small);
    }
    return out;
}

}  // namespace freestand::spectra
