#include "motion/baseline.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <mutex>

#include "core/measures.hpp"
#include "core/units.hpp"

namespace freestand::motion {
namespace {

// Long-period displacement shapes sin^2(pi t / T) sin(k pi t / T), k = 1..kTrendShapes: zero
// with their slope at both ends, content below ~(k + 2) / (2T) Hz (0.125 Hz at k = 3 in 20 s),
// i.e. mostly under the 0.1 Hz bottom of the acceptance band.
constexpr int kTrendShapes = 3;
// Displacement is fitted on a grid this fine (it is smooth at these periods).
constexpr double kFitStep_s = 0.05;
// Reweighting passes toward the peak: w_i <- w_i (1 + kGain (|d_i| / max |d|)^kPower).
constexpr int kReweights = 3;
constexpr double kGain = 4.0;
constexpr double kPower = 4.0;

double dot(const std::vector<double>& a, const std::vector<double>& b) {
    double s = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) s += a[i] * b[i];
    return s;
}

std::vector<double> on_grid(const std::vector<double>& full, std::size_t stride) {
    std::vector<double> out;
    out.reserve(full.size() / stride + 1);
    for (std::size_t i = 0; i < full.size(); i += stride) out.push_back(full[i]);
    return out;
}

std::vector<double> sampled(const Wavelet& w, std::size_t samples, double dt_s) {
    std::vector<double> a(samples, 0.0);
    add_wavelet(w, 1.0, dt_s, a);
    return a;
}

// Acceleration of sin^2(pi t / T) sin(k pi t / T) by central second differences, so that its
// trapezoidal double integral is the shape to O(dt^2).
std::vector<double> trend_shape(int k, std::size_t samples, double dt_s) {
    std::vector<double> phi(samples);
    const double last = static_cast<double>(samples - 1);
    for (std::size_t i = 0; i < samples; ++i) {
        const double x = units::pi * static_cast<double>(i) / last;
        phi[i] = std::sin(x) * std::sin(x) * std::sin(static_cast<double>(k) * x);
    }
    std::vector<double> a(samples, 0.0);
    for (std::size_t i = 1; i + 1 < samples; ++i)
        a[i] = (phi[i + 1] - 2.0 * phi[i] + phi[i - 1]) / (dt_s * dt_s);
    return a;
}

// Quintic smoothstep w(x) = 10 x^3 - 15 x^4 + 6 x^5 and its first two derivatives in x: w, w'
// and w'' vanish at x = 0, so the tapered displacement w d keeps a continuous second derivative
// (a cosine taper's jump in w'' integrates into a drift of ~2% of d).
struct Smoothstep {
    double w, w1, w2;
};
Smoothstep smoothstep(double x) {
    return {x * x * x * (10.0 + x * (-15.0 + 6.0 * x)), 30.0 * x * x * (x - 1.0) * (x - 1.0),
            60.0 * x * (2.0 * x - 1.0) * (x - 1.0)};
}

}  // namespace

BaselineCorrector::BaselineCorrector(std::size_t samples, double dt_s)
    : samples_(samples),
      dt_s_(dt_s),
      stride_(std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(kFitStep_s / dt_s)))),
      ends_(end_weights(samples, dt_s)) {
    static_assert(kShapes == 2 + kTrendShapes, "the two pulses and the trend shapes");
    for (const Wavelet& w : pulses(static_cast<double>(samples - 1) * dt_s))
        shape_a_.push_back(sampled(w, samples, dt_s));
    for (int k = 1; k <= kTrendShapes; ++k) shape_a_.push_back(trend_shape(k, samples, dt_s));
    for (const std::vector<double>& a : shape_a_) {
        shape_d_.push_back(on_grid(core::displacement_m(a, dt_s), stride_));
        shape_end_v_.push_back(dot(ends_.velocity, a));
        shape_end_d_.push_back(dot(ends_.displacement, a));
    }
}

