#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "core/statistics.hpp"
#include "fragility/fit.hpp"
#include "fragility/probit_detail.hpp"

namespace freestand::fragility {
namespace {

// The probit model centred on the PGA asked for: z_j = z0 + c x_j with x_j = ln(a_j / a), so z0
// is Phi^-1 of P(a) and c = 1 / beta. ln L is concave in (z0, c) (ln Phi is concave), so the
// profile max over c is concave in z0 and every search below looks for the one crossing of a
// monotone derivative or function.
struct Centred {
    std::vector<double> x, k, n;
};

// |z0| beyond this is P within 1e-19 of 0 or 1.
constexpr double kZ = 9.0;
constexpr double kMaxSlope = 1.0 / detail::min_beta;
constexpr int kMaxIterations = 200;
// The profile's slope c is solved to this fraction of itself: far below the digits written.
constexpr double kSlopeRelTol = 1e-13;
// A probability this close to 0 or 1 is written as 0 or 1 (fit.hpp: level probabilities).
constexpr double kWrittenCertain = 1e-15;

double log_likelihood(const Centred& l, double z0, double c) {
    double sum = 0.0;
    for (std::size_t j = 0; j < l.x.size(); ++j) {
        const double z = z0 + c * l.x[j];
        sum += l.k[j] * detail::log_phi_cdf(z) + (l.n[j] - l.k[j]) * detail::log_phi_cdf(-z);
    }
    return sum;
}

// d ln L / dz_j of level j, and its derivative (d/dz mills(z) = -mills(z) (z + mills(z))).
double score(const Centred& l, std::size_t j, double z) {
    return l.k[j] * detail::mills(z) - (l.n[j] - l.k[j]) * detail::mills(-z);
}
double score_slope(const Centred& l, std::size_t j, double z) {
    const double up = detail::mills(z), down = detail::mills(-z);
    return -l.k[j] * up * (z + up) - (l.n[j] - l.k[j]) * down * (down - z);
}

// The profile over the slope, remembering the last best slope: successive calls ask for
// nearby z0, so Newton's method from there needs a step or two.
class Profile {
  public:
    explicit Profile(const Centred& l) : l_(l) {}

    // The c in [0, 1 / min_beta] that maximises ln L at z0, where d ln L / dc (falling, ln L
    // being concave) changes sign: Newton's steps kept inside the bracket, else halving it.
    double best_slope(double z0) {
        if (d_dc(z0, 0.0) <= 0.0) return last_ = 0.0;
        if (d_dc(z0, kMaxSlope) >= 0.0) return last_ = kMaxSlope;
        double lo = 0.0, hi = kMaxSlope, c = last_ > lo && last_ < hi ? last_ : 1.0;
        for (int i = 0; i < kMaxIterations; ++i) {
            double d1 = 0.0, d2 = 0.0;
            for (std::size_t j = 0; j < l_.x.size(); ++j) {
                const double z = z0 + c * l_.x[j];
                d1 += l_.x[j] * score(l_, j, z);
                d2 += l_.x[j] * l_.x[j] * score_slope(l_, j, z);
            }
            (d1 > 0.0 ? lo : hi) = c;
            double next = d2 < 0.0 ? c - d1 / d2 : 0.5 * (lo + hi);
            if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
            const bool done = std::abs(next - c) <= kSlopeRelTol * (1.0 + c) ||
                              hi - lo <= kSlopeRelTol * hi;
            c = next;
            if (done) break;
        }
        return last_ = c;
    }

    // max over c of ln L at z0.
    double value(double z0) { return log_likelihood(l_, z0, best_slope(z0)); }

    // d value / dz0: the partial derivative at the best slope (Danskin's theorem).
    double slope(double z0) {
        const double c = best_slope(z0);
        double sum = 0.0;
        for (std::size_t j = 0; j < l_.x.size(); ++j) sum += score(l_, j, z0 + c * l_.x[j]);
        return sum;
    }

  private:
    double d_dc(double z0, double c) const {
        double sum = 0.0;
        for (std::size_t j = 0; j < l_.x.size(); ++j)
            sum += l_.x[j] * score(l_, j, z0 + c * l_.x[j]);
        return sum;
    }

    const Centred& l_;
    double last_ = 1.0;
};

// The z in [lo, hi] where the monotone f crosses 0, f(lo) and f(hi) of opposite signs
// (Alefeld, Potra & Shi 1995, TOMS 748, as Boost.Math implements it), to about 1e-12.
template <class F>
double crossing(F f, double lo, double hi) {
    std::uintmax_t iterations = kMaxIterations;
    const auto bracket = boost::math::tools::toms748_solve(
        f, lo, hi, f(lo), f(hi), boost::math::tools::eps_tolerance<double>(40), iterations);
    return 0.5 * (bracket.first + bracket.second);
}

double probability_of(double z0) {
    if (z0 <= -kZ) return 0.0;
    if (z0 >= kZ) return 1.0;
    const double p = core::normal_cdf(z0);
    return p < kWrittenCertain ? 0.0 : (p > 1.0 - kWrittenCertain ? 1.0 : p);
}

}  // namespace

Probability probability_at(const std::vector<double>& pga_g, const std::vector<int>& k,
                           const std::vector<int>& n, double a_g) {
    if (pga_g.size() != k.size() || k.size() != n.size())
        throw std::invalid_argument("probability_at: sizes differ");
    if (!(a_g > 0.0)) throw std::invalid_argument("probability_at: a_g must be > 0");
    Centred l;
    for (std::size_t j = 0; j < pga_g.size(); ++j) {
        if (n[j] <= 0) continue;
        l.x.push_back(std::log(pga_g[j] / a_g));
        l.k.push_back(k[j]);
        l.n.push_back(n[j]);
    }
    if (l.x.empty()) throw std::invalid_argument("probability_at: no level has samples");
    Profile profile(l);
    const auto slope = [&](double z0) { return profile.slope(z0); };
    double z_hat = -kZ;
    if (slope(kZ) >= 0.0) {
        z_hat = kZ;
    } else if (slope(-kZ) > 0.0) {
        z_hat = crossing(slope, -kZ, kZ);
    }
    const double half_chi2 =
        0.5 * boost::math::quantile(boost::math::chi_squared_distribution<>(1.0), 0.95);
    const double floor_ll = profile.value(z_hat) - half_chi2;
    const auto above = [&](double z) { return profile.value(z) - floor_ll; };
    const double z_lo = above(-kZ) >= 0.0 ? -kZ : crossing(above, -kZ, z_hat);
    const double z_hi = above(kZ) >= 0.0 ? kZ : crossing(above, z_hat, kZ);
    return Probability{probability_of(z_hat), {probability_of(z_lo), probability_of(z_hi)}};
}

}  // namespace freestand::fragility
