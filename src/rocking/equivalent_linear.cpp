#include "rocking/equivalent_linear.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "core/tolerances.hpp"
#include "core/errors.hpp"
#include "core/units.hpp"

namespace freestand::rocking {

using block::Block;
using block::Edge;

namespace {

SourceLocation field(const char* name) { return SourceLocation{"", 0, name}; }

// The roots f_e and theta0 are solved to this fraction of their scale (f_g, alpha): far below
// any digit a report prints, yet a few hundred ulps, so that the iterations end.
constexpr double root_rel_tol = 1e-13;

// The spectral margin, a factor on the spectra, is bisected to this fraction of itself
// (equivalent_linear.hpp: "to relative 1e-6"); reports print it to 4 significant digits.
constexpr double margin_rel_tol = 1e-6;

// Everything one trial angle needs, at one scale of the spectra.
struct Scan {
    double p_radps;
    double alpha;
    double R_m;
    const DampedDemand& h;
    const DampedDemand* v;  // vertical spectra, or null: SA_V = ratio * SA_H
    double ratio;
    double scale;
    double g_mps2;

    double sa_v_g(double f) const { return scale * (v ? v->psa_g(f) : ratio * h.psa_g(f)); }
    bool has_vertical() const { return v != nullptr || ratio > 0.0; }

    // f_e with gravity g (1 - 0.4 SA_V(f_e)): p scales with sqrt(g), so f_e solves
    // f = f_g sqrt(q(f)). Residual f - f_g sqrt(q(f)) is >= 0 at f_g (q <= 1) and < 0 as f -> 0
    // (psa_at -> 0 there, q -> 1), so (0, f_g] brackets a root. Safeguarded fixed-point
    // iteration: the image f_g sqrt(q(f)) is taken when it falls inside the bracket and the
    // bracket halved at least every other step; otherwise bisection (a steep SA_V makes the map
    // expansive).
    double frequency_hz(double theta) const {
        const double fg = rocking_frequency_hz(p_radps, alpha, theta);
        if (!has_vertical()) return fg;
        auto image = [&](double f) { return fg * std::sqrt(std::max(0.0, 1.0 - 0.4 * sa_v_g(f))); };
        double lo = 0.0, hi = fg, f = fg, width = fg;
        for (int it = 0; it < 200; ++it) {
            const double next = image(f);
            if (std::abs(next - f) <= root_rel_tol * fg) return next;
            (f - next < 0.0 ? lo : hi) = f;
            const bool shrunk = hi - lo <= 0.5 * width;
            if (shrunk) width = hi - lo;
            f = (next > lo && next < hi && (shrunk || it % 2 == 0)) ? next : 0.5 * (lo + hi);
            if (hi - lo <= root_rel_tol * fg) return f;
        }
        return f;
    }

    // Demand minus capacity, g.
    double excess_g(double theta, double* f_out = nullptr, double* demand_out = nullptr) const {
        const double f = frequency_hz(theta);
        const double w = units::hz_to_radps(f);
        const double capacity = w * w * rocking_displacement_m(R_m, alpha, theta) / g_mps2;
        const double demand = scale * h.psa_g(f);
        if (f_out) *f_out = f;
        if (demand_out) *demand_out = demand;
        return demand - capacity;
    }

    // First grid angle with demand <= capacity, refined by bisection against the previous one.
    // The grid is alpha k / n, k = 1..n-1, closed by alpha (1 - core::tol::relative) so that the last interval
    // below alpha is not skipped (a demand just inside the block's reach).
    std::optional<double> theta0(int n) const {
        double prev = 0.0;
        for (int k = 1; k <= n; ++k) {
            const double th = k < n ? alpha * static_cast<double>(k) / static_cast<double>(n)
                                    : alpha * (1.0 - core::tol::relative);
            if (excess_g(th) <= 0.0) {
                double lo = prev, hi = th;
                for (int it = 0; it < 100 && hi - lo > root_rel_tol * alpha; ++it) {
                    const double mid = 0.5 * (lo + hi);
                    (excess_g(mid) <= 0.0 ? hi : lo) = mid;
                }
                return hi;
            }
            prev = th;
        }
        return std::nullopt;
    }
};

struct Context {
    const Block& blk;
    Edge e;
    const DampedDemand& h;
    const DampedDemand* v;
    double ratio;
    double pga_h;
    double pga_v;
    int n;
    double g_mps2;