std::shared_ptr<const BaselineCorrector> BaselineCorrector::shared(std::size_t samples,
                                                                   double dt_s) {
    constexpr std::size_t kKept = 4;
    static std::mutex mutex;
    static std::vector<std::shared_ptr<const BaselineCorrector>> kept;  // most recent last
    const auto find = [&]() -> std::shared_ptr<const BaselineCorrector> {
        for (const auto& c : kept)
            if (c->samples_ == samples && c->dt_s_ == dt_s) return c;
        return nullptr;
    };
    {
        const std::lock_guard<std::mutex> lock(mutex);
        if (auto c = find()) return c;
    }
    auto made = std::make_shared<const BaselineCorrector>(samples, dt_s);
    const std::lock_guard<std::mutex> lock(mutex);
    if (auto c = find()) return c;  // another thread built it meanwhile
    if (kept.size() == kKept) kept.erase(kept.begin());
    kept.push_back(made);
    return made;
}

std::array<Wavelet, 2> BaselineCorrector::pulses(double duration_s) {
    const double gamma_s = std::min(duration_s / 12.0, 2.0);
    return {Wavelet::pulse(duration_s / 3.0, gamma_s), Wavelet::pulse(2.0 * duration_s / 3.0, gamma_s)};
}

void BaselineCorrector::minimise_displacement(std::vector<double>& accel_mps2) const {
    const std::vector<double> d = displacement_on_grid(accel_mps2);
    const auto nb = static_cast<Eigen::Index>(shape_a_.size());
    const auto nbu = shape_a_.size();
    // KKT system of min sum_i w_i (d_i + sum_k c_k D_ki)^2 s.t. the two end conditions:
    // [H E^T; E 0] [c; lambda] = [-g; -e].
    const double end_v = dot(ends_.velocity, accel_mps2);
    const double end_d = dot(ends_.displacement, accel_mps2);
    std::vector<double> weight(d.size(), 1.0);
    Eigen::VectorXd c;
    for (int pass = 0; pass <= kReweights; ++pass) {
        Eigen::MatrixXd kkt = Eigen::MatrixXd::Zero(nb + 2, nb + 2);
        Eigen::VectorXd rhs = Eigen::VectorXd::Zero(nb + 2);
        const WeightedSums sums = weighted_sums(weight, d);
        std::size_t pair = 0;
        for (std::size_t i = 0; i < nbu; ++i) {
            const auto ii = static_cast<Eigen::Index>(i);
            for (std::size_t j = i; j < nbu; ++j) {
                const double h = sums.h[pair++];
                kkt(ii, static_cast<Eigen::Index>(j)) = kkt(static_cast<Eigen::Index>(j), ii) = h;
            }
            rhs(ii) = -sums.g[i];
            kkt(nb, ii) = kkt(ii, nb) = shape_end_v_[i];
            kkt(nb + 1, ii) = kkt(ii, nb + 1) = shape_end_d_[i];
        }
        rhs(nb) = -end_v;
        rhs(nb + 1) = -end_d;
        c = kkt.fullPivLu().solve(rhs);
        if (pass == kReweights) break;  // the weights of a next pass would not be used
        double peak = 0.0;
        std::vector<double> corrected = d;
        for (std::size_t q = 0; q < d.size(); ++q) {
            for (std::size_t k = 0; k < nbu; ++k)
                corrected[q] += c(static_cast<Eigen::Index>(k)) * shape_d_[k][q];
            peak = std::max(peak, std::abs(corrected[q]));
        }
        if (peak <= 0.0) break;
        for (std::size_t q = 0; q < d.size(); ++q)
            weight[q] *= 1.0 + kGain * std::pow(std::abs(corrected[q]) / peak, kPower);
    }
    // Shape by shape for each sample (the additions in the order of the shapes, as ever).
    std::array<double, kShapes> ck{};
    for (std::size_t k = 0; k < nbu; ++k) ck[k] = c(static_cast<Eigen::Index>(k));
    for (std::size_t i = 0; i < samples_; ++i) {
        double a = accel_mps2[i];
        for (std::size_t k = 0; k < kShapes; ++k) a += ck[k] * shape_a_[k][i];
        accel_mps2[i] = a;
    }
}

