#include "sliding/initiation.hpp"

#include <cmath>
#include <fmt/format.h>

#include "core/errors.hpp"

namespace freestand::sliding {

using block::Block;
using block::Edge;

std::string describe(Criterion criterion) {
    switch (criterion) {
        case Criterion::below_thresholds: return "A <= mu_s and A <= tan(alpha)";
        case Criterion::friction_below_slenderness: return "A > mu_s and mu_s <= tan(alpha)";
        case Criterion::friction_holds_at_uplift:
            return "A > tan(alpha), mu_s > tan(alpha) and mu_s >= mu_crit(A)";
        case Criterion::friction_fails_at_uplift:
            return "A > tan(alpha) and tan(alpha) < mu_s < mu_crit(A)";
    }
    return "unknown";
}

double load_ratio(double a_h_g, double a_v_g) {
    if (!std::isfinite(a_h_g))
        throw InputError(SourceLocation{"", 0, "a_h_g"},
                         fmt::format("horizontal acceleration {} g must be finite", a_h_g));
    if (!std::isfinite(a_v_g) || 1.0 + a_v_g <= 0.0)
        throw InputError(SourceLocation{"", 0, "a_v_g"},
                         fmt::format("vertical acceleration {} g leaves no effective gravity "
                                     "(expected a_v > -1 g); the block is in free flight and the "
                                     "static classification does not apply",
                                     a_v_g));
    return std::abs(a_h_g) / (1.0 + a_v_g);
}

// Derivation of mu_crit for a general block (docs/methods.md s.2 asks for it from I_O and R).
// Pivot O at edge e; CG relative to O: x = -b (towards the block), y = h, with b = R sin(alpha),
// h = R cos(alpha). The base accelerates away from the pivot side with magnitude a (for the right
// edge, x_g'' = -a) and vertically with y_g''; G = g + y_g'', A = a / G. No slip at O.
// Rock equation (docs/methods.md s.3) at theta = 0:  I_O theta'' = M (a h - G b).
// CG acceleration at theta = 0, theta' = 0 (centripetal terms vanish):
//   x_CG'' = x_g'' + h theta'',  y_CG'' = y_g'' + b theta''.
// Base reactions at O: F = M x_CG'' = M (-a + h theta''), N = M (g + y_CG'') = M (G + b theta'').
// With theta'' = M G (A h - b) / I_O:
//   |F| / (M G) = A - M h (A h - b) / I_O,   N / (M G) = 1 + M b (A h - b) / I_O,
//   mu_crit = [A (I_O - M h^2) + M h b] / [I_O - M b^2 + M A b h].
// I_O - M h^2 = I_c + M b^2 > 0 and I_O - M b^2 = I_c + M h^2 > 0, so both are positive.
// Check A = b/h: numerator (b/h) I_O, denominator I_O -> mu_crit = tan(alpha).
// Uniform block, I_O = (4/3) M (b^2 + h^2), gamma = b/h: dividing by M h^2 / 3 gives
//   [A (1 + 4 gamma^2) + 3 gamma] / [4 + gamma^2 + 3 A gamma]   (Shenton 1996).
double mu_crit(const Block& blk, Edge e, double A) {
    require_in_range(A, 0.0, HUGE_VAL, SourceLocation{"", 0, "A"}, true, false);
    const double m = blk.mass_kg;
    const double b = blk.b(e);
    const double h = blk.h_m;
    const double io = blk.inertia_edge_kgm2(e);
    return (A * (io - m * h * h) + m * h * b) / (io - m * b * b + m * A * b * h);
}

Initiation classify_edge(const Block& blk, Edge e, double mu_s, double a_h_g, double a_v_g) {
    require_in_range(mu_s, 0.0, HUGE_VAL, SourceLocation{"", 0, "mu_s"}, true, false);
    require_in_range(a_h_g, 0.0, HUGE_VAL, SourceLocation{"", 0, "a_h_g"}, true, false);
    Initiation out;
    out.edge = e;
    out.A = load_ratio(a_h_g, a_v_g);
    out.tan_alpha = blk.tan_alpha(e);
    const double A = out.A;
    const double ta = out.tan_alpha;
    if (A > ta) {
        out.mu_crit = mu_crit(blk, e, A);
    } else {
        out.mu_crit_reason = fmt::format("A = {} <= tan(alpha) = {}: no uplift demanded", A, ta);
    }
    // Section 2 partitions the (A, mu_s) plane; equality on either threshold is rest.
    if (A <= mu_s && A <= ta) {
        out.mode = Mode::rest;
        out.decided_by = Criterion::below_thresholds;
    } else if (mu_s <= ta) {
        out.mode = Mode::slide;
        out.decided_by = Criterion::friction_below_slenderness;
    } else if (mu_s >= *out.mu_crit) {
        out.mode = Mode::rock;
        out.decided_by = Criterion::friction_holds_at_uplift;
    } else {
        out.mode = Mode::slide_rock;
        out.decided_by = Criterion::friction_fails_at_uplift;
    }
    return out;
}

Initiation classify_signed(const Block& blk, double mu_s, double a_h_g, double a_v_g) {
    const Edge e = a_h_g < 0.0 ? Edge::right : a_h_g > 0.0 ? Edge::left : blk.critical_edge();
    return classify_edge(blk, e, mu_s, std::abs(a_h_g), a_v_g);
}

PeakInitiation classify_peak(const Block& blk, double mu_s, double peak_h_g, double peak_v_g) {
    require_in_range(peak_h_g, 0.0, HUGE_VAL, SourceLocation{"", 0, "peak_h_g"}, true, false);
    require_in_range(peak_v_g, 0.0, 1.0, SourceLocation{"", 0, "peak_v_g"}, true, false);
    PeakInitiation out;
    out.left = classify_edge(blk, Edge::left, mu_s, peak_h_g, -peak_v_g);
    out.right = classify_edge(blk, Edge::right, mu_s, peak_h_g, -peak_v_g);
    out.governing_edge = blk.critical_edge();
    return out;
}

}  // namespace freestand::sliding
