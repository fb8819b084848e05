#include "spectra/design.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "core/errors.hpp"
#include "core/units.hpp"

namespace freestand::spectra {

namespace {

void check_frequencies(const std::vector<double>& f) {
    if (f.empty())
        throw InputError(SourceLocation{"", 0, "frequency_hz"},
                         "no frequency given; expected at least one");
    for (std::size_t i = 0; i < f.size(); ++i) {
        require_positive(f[i], SourceLocation{"", 0, "frequency_hz"});
        if (i > 0 && !(f[i] > f[i - 1]))
            throw InputError(
                SourceLocation{"", 0, "frequency_hz"},
                fmt::format("frequency {} Hz follows {} Hz; expected strictly increasing", f[i],
                            f[i - 1]));
    }
}

/// Builds a Spectrum by evaluating psa_of_period(T) at each frequency.
template <class F>
Spectrum tabulate(double damping, std::string label, const std::vector<double>& frequency_hz,
                  F psa_of_period) {
    check_frequencies(frequency_hz);
    Spectrum s;
    s.damping = damping;
    s.label = std::move(label);
    s.frequency_hz = frequency_hz;
    s.psa_g.reserve(frequency_hz.size());
    for (double f : frequency_hz) s.psa_g.push_back(psa_of_period(1.0 / f));
    return s;
}

// RG 1.60 Tables I and II (docs/methods.md s.8): A / B / C / D per damping.
constexpr const std::array<double, 5>& rg_damping = rg160_dampings;
constexpr std::array<Rg160Factors, 5> rg_horizontal{{{1.0, 4.96, 5.95, 3.20},
                                                     {1.0, 3.54, 4.25, 2.50},
                                                     {1.0, 2.61, 3.13, 2.05},
                                                     {1.0, 2.27, 2.72, 1.88},
                                                     {1.0, 1.90, 2.28, 1.70}}};
constexpr std::array<Rg160Factors, 5> rg_vertical{{{1.0, 4.96, 5.67, 2.13},
                                                   {1.0, 3.54, 4.05, 1.67},
                                                   {1.0, 2.61, 2.98, 1.37},
                                                   {1.0, 2.27, 2.59, 1.25},
                                                   {1.0, 1.90, 2.17, 1.13}}};
constexpr double rg_ground_displacement_m_per_g = 0.9144;  // 36 in per 1 g (RG 1.60)

/// Log-log straight line through (x0, y0) and (x1, y1), evaluated at x.
double loglog(double x, double x0, double y0, double x1, double y1) {
    return y0 * std::pow(y1 / y0, std::log(x / x0) / std::log(x1 / x0));
}

}  // namespace

Rg160Factors rg160_factors(double damping, bool vertical) {
    require_in_range(damping, rg_damping.front(), rg_damping.back(),
                     SourceLocation{"", 0, "damping"});
    const auto& table = vertical ? rg_vertical : rg_horizontal;
    std::size_t hi = 1;
    while (hi + 1 < rg_damping.size() && damping > rg_damping[hi]) ++hi;
    const std::size_t lo = hi - 1;
    // Linear in ln(damping) between the bracketing table rows; exact at the rows.
    const double t = std::log(damping / rg_damping[lo]) / std::log(rg_damping[hi] / rg_damping[lo]);
    const auto mix = [t](double a, double b) { return a + t * (b - a); };
    return {mix(table[lo].a, table[hi].a), mix(table[lo].b, table[hi].b),
            mix(table[lo].c, table[hi].c), mix(table[lo].d, table[hi].d)};
}

Spectrum rg160(double pga_g, double damping, bool vertical,
               const std::vector<double>& frequency_hz, double g_mps2) {
    require_positive(pga_g, SourceLocation{"", 0, "pga_g"});
    const Rg160Factors k = rg160_factors(damping, vertical);
    const double fa = 33.0, fb = 9.0, fc = vertical ? 3.5 : 2.5, fd = 0.25;
    const double wd = units::hz_to_radps(fd);
    // D multiplies the ground displacement; as PSA at 0.25 Hz: omega^2 SD / g.
    const double psa_d = k.d * rg_ground_displacement_m_per_g * pga_g * wd * wd / g_mps2;
    const double psa_a = k.a * pga_g, psa_b = k.b * pga_g, psa_c = k.c * pga_g;
    const std::string label =
        fmt::format("RG 1.60 {}, PGA {} g, {}% damping", vertical ? "vertical" : "horizontal",
                    pga_g, 100.0 * damping);
    return tabulate(damping, label, frequency_hz, [=](double period_s) {
        const double f = 1.0 / period_s;
        if (f >= fa) return psa_a;
        if (f >= fb) return loglog(f, fb, psa_b, fa, psa_a);
        if (f >= fc) return loglog(f, fc, psa_c, fb, psa_b);
        if (f >= fd) return loglog(f, fd, psa_d, fc, psa_c);
        return psa_d * (f / fd) * (f / fd);  // constant spectral displacement
    });
}

Spectrum asce7(double sds_g, double sd1_g, double tl_s, const std::vector<double>& frequency_hz) {
    require_positive(sds_g, SourceLocation{"", 0, "sds_g"});
    require_positive(sd1_g, SourceLocation{"", 0, "sd1_g"});
    require_positive(tl_s, SourceLocation{"", 0, "tl_s"});
    const double ts = sd1_g / sds_g;
    const double t0 = 0.2 * ts;
    if (!(tl_s > ts))
        throw InputError(SourceLocation{"", 0, "tl_s"},
                         fmt::format("TL {} s must exceed TS = SD1/SDS = {} s", tl_s, ts));
    const std::string label =
        fmt::format("ASCE 7, SDS {} g, SD1 {} g, TL {} s, 5% damping", sds_g, sd1_g, tl_s);
    return tabulate(0.05, label, frequency_hz, [=](double t) {
        if (t < t0) return sds_g * (0.4 + 0.6 * t / t0);
        if (t <= ts) return sds_g;
        if (t <= tl_s) return sd1_g / t;
        return sd1_g * tl_s / (t * t);
    });
}

Spectrum ec8(double ag_g, Ec8Type type, char ground, double damping,
             const std::vector<double>& frequency_hz) {
    require_positive(ag_g, SourceLocation{"", 0, "ag_g"});
    require_in_range(damping, 0.0, 1.0, SourceLocation{"", 0, "damping"}, false, false);
    struct Ground {
        double s, tb, tc, td;
    };
    // EN 1998-1 Tables 3.2 (Type 1) and 3.3 (Type 2), recommended values.
    constexpr std::array<Ground, 5> type1{{{1.0, 0.15, 0.4, 2.0},
                                           {1.2, 0.15, 0.5, 2.0},
                                           {1.15, 0.20, 0.6, 2.0},
                                           {1.35, 0.20, 0.8, 2.0},
                                           {1.4, 0.15, 0.5, 2.0}}};
    constexpr std::array<Ground, 5> type2{{{1.0, 0.05, 0.25, 1.2},
                                           {1.35, 0.05, 0.25, 1.2},
                                           {1.5, 0.10, 0.25, 1.2},
                                           {1.8, 0.10, 0.30, 1.2},
                                           {1.6, 0.05, 0.25, 1.2}}};
    if (ground < 'A' || ground > 'E')
        throw InputError(SourceLocation{"", 0, "ground"},
                         fmt::format("ground type '{}'; expected one of A, B, C, D, E", ground));
    const Ground g =
        (type == Ec8Type::type1 ? type1 : type2)[static_cast<std::size_t>(ground - 'A')];
    // EN 1998-1 eq. (3.6), xi in percent.
    const double eta = std::max(0.55, std::sqrt(10.0 / (5.0 + 100.0 * damping)));
    const double plateau = ag_g * g.s * eta * 2.5;
    const std::string label =
        fmt::format("EC8 Type {}, ground {}, ag {} g, {}% damping", type == Ec8Type::type1 ? 1 : 2,
                    ground, ag_g, 100.0 * damping);
    // EN 1998-1 eqs. (3.2)-(3.5).
    return tabulate(damping, label, frequency_hz, [=](double t) {
        if (t <= g.tb) return ag_g * g.s * (1.0 + t / g.tb * (eta * 2.5 - 1.0));
        if (t <= g.tc) return plateau;
        if (t <= g.td) return plateau * g.tc / t;
        return plateau * g.tc * g.td / (t * t);
    });
}

Spectrum is1893(double pga_g, Is1893Soil soil, const std::vector<double>& frequency_hz) {
    require_positive(pga_g, SourceLocation{"", 0, "pga_g"});
    // IS 1893 (Part 1) 2016 eq. for Sa/g: corner period and the 1/T coefficient per soil.
    const double tc = soil == Is1893Soil::rock ? 0.40 : soil == Is1893Soil::medium ? 0.55 : 0.67;
    const double k = soil == Is1893Soil::rock ? 1.0 : soil == Is1893Soil::medium ? 1.36 : 1.67;
    const char* name = soil == Is1893Soil::rock     ? "rock"
                       : soil == Is1893Soil::medium ? "medium"
                                                    : "soft";
    const std::string label = fmt::format("IS 1893 {} soil, PGA {} g, 5% damping", name, pga_g);
    return tabulate(0.05, label, frequency_hz, [=](double t) {
        double sa = 0.0;
        if (t < 0.1)
            sa = 1.0 + 15.0 * t;
        else if (t <= tc)
            sa = 2.5;
        else if (t <= 4.0)
            sa = k / t;
        else
            sa = k / 4.0;
        return pga_g * sa;
    });
}

double rg160_target_psd_per_radps(double f_hz, double pga_g) {
    require_positive(f_hz, SourceLocation{"", 0, "f_hz"});
    require_positive(pga_g, SourceLocation{"", 0, "pga_g"});
    // SRP 3.7.1 Appendix A, per 1 g, m^2/s^3; scales with PGA^2.
    double s1 = 0.0;
    if (f_hz <= 2.5)
        s1 = 0.419 * std::pow(f_hz / 2.5, 0.2);
    else if (f_hz <= 9.0)
        s1 = 0.419 * std::pow(2.5 / f_hz, 1.8);
    else if (f_hz <= 16.0)
        s1 = 0.0418 * std::pow(9.0 / f_hz, 3.0);
    else
        s1 = 0.00742 * std::pow(16.0 / f_hz, 8.0);
    return s1 * pga_g * pga_g;
}

double rg160_target_psd(double f_hz, double pga_g) {
    // d omega = 2 pi df: a density per rad/s is 2 pi times larger per Hz.
    return units::two_pi * rg160_target_psd_per_radps(f_hz, pga_g);
}

}  // namespace freestand::spectra
