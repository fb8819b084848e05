#pragma once
/// Internal: one Dormand-Prince 5(4) step on a fixed-size state, with its error estimate and
/// Hairer's order-4 continuous extension (Hairer, Norsett & Wanner, Solving ODEs I, s. II.5 and
/// II.6, code DOPRI5). Written out for a small std::array state: the biaxial slide takes
/// thousands of such steps per record, and a generic stepper's algebra and copies cost more
/// than the seven evaluations of its right-hand side.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <initializer_list>

namespace freestand::dynamics::detail {

template <std::size_t N>
class Dopri5 {
public:
    using State = std::array<double, N>;

    /// Tries the step [t, t + h] from x0 with k1 = f(x0, t): fills x1 and k7 = f(x1, t + h)
    /// (first-same-as-last: the next step's k1) and returns the error of the embedded order-4
    /// solution as max_i |e_i| / (abs_tol + rel_tol max(|x0_i|, |x1_i|)); <= 1 accepts.
    /// Components outside [Lo, Hi) must be constants of the motion (f gives them derivative 0):
    /// they are carried, not stepped, which gives the same x1 and error (and the continuous
    /// extension, which reads their zero k_j).
    template <std::size_t Lo = 0, std::size_t Hi = N, class F>
    double step(const F& f, double t, const State& x0, const State& k1, double h, double rel_tol,
                double abs_tol) {
        static_assert(Lo < Hi && Hi <= N);
        x0_ = x0;
        k_[0] = k1;
        h_ = h;
        State y;
        if constexpr (Lo > 0 || Hi < N) y = x0;
        stage<Lo, Hi>(y, {a21});
        f(y, k_[1], t + c2 * h);
        stage<Lo, Hi>(y, {a31, a32});
        f(y, k_[2], t + c3 * h);
        stage<Lo, Hi>(y, {a41, a42, a43});
        f(y, k_[3], t + c4 * h);
        stage<Lo, Hi>(y, {a51, a52, a53, a54});
        f(y, k_[4], t + c5 * h);
        stage<Lo, Hi>(y, {a61, a62, a63, a64, a65});
        f(y, k_[5], t + h);
        stage<Lo, Hi>(y, {b1, 0.0, b3, b4, b5, b6});
        x1_ = y;
        f(x1_, k_[6], t + h);
        double err = 0.0;
        for (std::size_t i = Lo; i < Hi; ++i) {
            const double e = h * (e1 * k_[0][i] + e3 * k_[2][i] + e4 * k_[3][i] +
                                  e5 * k_[4][i] + e6 * k_[5][i] + e7 * k_[6][i]);
            const double sk = abs_tol + rel_tol * std::max(std::abs(x0[i]), std::abs(x1_[i]));
            err = std::max(err, std::abs(e) / sk);
        }
        return err;
    }

    const State& x0() const { return x0_; }
    const State& x1() const { return x1_; }
    const State& k7() const { return k_[6]; }

    /// The continuous extension of the last step at theta = (t - t0) / h in [0, 1].
    State dense(double theta) const {
        State y;
        for (std::size_t i = 0; i < N; ++i) y[i] = dense_component(theta, i);
        return y;
    }
    /// Its component i alone (a root search on one component).
    double dense_component(double theta, std::size_t i) const {
        const double th1 = 1.0 - theta;
        const double diff = x1_[i] - x0_[i];
        const double bspl = h_ * k_[0][i] - diff;
        const double r4 = diff - h_ * k_[6][i] - bspl;
        const double r5 = h_ * (d1 * k_[0][i] + d3 * k_[2][i] + d4 * k_[3][i] + d5 * k_[4][i] +
                                d6 * k_[5][i] + d7 * k_[6][i]);
        return x0_[i] + theta * (diff + th1 * (bspl + theta * (r4 + th1 * r5)));
    }

    /// The step factor the error asks for next (0.9 err^(-1/5), between 0.2 and 5).
    static double factor(double err) {
        if (!std::isfinite(err)) return 0.2;
        if (err <= 0.0) return 5.0;
        return std::clamp(0.9 * std::pow(err, -0.2), 0.2, 5.0);
    }

private:
    // y = x0 + h sum_j a_j k_j over the given coefficients, on the stepped components.
    template <std::size_t Lo, std::size_t Hi>
    void stage(State& y, std::initializer_list<double> a) const {
        for (std::size_t i = Lo; i < Hi; ++i) {
            double s = 0.0;
            std::size_t j = 0;
            for (double aj : a) s += aj * k_[j++][i];
            y[i] = x0_[i] + h_ * s;
        }
    }

    static constexpr double c2 = 1.0 / 5, c3 = 3.0 / 10, c4 = 4.0 / 5, c5 = 8.0 / 9;
    static constexpr double a21 = 1.0 / 5;
    static constexpr double a31 = 3.0 / 40, a32 = 9.0 / 40;
    static constexpr double a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
    static constexpr double a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561,
                            a54 = -212.0 / 729;
    static constexpr double a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247,
                            a64 = 49.0 / 176, a65 = -5103.0 / 18656;
    static constexpr double b1 = 35.0 / 384, b3 = 500.0 / 1113, b4 = 125.0 / 192,
                            b5 = -2187.0 / 6784, b6 = 11.0 / 84;
    // e = b - b_hat (the order-4 weights).
    static constexpr double e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920,
                            e5 = -17253.0 / 339200, e6 = 22.0 / 525, e7 = -1.0 / 40;
    static constexpr double d1 = -12715105075.0 / 11282082432.0,
                            d3 = 87487479700.0 / 32700410799.0,
                            d4 = -10690763975.0 / 1880347072.0,
                            d5 = 701980252875.0 / 199316789632.0,
                            d6 = -1453857185.0 / 822651844.0, d7 = 69997945.0 / 29380423.0;

    State x0_{}, x1_{};
    std::array<State, 7> k_{};
    double h_ = 0.0;
};

}  // namespace freestand::dynamics::detail