    Scan scan(double scale) const {
        return Scan{blk.p_radps(e, g_mps2), blk.alpha_rad(e), blk.R_m(e), h, v, ratio, scale, g_mps2};
    }
    bool gate_exceeded(double scale) const {
        return scale * pga_h > (1.0 - 0.4 * scale * pga_v) * blk.tan_alpha(e);
    }
    bool finds(double scale) const {
        return !gate_exceeded(scale) || scan(scale).theta0(n).has_value();
    }
};

void spectral_margin(const Context& c, ElResult& r) {
    constexpr double max_scale = 1e6;
    double lo = 0.0, hi = 1.0;
    if (c.finds(1.0)) {
        lo = 1.0;
        while (c.finds(hi = 2.0 * lo)) {
            lo = hi;
            if (lo > max_scale) {
                r.spectral_margin_reason =
                    fmt::format("theta0 < alpha at every scale up to {:g}", max_scale);
                return;
            }
        }
    }
    while (hi - lo > margin_rel_tol * hi) {
        const double mid = 0.5 * (lo + hi);
        (c.finds(mid) ? lo : hi) = mid;
    }
    r.spectral_margin = lo;
}

void check_options(const ElOptions& o, const VerticalDemand& v) {
    // r = 0 (no rebound) is a valid restitution: the estimate is then not applicable.
    if (o.restitution) require_in_range(*o.restitution, 0.0, 1.0, field("restitution"));
    require_positive(o.fs_required, field("fs_required"));
    if (o.pga_h_g) require_in_range(*o.pga_h_g, 0.0, HUGE_VAL, field("pga_h_g"), true, false);
    if (o.pga_v_g) require_in_range(*o.pga_v_g, 0.0, HUGE_VAL, field("pga_v_g"), true, false);
    require_in_range(v.ratio, 0.0, HUGE_VAL, field("vertical ratio"), true, false);
    require_in_range(o.grid_points, 10.0, 1e7, field("grid_points"));
}

// Below the gate: theta0 = 0 whatever the spectrum or the restitution.
void no_rocking(ElResult& r) {
    r.theta0_rad = 0.0;
    r.theta0_reason = fmt::format("no rocking: PGA {:.4g} g <= gate (1 - 0.4 A_v) tan(alpha) "
                                  "= {:.4g} g",
                                  r.pga_h_g, r.gate_g);
    r.fs_reason = "no rocking predicted: the factor of safety is unbounded";
    r.fs_ok = true;
}

void estimate_theta0(const Context& c, ElResult& r) {
    if (!r.gate_exceeded) {
        no_rocking(r);
        return;
    }
    const Scan s = c.scan(1.0);
    r.theta0_rad = s.theta0(c.n);
    if (!r.theta0_rad) {
        r.overturning_predicted = true;
        r.theta0_reason = "demand exceeds capacity for every theta0 < alpha: overturning predicted";
        r.fs_reason = r.theta0_reason;
        return;
    }
    double f = 0.0, demand = 0.0;
    s.excess_g(*r.theta0_rad, &f, &demand);
    r.f_e_hz = f;
    r.demand_g = demand;
    r.fs = r.alpha_rad / *r.theta0_rad;
    r.fs_ok = *r.fs >= r.fs_required;
}

}  // namespace

double rocking_frequency_hz(double p_radps, double alpha_rad, double theta0_rad) {
    require_positive(p_radps, field("p_radps"));
    require_positive(alpha_rad, field("alpha_rad"));
    require_in_range(theta0_rad, 0.0, alpha_rad, field("theta0_rad"), false, false);
    // arccosh(1 / (1 - x)) = ln((1 + sqrt(x (2 - x))) / (1 - x)), accurate for small x.
    const double x = theta0_rad / alpha_rad;
    const double acosh = std::log1p(std::sqrt(x * (2.0 - x))) - std::log1p(-x);
    return p_radps / (4.0 * acosh);
}

double rocking_displacement_m(double R_m, double alpha_rad, double theta0_rad) {
    return R_m * (std::sin(alpha_rad) - std::sin(alpha_rad - theta0_rad));
}

double damping_from_restitution(double r) {
    require_in_range(r, 0.0, 1.0, field("restitution"), false, true);
    return -std::log(r) / units::pi;
}

ElResult equivalent_linear_rocking(const Block& blk, Edge e, const DampedSpectra& horizontal,
                                   const VerticalDemand& vertical, const ElOptions& o) {
    check_options(o, vertical);
    ElResult r;
    r.edge = e;
    r.alpha_rad = blk.alpha_rad(e);
    r.fs_required = o.fs_required;
    r.restitution = o.restitution.value_or(blk.housner_restitution(e));
    r.pga_h_g = o.pga_h_g.value_or(horizontal.zpa_g());
    r.pga_v_g = o.pga_v_g ? *o.pga_v_g
                : vertical.spectra ? vertical.spectra->zpa_g()
                                   : vertical.ratio * r.pga_h_g;
    r.gate_g = (1.0 - 0.4 * r.pga_v_g) * blk.tan_alpha(e);
    r.gate_exceeded = r.pga_h_g > r.gate_g;
    // beta_e = -ln(r) / pi reaches 100% at r = exp(-pi) = 0.043: no spectrum goes there.
    const bool damping_beyond = r.restitution > 0.0 && r.restitution < 1.0 &&
                                damping_from_restitution(r.restitution) >= 1.0;
    if (!(r.restitution > 0.0 && r.restitution < 1.0) || damping_beyond) {
        r.beta_e_reason =
            damping_beyond
                ? fmt::format("restitution r = {:.4g} gives a damping -ln(r) / pi = {:.3g}, 100% "
                              "or more, beyond any demand spectrum",
                              r.restitution, damping_from_restitution(r.restitution))
                : fmt::format("restitution r = {:.4g} is not in (0, 1): {}", r.restitution,
                              r.restitution >= 1.0 ? "no impact damping"
                                                   : "the block does not rebound");
        const std::string why = "equivalent-linear estimate not applicable: " + r.beta_e_reason;
        r.spectral_margin_reason = why;
        // The gate needs no damping: below it the answer is still "no rocking".
        if (!r.gate_exceeded) {
            no_rocking(r);
            return r;
        }
        r.theta0_reason = why;
        r.fs_reason = why;
        return r;
    }
    r.beta_e = damping_from_restitution(r.restitution);
    const DampedDemand h = horizontal.at(*r.beta_e);
    std::optional<DampedDemand> v;
    if (vertical.spectra) v = vertical.spectra->at(*r.beta_e);
    r.damping_note = h.note;
    const Context c{blk, e, h, v ? &*v : nullptr, vertical.ratio, r.pga_h_g, r.pga_v_g,
                    o.grid_points, o.g_mps2};
    estimate_theta0(c, r);
    spectral_margin(c, r);
    return r;
}

ElBlockResult equivalent_linear_rocking(const Block& blk, const DampedSpectra& horizontal,
                                        const VerticalDemand& vertical, const ElOptions& o) {
    ElBlockResult out;
    out.right = equivalent_linear_rocking(blk, Edge::right, horizontal, vertical, o);
    if (blk.symmetric()) {
        out.left = out.right;
        out.left.edge = Edge::left;
    } else {
        out.left = equivalent_linear_rocking(blk, Edge::left, horizontal, vertical, o);
    }
    const double ml = out.left.spectral_margin.value_or(HUGE_VAL);
    const double mr = out.right.spectral_margin.value_or(HUGE_VAL);
    out.governing_edge = ml < mr ? Edge::left : mr < ml ? Edge::right : blk.critical_edge();
    return out;
}

}  // namespace freestand::rocking
