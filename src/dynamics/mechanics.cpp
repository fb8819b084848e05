#include "dynamics/mechanics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace freestand::dynamics::detail {

namespace {
double sgn(double x) { return x > 0.0 ? 1.0 : (x < 0.0 ? -1.0 : 0.0); }
}  // namespace

Geometry make_geometry(const BlockModel& model) {
    const block::Block& blk = model.block;
    Geometry g;
    g.M = blk.mass_kg;
    g.Ic = blk.inertia_cg_kgm2;
    g.h = blk.h_m;
    g.top = model.top_height_m;
    g.mu_s = model.mu_s;
    g.mu_k = model.mu_k;
    const block::Edge edges[2] = {block::Edge::left, block::Edge::right};
    for (int i = 0; i < 2; ++i) {
        const auto k = static_cast<std::size_t>(i);
        g.b[k] = blk.b(edges[i]);
        g.R[k] = blk.R_m(edges[i]);
        g.alpha[k] = blk.alpha_rad(edges[i]);
        g.sin_alpha[k] = std::sin(g.alpha[k]);
        g.cos_alpha[k] = std::cos(g.alpha[k]);
        g.tan_alpha[k] = blk.tan_alpha(edges[i]);
        g.IO[k] = blk.inertia_edge_kgm2(edges[i]);
        g.c_rest[k] = std::min(g.mu_s, g.tan_alpha[k]);
        g.k_rock[k] = g.M * g.R[k] / g.IO[k];
    }
    for (std::size_t i = 0; i < 2; ++i) {
        // Default: angular momentum about the striking edge (block::Block::housner_restitution),
        // exact for asymmetric blocks too.
        g.r_onto[i] = model.restitution ? *model.restitution : blk.housner_restitution(edges[i]);
        // A squat block (alpha > ~0.96 rad when uniform) cannot rebound: the impulse stops it.
        g.r_onto[i] = std::max(0.0, g.r_onto[i]);
    }
    return g;
}

Accel rock_accel(const Geometry& g, int s, double th, double om, Base base) {
    const auto i = static_cast<std::size_t>(Geometry::index(s));
    if (th == 0.0) return rock_accel_sc(g, s, g.sin_alpha[i], g.cos_alpha[i], om, base);
    const double a = g.alpha[i] - th;
    return rock_accel_sc(g, s, std::sin(a), std::cos(a), om, base);
}

Accel slide_rock_accel(const Geometry& g, int s, int sigma, double th, double om, Base base) {
    const double a = g.alpha[static_cast<std::size_t>(Geometry::index(s))] - th;
    return slide_rock_accel_sc(g, s, sigma, std::sin(a), std::cos(a), om, base);
}

Accel slide_rock_accel_sc(const Geometry& g, int s, int sigma, double sn, double c, double om,
                          Base base) {
    const auto i = static_cast<std::size_t>(Geometry::index(s));
    const double ds = static_cast<double>(s), dsig = static_cast<double>(sigma);
    const double R = g.R[i];
    const double w2 = om * om;
    // Rows of the 3x3 system in (u'', theta'', N) (sec. 3): horizontal and vertical balance of
    // the CG and the moment about it. The last two do not contain u'': the moment row gives
    // N = -s I_c theta'' / D with D = s R sn - sigma mu_k R c, and the vertical row then
    // theta'' = -D (G - R c w^2) / (R sn D + s I_c / M); the horizontal row gives u''.
    const double D = ds * R * sn - dsig * g.mu_k * R * c;
    Accel a;
    a.th_dd = -D * (base.G - R * c * w2) / (R * sn * D + ds * g.Ic / g.M);
    a.N = g.M * (R * sn * a.th_dd - R * c * w2 + base.G);
    a.F = -dsig * g.mu_k * a.N;
    a.u_dd = -(ds * R * sn * w2 + base.ax) + a.F / g.M - ds * R * c * a.th_dd;
    return a;
}

Start classify_sliding(const Geometry& g, double v) {
    const int sigma = v >= 0.0 ? 1 : -1;
    Start st;
    st.sigma = sigma;
    st.s = sigma;
    // Friction decelerating the slip lifts the leading edge once mu_k h > b (section 3).
    st.mode = g.mu_k > g.tan_alpha[static_cast<std::size_t>(Geometry::index(sigma))]
                  ? Mode::slide_rock
                  : Mode::slide;
    return st;
}

namespace {
// Slide-rock from theta = theta' = 0 needs theta'' > 0 under kinetic friction. When
// mu_k < tan(alpha) < mu_s < mu_crit(A), static friction could lift the edge but the sliding
// contact cannot (a case section 2 does not list): the block slides flat instead.
Start slide_rock_or_slide(const Geometry& g, int s, int sigma, Base base) {
    if (slide_rock_accel(g, s, sigma, 0.0, 0.0, base).th_dd > 0.0) {
        Start st;
        st.mode = Mode::slide_rock;
        st.s = s;
        st.sigma = sigma;
        return st;
    }
    return classify_sliding(g, static_cast<double>(sigma));
}
}  // namespace