BaselineCorrector::WeightedSums BaselineCorrector::weighted_sums(
    const std::vector<double>& weight, const std::vector<double>& d) const {
    // H_ij = sum_q w_q D_iq D_jq (j >= i) and g_i = sum_q w_q D_iq d_q, each summed in order of q
    // as (w_q D_iq) D_jq: twenty chains of dependent additions, taken side by side in one sweep
    // rather than one after another (the same operations, the same bits).
    WeightedSums s;
    for (std::size_t q = 0; q < d.size(); ++q) {
        std::array<double, kShapes> wd;
        for (std::size_t i = 0; i < kShapes; ++i) wd[i] = weight[q] * shape_d_[i][q];
        std::size_t pair = 0;
        for (std::size_t i = 0; i < kShapes; ++i) {
            for (std::size_t j = i; j < kShapes; ++j) s.h[pair++] += wd[i] * shape_d_[j][q];
            s.g[i] += wd[i] * d[q];
        }
    }
    return s;
}

std::vector<double> BaselineCorrector::displacement_on_grid(
    const std::vector<double>& accel_mps2) const {
    // core::displacement_m's two cumulative trapezoids, one sample at a time, keeping every
    // stride-th displacement (the same operations: the same bits).
    std::vector<double> out;
    out.reserve(samples_ / stride_ + 1);
    double v = 0.0, d = 0.0;
    out.push_back(d);
    for (std::size_t i = 1; i < samples_; ++i) {
        const double v_next = v + 0.5 * dt_s_ * (accel_mps2[i - 1] + accel_mps2[i]);
        d = d + 0.5 * dt_s_ * (v + v_next);
        v = v_next;
        if (i % stride_ == 0) out.push_back(d);
    }
    return out;
}

void BaselineCorrector::taper_ends(std::vector<double>& accel_mps2) const {
    // d <- w d gives a <- w a + 2 w' v + w'' d (w' and w'' in time).
    const std::vector<double> v = core::velocity_mps(accel_mps2, dt_s_);
    const std::vector<double> d = core::displacement_m(accel_mps2, dt_s_);
    const double duration_s = static_cast<double>(samples_ - 1) * dt_s_;
    const double tau = std::min(taper_s, duration_s / 4.0);
    for (std::size_t i = 0; i < samples_; ++i) {
        const double t = static_cast<double>(i) * dt_s_;
        const bool start = t < tau;
        if (!start && t <= duration_s - tau) continue;
        const Smoothstep s = smoothstep((start ? t : duration_s - t) / tau);
        const double w1 = (start ? s.w1 : -s.w1) / tau;
        const double w2 = s.w2 / (tau * tau);
        accel_mps2[i] = s.w * accel_mps2[i] + 2.0 * w1 * v[i] + w2 * d[i];
    }
}

void BaselineCorrector::zero_ends_exactly(std::vector<double>& accel_mps2) const {
    const double v = dot(ends_.velocity, accel_mps2);
    const double d = dot(ends_.displacement, accel_mps2);
    const double det = shape_end_v_[0] * shape_end_d_[1] - shape_end_v_[1] * shape_end_d_[0];
    const double c0 = (-v * shape_end_d_[1] + d * shape_end_v_[1]) / det;
    const double c1 = (-d * shape_end_v_[0] + v * shape_end_d_[0]) / det;
    for (std::size_t i = 0; i < samples_; ++i)
        accel_mps2[i] += c0 * shape_a_[0][i] + c1 * shape_a_[1][i];
}

void BaselineCorrector::correct(std::vector<double>& accel_mps2) const {
    minimise_displacement(accel_mps2);
    taper_ends(accel_mps2);
    zero_ends_exactly(accel_mps2);
}

}  // namespace freestand::motion
