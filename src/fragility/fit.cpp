#include "fragility/fit.hpp"

#include <fmt/format.h>

#include <array>
#include <boost/math/distributions/chi_squared.hpp>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "core/statistics.hpp"
#include "fragility/probit_detail.hpp"

namespace freestand::fragility {
namespace {

using detail::log_phi_cdf;
using detail::mills;

constexpr double kMinBeta = detail::min_beta;
constexpr int kMaxIterations = 200;
// Fisher scoring stops once the log-likelihood moves by less than this fraction of itself.
constexpr double kLogLikelihoodRelTol = 1e-12;

struct Levels {
    std::vector<double> x;  // ln a
    std::vector<double> k, n;
};

// The probit parameters (a0, a1); two unknowns, so the solves below are written out rather
// than taken from a linear-algebra library.
using Params = std::array<double, 2>;

bool finite(const Params& p) { return std::isfinite(p[0]) && std::isfinite(p[1]); }

// Solves [[s00, s01], [s01, s11]] x = b by Cramer's rule; non-finite when singular.
Params solve_symmetric_2x2(double s00, double s01, double s11, const Params& b) {
    const double det = s00 * s11 - s01 * s01;
    return {(s11 * b[0] - s01 * b[1]) / det, (s00 * b[1] - s01 * b[0]) / det};
}

double log_likelihood(const Levels& l, double a0, double a1) {
    double sum = 0.0;
    for (std::size_t j = 0; j < l.x.size(); ++j) {
        const double z = a0 + a1 * l.x[j];
        sum += l.k[j] * log_phi_cdf(z) + (l.n[j] - l.k[j]) * log_phi_cdf(-z);
    }
    return sum;
}

// Fisher scoring for the probit model P = Phi(a0 + a1 ln a): gradient from the Mills ratios,
// expected information n phi^2 / (Phi (1 - Phi)), step halved while the likelihood falls.
std::optional<Params> maximise(const Levels& l, Params start) {
    Params p = start;
    double current = log_likelihood(l, p[0], p[1]);
    for (int it = 0; it < kMaxIterations; ++it) {
        Params g{0.0, 0.0};
        double i00 = 0.0, i01 = 0.0, i11 = 0.0;  // the information matrix, symmetric
        for (std::size_t j = 0; j < l.x.size(); ++j) {
            const double x = l.x[j];
            const double z = p[0] + p[1] * x;
            const double dz = l.k[j] * mills(z) - (l.n[j] - l.k[j]) * mills(-z);
            const double w = l.n[j] * mills(z) * mills(-z);  // n phi^2 / (Phi (1 - Phi))
            g[0] += dz;
            g[1] += dz * x;
            i00 += w;
            i01 += w * x;
            i11 += w * x * x;
        }
        Params step = solve_symmetric_2x2(i00, i01, i11, g);
        if (!finite(step)) return std::nullopt;
        double next = log_likelihood(l, p[0] + step[0], p[1] + step[1]);
        for (int h = 0; h < 40 && !(next >= current); ++h) {
            step[0] *= 0.5;
            step[1] *= 0.5;
            next = log_likelihood(l, p[0] + step[0], p[1] + step[1]);
        }
        p[0] += step[0];
        p[1] += step[1];
        if (!finite(p)) return std::nullopt;
        const bool done = std::abs(next - current) <= kLogLikelihoodRelTol * (1.0 + std::abs(next));
        current = next;
        if (done || 1.0 / p[1] < kMinBeta * 0.5) break;
    }
    return p;
}

// (Quasi-)complete separation: no failure below some level and only failures above it (that
// level itself anything). The likelihood then has no finite maximum (Albert & Anderson 1984):
// a step at that level fits its own fraction exactly and every other level perfectly. Returns
// the level's index.
std::optional<std::size_t> separating_level(const Levels& l) {
    for (std::size_t m = 0; m < l.x.size(); ++m) {
        bool below = true, above = true;
        for (std::size_t j = 0; j < m; ++j) below = below && l.k[j] == 0.0;
        for (std::size_t j = m + 1; j < l.x.size(); ++j) above = above && l.k[j] == l.n[j];
        if (below && above) return m;
    }
    return std::nullopt;
}

std::string separation_note(const Levels& l, std::size_t m) {
    const double a = std::exp(l.x[m]);
    const std::string where =
        m + 1 == l.x.size() ? fmt::format("failures only at the highest level, {:g} g", a)
        : m == 0 ? fmt::format("every sample fails above the lowest level, {:g} g", a)
                 : fmt::format("none below {:g} g, only failures above it", a);
    const std::string needed = m + 1 == l.x.size() ? "levels above it are needed"
                               : m == 0           ? "levels below it are needed"
                                                  : "levels between its neighbours are needed";
    return fmt::format(
        "the levels separate failures perfectly: {} ({} of {} there); the likelihood grows as "
        "beta -> 0 (a step at about {:g} g, not a curve); {}",
        where, l.k[m], l.n[m], a, needed);
}

// The levels that have samples, on ln a.
Levels observed_levels(const std::vector<double>& pga_g, const std::vector<int>& k,
                       const std::vector<int>& n) {
    Levels l;
    for (std::size_t j = 0; j < pga_g.size(); ++j) {
        if (n[j] <= 0) continue;
        l.x.push_back(std::log(pga_g[j]));
        l.k.push_back(k[j]);
        l.n.push_back(n[j]);
    }
    return l;
}

// Why no curve can be fitted to the levels, when that is known before fitting.
std::optional<std::string> unfittable(const Levels& l) {
    double failures = 0.0, total = 0.0;
    for (std::size_t j = 0; j < l.x.size(); ++j) {
        failures += l.k[j];
        total += l.n[j];
    }
    if (l.x.size() < 2) return "a lognormal curve needs at least two levels";
    if (failures == 0.0) return "no level has a failure";
    if (failures == total)
        return "every sample fails at every level: the median lies below the lowest level";
    if (const auto m = separating_level(l)) return separation_note(l, *m);
    return std::nullopt;
}

// Least squares on the empirical probits (continuity-corrected): the straight line
// z = a0 + a1 x through the points, by its normal equations; a unit slope through the lowest
// level when that line does not rise.
Params probit_start(const Levels& l) {
    double sx = 0.0, sxx = 0.0, sz = 0.0, sxz = 0.0;
    for (std::size_t j = 0; j < l.x.size(); ++j) {
        const double z = core::normal_quantile((l.k[j] + 0.5) / (l.n[j] + 1.0));
        sx += l.x[j];
        sxx += l.x[j] * l.x[j];
        sz += z;
        sxz += l.x[j] * z;
    }
    const Params ls =
        solve_symmetric_2x2(static_cast<double>(l.x.size()), sx, sxx, Params{sz, sxz});
    return finite(ls) && ls[1] > 0.0 ? ls : Params{-l.x.front(), 1.0};
}

// The fitted curve's parameters, fractiles and goodness of fit (Pearson's chi-squared).
Fit fit_of(const Levels& l, const Params& p) {
    Fit f;
    f.beta = 1.0 / p[1];
    f.theta_m_g = std::exp(-p[0] * f.beta);
    f.pga_1pct_g = f.theta_m_g * std::exp(f.beta * core::normal_quantile(0.01));
    f.pga_5pct_g = f.theta_m_g * std::exp(f.beta * core::normal_quantile(0.05));
    f.pga_50pct_g = f.theta_m_g;
    f.log_likelihood = log_likelihood(l, p[0], p[1]);
    for (std::size_t j = 0; j < l.x.size(); ++j) {
        const double pj = core::normal_cdf(p[0] + p[1] * l.x[j]);
        const double var = l.n[j] * pj * (1.0 - pj);
        if (var > 0.0) f.chi2 += std::pow(l.k[j] - l.n[j] * pj, 2) / var;
    }
    f.dof = static_cast<int>(l.x.size()) - 2;
    if (f.dof >= 1)
        f.p_value = boost::math::cdf(
            boost::math::complement(boost::math::chi_squared_distribution<>(f.dof), f.chi2));
    return f;
}

}  // namespace

EventFit fit_lognormal(const std::vector<double>& pga_g, const std::vector<int>& k,
                       const std::vector<int>& n) {
    if (pga_g.size() != k.size() || k.size() != n.size())
        throw std::invalid_argument("fit_lognormal: sizes differ");
    const Levels l = observed_levels(pga_g, k, n);
    EventFit out;
    if (auto why = unfittable(l)) {
        out.note = std::move(*why);
        return out;
    }
    const auto p = maximise(l, probit_start(l));
    if (!p || !((*p)[1] > 0.0)) {
        out.note = p ? "failures do not increase with the PGA: no increasing lognormal fits"
                     : "the likelihood has no finite maximum";
        return out;
    }
    if (1.0 / (*p)[1] < kMinBeta) {
        out.note = "the fit tends to a step (beta -> 0): more samples or levels between are needed";
        return out;
    }
    out.fit = fit_of(l, *p);
    return out;
}

double fitted_p(const Fit& fit, double a_g) {
    return core::normal_cdf(std::log(a_g / fit.theta_m_g) / fit.beta);
}

std::vector<CurvePoint> fitted_curve(const Fit& fit, double lo_g, double hi_g, int intervals) {
    std::vector<CurvePoint> out;
    for (int i = 0; i <= intervals; ++i) {
        const double a = lo_g * std::pow(hi_g / lo_g, i / static_cast<double>(intervals));
        out.push_back({a, fitted_p(fit, a)});
    }
    return out;
}

}  // namespace freestand::fragility