Start classify_from_rest(const Geometry& g, Base base) {
    Start st;
    if (rest_holds(g, base)) return st;
    if (base.G <= 0.0) {
        st.mode = Mode::flight;
        return st;
    }
    const int s_tip = base.ax > 0.0 ? -1 : 1;
    const double A = std::abs(base.ax) / base.G;
    const double tan_a = g.tan_alpha[static_cast<std::size_t>(Geometry::index(s_tip))];
    if (A > g.mu_s && g.mu_s <= tan_a) return classify_sliding(g, static_cast<double>(s_tip));
    // A > tan(alpha) < mu_s: pure rock if the friction needed at uplift is available
    // (the general-block form of Shenton's mu_crit), else slide-rock.
    const Accel a = rock_accel(g, s_tip, 0.0, 0.0, base);
    st.s = s_tip;
    if (std::abs(a.F) <= g.mu_s * a.N) {
        st.mode = Mode::rock;
        return st;
    }
    return slide_rock_or_slide(g, s_tip, a.F > 0.0 ? -1 : 1, base);
}

Start classify_on_edge(const Geometry& g, int s, double th, double om, double v, Base base) {
    Start st;
    st.s = s;
    if (v != 0.0) {
        st.mode = Mode::slide_rock;
        st.sigma = v > 0.0 ? 1 : -1;
        return st;
    }
    const Accel a = rock_accel(g, s, th, om, base);
    if (a.N < 0.0) {
        st.mode = Mode::flight;
    } else if (std::abs(a.F) <= g.mu_s * a.N) {
        st.mode = Mode::rock;
    } else if (th == 0.0 && om == 0.0) {
        return slide_rock_or_slide(g, s, a.F > 0.0 ? -1 : 1, base);
    } else {
        st.mode = Mode::slide_rock;
        st.sigma = a.F > 0.0 ? -1 : 1;
    }
    return st;
}

double rebound_angle(const Geometry& g, int s, double om, double G) {
    const auto i = static_cast<std::size_t>(Geometry::index(s));
    if (G <= 0.0) return std::numeric_limits<double>::infinity();
    // 1/2 I_O om^2 = M G R (cos(alpha - theta_max) - cos(alpha)).
    const double cos_v = g.cos_alpha[i] + g.IO[i] * om * om / (2.0 * g.M * G * g.R[i]);
    if (cos_v >= 1.0) return std::numeric_limits<double>::infinity();
    return g.alpha[i] - std::acos(cos_v);
}

double top_corner_accel(const Geometry& g, double ax_base, double xdd_cg, double phi, double phid,
                        double phidd) {
    return top_corner_accel_cs(g, ax_base, xdd_cg, std::cos(phi), std::sin(phi), phid, phidd);
}

Flight to_flight(const Geometry& g, int s, double u, double v, double th, double om) {
    const auto i = static_cast<std::size_t>(Geometry::index(s));
    const double ds = static_cast<double>(s);
    const double sn = std::sin(g.alpha[i] - th), c = std::cos(g.alpha[i] - th);
    Flight f;
    f.X = u + ds * g.b[i] - ds * g.R[i] * sn;
    f.Y = g.R[i] * c;
    f.phi = -ds * th;
    f.Xd = v + ds * g.R[i] * c * om;
    f.Yd = g.R[i] * sn * om;
    f.phid = -ds * om;
    return f;
}

double lowest_corner(const Geometry& g, const Flight& f, int& s_out) {
    const double sp = std::sin(f.phi), cp = std::cos(f.phi);
    const double y_right = f.Y + g.b[1] * sp - g.h * cp;
    const double y_left = f.Y - g.b[0] * sp - g.h * cp;
    s_out = y_right <= y_left ? 1 : -1;
    return std::min(y_right, y_left);
}

Contact land(const Geometry& g, const Flight& f, double flat_window_s) {
    Contact c;
    lowest_corner(g, f, c.s);
    c.th = std::max(0.0, -static_cast<double>(c.s) * f.phi);
    const auto i = static_cast<std::size_t>(Geometry::index(c.s));
    const double ds = static_cast<double>(c.s);
    const double sn = std::sin(g.alpha[i] - c.th), cs = std::cos(g.alpha[i] - c.th);
    c.u = f.X - ds * g.b[i] + ds * g.R[i] * sn;
    // Gap of the far edge: it closes at about the vertical speed (Options::flat_landing_window_s).
    const double far_gap = (g.b[0] + g.b[1]) * std::sin(c.th);
    const bool together = f.Yd < 0.0 && far_gap <= -f.Yd * flat_window_s;
    if (c.th <= 1e-12 || together) {
        // Both edges strike together: the vertical velocity stops; friction removes at most
        // mu_k times the vertical impulse from the horizontal velocity (Coulomb impact).
        c.flat = true;
        c.th = 0.0;
        const double dv = std::min(std::abs(f.Xd), g.mu_k * std::max(0.0, -f.Yd));
        c.v = f.Xd - sgn(f.Xd) * dv;
        return c;
    }
    // Angular momentum about the striking corner is conserved through the sticking impact.
    const double rx = -ds * g.R[i] * sn, ry = g.R[i] * cs;  // CG relative to the corner
    const double H = g.Ic * f.phid + g.M * (rx * f.Yd - ry * f.Xd);
    c.om = -ds * H / g.IO[i];
    c.v = 0.0;
    return c;
}

}  // namespace freestand::dynamics::detail
