// Time-domain spectral matching with the improved tapered cosine wavelet (Al Atik & Abrahamson
// 2010; Hancock et al. 2006, J. Earthq. Eng. 10:S1 67-89, RspMatch): per pass, find each
// oscillator's peak time and sign, solve C b = dR for wavelet amplitudes (C_ij = response of
// oscillator i at its peak time to wavelet j, in closed form), add sum b_j w_j. The same solve
// holds the record's peak acceleration near the target's zero-period acceleration (rows on the
// samples of the largest peaks), and after every pass the displacement-aware baseline correction
// (baseline.hpp) brings the record to rest with the smallest peak displacement it can, so the
// match converges on a record that is realistic as well as compatible (docs/methods.md s.8).
#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <utility>

#include "core/errors.hpp"
#include "core/units.hpp"
#include "motion/baseline.hpp"
#include "motion/criteria.hpp"
#include "motion/internal.hpp"
#include "motion/motion.hpp"
#include "motion/wavelet.hpp"
#include "spectra/response.hpp"

namespace freestand::motion {
namespace {

constexpr double kDamping = 0.05;
// Tikhonov weight relative to the mean squared (column-normalised) entry: only a guard against
// near-identical rows (rigid-range oscillators peaking at the same instant).
constexpr double kRegularisation = 1e-2;
// In-loop upper ratio outside the cap band.
constexpr double kUncappedUpper = 1.4;
// Band raise after a full check fails although every matching frequency is inside the band.
constexpr double kRaise = 0.02;
constexpr int kMaxRaises = 2;
// Misfit below which the full acceptance check is tried on a copy, at most every kCheckEvery
// passes.
constexpr double kNearBand = 0.04;
constexpr int kCheckEvery = 3;
// Wavelets are kept at >= 10 samples per cycle: coarser ones are poorly represented by their
// samples (and the closed-form Jacobian no longer describes them); near-rigid oscillators above
// that frequency respond quasi-statically to the lower-frequency wavelet placed at their peak.
constexpr double kMaxWaveletCyclesPerSample = 0.1;
// Peak-acceleration rows: at most this many peaks held per pass; the in-loop band is the
// acceptance range [lo, hi] narrowed to [lo + 0.1 (hi - lo), hi - 0.2 (hi - lo)], aiming at its
// middle, so that the band's edges are not met by rounding.
constexpr std::size_t kPeakRows = 5;
constexpr double kPgaBandLow = 0.1;
constexpr double kPgaBandHigh = 0.2;
// Baseline rows: a final displacement of this much per g of ZPA weighs like the whole target at
// one frequency (a tenth of the RG 1.60 realism limit on D/A).
constexpr double kBaselineDisplacement_m_per_g = 0.13;
// Weight of a held spectral row whose oscillator peaks within kSameInstant_s of a held
// acceleration peak.
constexpr double kYield = 0.1;
constexpr double kSameInstant_s = 0.02;

double dot_support(const SampledWavelet& w, const std::vector<double>& weights) {
    double s = 0.0;
    for (std::size_t k = 0; k < w.values.size(); ++k) s += weights[w.first + k] * w.values[k];
    return s;
}

double dot(const std::vector<double>& a, const std::vector<double>& b) {
    double s = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) s += a[i] * b[i];
    return s;
}

double value_at(const SampledWavelet& w, std::size_t i) {
    return i >= w.first && i < w.first + w.values.size() ? w.values[i - w.first] : 0.0;
}

// Piecewise-linear interpolation of the samples passes a sinusoid of frequency f with gain
// sinc^2(f dt); the closed-form response is of the continuous wavelet.
double interpolation_gain(double f_hz, double dt_s) {
    const double x = units::pi * f_hz * dt_s;
    // Below this sin(x) / x = 1 - x^2 / 6 is 1 in double precision (and 0 / 0 is avoided).
    constexpr double sinc_is_one_below = 1e-8;
    return x < sinc_is_one_below ? 1.0 : std::pow(std::sin(x) / x, 2);
}

// Samples of the `count` largest local maxima of |a|, largest first (ties by sample: the order
// is total, so these are the first `count` of the whole sorted list).
std::vector<std::size_t> peaks_by_size(const std::vector<double>& a, std::size_t count) {
    std::vector<std::pair<double, std::size_t>> found;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const double v = std::abs(a[i]);
        const bool left = i == 0 || v >= std::abs(a[i - 1]);
        const bool right = i + 1 == a.size() || v > std::abs(a[i + 1]);
        if (left && right && v > 0.0) found.push_back({v, i});
    }
    const auto kept = found.begin() + static_cast<std::ptrdiff_t>(std::min(count, found.size()));
    std::partial_sort(found.begin(), kept, found.end(), [](const auto& x, const auto& y) {
        return x.first != y.first ? x.first > y.first : x.second < y.second;
    });
    std::vector<std::size_t> out;
    for (auto p = found.begin(); p != kept; ++p) out.push_back(p->second);
    return out;
}

// A remembered closed-form response of one oscillator to one placed wavelet, at the last two
// peak times of the oscillator (competing peaks make a peak time move back and forth), and the
// wavelet's start state (which does not depend on the peak time).
struct Response {
    std::array<bool, 2> known{};  // [0]: the latest
    std::array<double, 2> t_s{}, y{};
    bool start_known = false;
    WaveletStart start;
};

// A wavelet of the linearised system placed for its oscillator's peak at t_s: the wavelet, its
// samples, its end-velocity and end-displacement rows, and its responses at each oscillator's
// peak time.
struct Placement {
    bool placed = false;
    double t_s = 0.0;
    Wavelet wave;
    SampledWavelet sampled;
    double end_v = 0.0, end_d = 0.0;
    std::vector<Response> response;  // per oscillator
};

// A wavelet column: its current placement and the one before, kept while the oscillator's peak
// may move back.
struct Column {
    Placement now, before;
};

struct Matcher {
    const Target& target;
    MatchOptions opt;
    core::Record& rec;
    std::vector<double> f;       // matching frequencies
    std::vector<double> f_wave;  // wavelet frequencies, sampled at >= 10 points per cycle
    std::vector<double> q;       // target PSA, m/s^2
    std::vector<double> upper;   // in-loop upper ratio: opt.upper inside the 1.3-cap band
    double zpa_mps2 = 0.0;
    double pga_low = 0.0, pga_high = 0.0, pga_aim = 0.0;  // in-loop PGA / ZPA band
    std::vector<double> gain;  // interpolation_gain of each wavelet frequency
    EndWeights ends;
    std::shared_ptr<const BaselineCorrector> baseline;
    spectra::OscillatorSet oscillators;  // at f, kDamping, rec.dt_s
    std::array<Wavelet, 2> pulses;
    std::array<SampledWavelet, 2> pulse_samples;
    std::array<double, 2> pulse_v{}, pulse_d{};
    std::vector<Column> columns;                           // one per matching frequency
    std::vector<OscillatorAt> observed;                    // each oscillator at its peak time
    std::array<std::vector<Response>, 2> pulse_responses;  // [pulse][oscillator]
    // A pass's new wavelet placements to sample.
    std::vector<SampleRequest> sample_queue;
    // A pass's closed forms to evaluate, and the (row, column) of each response.
    std::vector<StartRequest> start_queue;
    std::vector<ResponseRequest> response_queue;
    std::vector<std::pair<std::size_t, std::size_t>> queued_at;

    Matcher(const Target& t, const MatchOptions& o, core::Record& r)
        : target(t),
          opt(o),
          rec(r),
          f(spectra::log_frequencies(criteria::band_low_hz, criteria::band_high_for(r.dt_s),
                                     o.match_per_decade)),
          ends(end_weights(r.size(), r.dt_s)),
          baseline(BaselineCorrector::shared(r.size(), r.dt_s)),
          oscillators(kDamping, f, r.dt_s) {
        for (double fi : f) {
            const double cycles = fi > criteria::cap_high_hz ? opt.rigid_wavelet_cycles_per_sample
                                                             : kMaxWaveletCyclesPerSample;
            f_wave.push_back(std::min(fi, cycles / rec.dt_s));
            gain.push_back(interpolation_gain(f_wave.back(), rec.dt_s));
            q.push_back(target.psa_5pct.psa_at(fi) * target.g_mps2);
            // No cap outside 0.2-25 Hz: holding a tight band there only makes competing peaks of
            // the long-period oscillators alternate.
            const bool capped = fi >= criteria::cap_low_hz && fi <= criteria::cap_high_hz;
            upper.push_back(capped ? opt.upper : kUncappedUpper);
        }
        columns.resize(f.size());
        observed.resize(f.size());
        for (auto& row : pulse_responses) row.resize(f.size());
        pulses = BaselineCorrector::pulses(rec.duration_s());
        for (std::size_t k = 0; k < 2; ++k) {
            pulse_samples[k] = sample_wavelet(pulses[k], rec.dt_s, rec.size());
            pulse_v[k] = dot_support(pulse_samples[k], ends.velocity);
            pulse_d[k] = dot_support(pulse_samples[k], ends.displacement);
        }
        zpa_mps2 = zero_period_g(target.psa_5pct) * target.g_mps2;
        const Range& band = target.realism.pga_over_zpa;
        const double width = band.max - band.min;
        pga_low = band.min + kPgaBandLow * width;
        pga_high = band.max - kPgaBandHigh * width;
        pga_aim = 0.5 * (band.min + band.max);
    }

    struct Peaks {
        std::vector<double> r, sign, t;
        std::vector<std::size_t> accel_rows;  // samples whose |a| is pulled to pga_aim ZPA
        double worst = -1.0;  // largest distance of a ratio outside its band, < 0 inside
    };

    Peaks peaks() const {
        const auto p = oscillators.peak_responses(rec);
        Peaks out;
        for (std::size_t i = 0; i < f.size(); ++i) {
            const double w = units::hz_to_radps(f[i]);
            out.r.push_back(w * w * std::abs(p[i].sd_m));
            out.sign.push_back(p[i].sd_m > 0.0 ? -1.0 : 1.0);  // y = -omega^2 u
            out.t.push_back(p[i].time_s);
            const double ratio = out.r.back() / q[i];
            out.worst = std::max(out.worst, std::max(opt.lower - ratio, ratio - upper[i]));
        }
        const std::vector<std::size_t> by_size = peaks_by_size(rec.accel_mps2, kPeakRows);
        if (by_size.empty()) return out;
        const double pga_ratio = std::abs(rec.accel_mps2[by_size.front()]) / zpa_mps2;
        out.worst = std::max(out.worst, std::max(pga_low - pga_ratio, pga_ratio - pga_high));
        if (pga_ratio < pga_low) out.accel_rows.push_back(by_size.front());
        for (std::size_t k = 0; k < by_size.size() && k < kPeakRows; ++k)
            if (std::abs(rec.accel_mps2[by_size[k]]) > pga_high * zpa_mps2)
                out.accel_rows.push_back(by_size[k]);
        return out;
    }

    // True if t_s lies within kSameInstant_s of a sample held by a peak row.
    bool peaks_on(const Peaks& pk, double t_s) const {
        for (std::size_t sample : pk.accel_rows)
            if (std::abs(static_cast<double>(sample) * rec.dt_s - t_s) <= kSameInstant_s)
                return true;
        return false;
    }

    // The wavelet of column j placed for the peak at t_s, or the column's previous placement if
    // that was at t_s; a new one is queued for its samples and end rows (sample_queued).
    void place(std::size_t j, double t_s) {
        Column& col = columns[j];
        if (col.now.placed && col.now.t_s == t_s) return;
        std::swap(col.now, col.before);
        Placement& p = col.now;
        if (p.placed && p.t_s == t_s) return;
        p.placed = true;
        p.t_s = t_s;
        p.wave = Wavelet::for_oscillator(f_wave[j], f[j], kDamping, t_s);
        sample_queue.push_back({&p.wave, &p.sampled, &p.end_v, &p.end_d});
        p.response.assign(f.size(), Response{});
    }

    // Every column's wavelet placed for its oscillator's peak, the new ones sampled together.
    void place_all(const Peaks& pk) {
        sample_queue.clear();
        for (std::size_t j = 0; j < f.size(); ++j) place(j, pk.t[j]);
        sample_wavelets(sample_queue.data(), sample_queue.size(), rec.dt_s, rec.size(),
                        ends.velocity, ends.displacement);
    }

    // Pseudo-acceleration of oscillator i at its peak time due to wavelet w, remembered in
    // `memo`: the closed form costs two to four Faddeeva evaluations, and most peak times stay
    // put from one pass to the next. Null when the memo does not hold the oscillator's current
    // peak time.
    const double* remembered(const Response& memo, std::size_t i) const {
        for (std::size_t k = 0; k < 2; ++k)
            if (memo.known[k] && memo.t_s[k] == observed[i].t_s) return &memo.y[k];
        return nullptr;
    }

    // The memo takes oscillator i's current peak time, keeping the previous one; its response
    // (and the wavelet's start state, the first time it is needed) is queued for evaluation.
    void queue(Response& memo, const Wavelet& w, std::size_t i) {
        if (!memo.start_known && w.start_s() < 0.0) {
            start_queue.push_back({&w, f[i], kDamping, &memo.start});
            memo.start_known = true;
        }
        memo.known[1] = memo.known[0];
        memo.t_s[1] = memo.t_s[0];
        memo.y[1] = memo.y[0];
        memo.known[0] = true;
        memo.t_s[0] = observed[i].t_s;
        response_queue.push_back({&w, &observed[i], &memo.start, &memo.y[0]});
    }

    // The response rows of c: c(i, j) = gain_j y_ij / q_i for the wavelet columns and y_ij / q_i
    // for the two pulse columns, y_ij the response of oscillator i at its peak time to column j,
    // remembered or evaluated with the other new ones in one batch (wavelet_responses).
    void fill_responses(Eigen::MatrixXd& c) {
        const std::size_t m = f.size();
        const auto value = [&](std::size_t i, std::size_t j, double y) {
            return j < m ? gain[j] * y / q[i] : y / q[i];
        };
        start_queue.clear();
        response_queue.clear();
        queued_at.clear();
        for (std::size_t j = 0; j < m + 2; ++j) {
            const Wavelet& w = j < m ? columns[j].now.wave : pulses[j - m];
            std::vector<Response>& memos = j < m ? columns[j].now.response : pulse_responses[j - m];
            for (std::size_t i = 0; i < m; ++i) {
                if (const double* y = remembered(memos[i], i)) {
                    c(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = value(i, j, *y);
                    continue;
                }
                queue(memos[i], w, i);
                queued_at.push_back({i, j});
            }
        }
        wavelet_starts(start_queue.data(), start_queue.size());
        wavelet_responses(response_queue.data(), response_queue.size());
        for (std::size_t k = 0; k < queued_at.size(); ++k) {
            const auto [i, j] = queued_at[k];
            c(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) =
                value(i, j, *response_queue[k].out);
        }
    }

    // One linearised correction: rows in units of the target (spectral rows: change of the
    // ratio; peak rows: change of |a| / ZPA; two rows keeping the final velocity and displacement
    // at zero with two pulse columns, so the wavelets add no drift for the baseline step to
    // remove), then add the wavelets.
    void pass(const Peaks& pk, double relaxation) {
        const std::size_t m = f.size();
        const std::size_t cols = m + 2;
        const std::size_t rows = m + 2 + pk.accel_rows.size();
        place_all(pk);
        for (std::size_t j = 0; j < m; ++j)
            if (observed[j].t_s != pk.t[j] || observed[j].f_hz == 0.0)
                observed[j] = oscillator_at(f[j], kDamping, pk.t[j]);
        Eigen::MatrixXd c(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(cols));
        Eigen::VectorXd rhs(static_cast<Eigen::Index>(rows));
        const auto mv = static_cast<Eigen::Index>(m);
        fill_responses(c);
        for (std::size_t i = 0; i < m; ++i) {
            const auto ii = static_cast<Eigen::Index>(i);
            const double ratio = pk.r[i] / q[i];
            const bool inside = ratio >= opt.lower && ratio <= upper[i];
            const double want = inside ? pk.r[i] : opt.aim * q[i];
            rhs(ii) = (want - pk.r[i]) * pk.sign[i] / q[i];
            // A rigid-range oscillator peaking on a held acceleration peak follows that peak: a
            // row holding its ratio where it is would fight the peak row.
            if (inside && peaks_on(pk, pk.t[i])) {
                c.row(ii) *= kYield;
                rhs(ii) *= kYield;
            }
        }
        // Baseline rows held firmly (kBaselineDisplacement_m_per_g, and that over the duration
        // in velocity): drift the wavelets added would otherwise be removed afterwards by the
        // baseline correction, and with it the long-period part of the match.
        const double d_unit = kBaselineDisplacement_m_per_g * zpa_mps2 / target.g_mps2;
        const double v_unit = d_unit / rec.duration_s();
        for (std::size_t j = 0; j < m; ++j) {
            c(mv, static_cast<Eigen::Index>(j)) = columns[j].now.end_v / v_unit;
            c(mv + 1, static_cast<Eigen::Index>(j)) = columns[j].now.end_d / d_unit;
        }
        for (std::size_t k = 0; k < 2; ++k) {
            c(mv, mv + static_cast<Eigen::Index>(k)) = pulse_v[k] / v_unit;
            c(mv + 1, mv + static_cast<Eigen::Index>(k)) = pulse_d[k] / d_unit;
        }
        rhs(mv) = -dot(ends.velocity, rec.accel_mps2) / v_unit;
        rhs(mv + 1) = -dot(ends.displacement, rec.accel_mps2) / d_unit;
        for (std::size_t k = 0; k < pk.accel_rows.size(); ++k) {
            const std::size_t sample = pk.accel_rows[k];
            const auto row = static_cast<Eigen::Index>(m + 2 + k);
            for (std::size_t j = 0; j < m; ++j)
                c(row, static_cast<Eigen::Index>(j)) =
                    value_at(columns[j].now.sampled, sample) / zpa_mps2;
            for (std::size_t k2 = 0; k2 < 2; ++k2)
                c(row, mv + static_cast<Eigen::Index>(k2)) =
                    value_at(pulse_samples[k2], sample) / zpa_mps2;
            const double a = rec.accel_mps2[sample];
            rhs(row) = (std::copysign(pga_aim * zpa_mps2, a) - a) / zpa_mps2;
        }
        const Eigen::VectorXd b = solve_regularised(c, rhs);
        for (std::size_t j = 0; j < m; ++j)
            add_wavelet(columns[j].now.sampled, relaxation * b(static_cast<Eigen::Index>(j)),
                        rec.accel_mps2);
        for (std::size_t k = 0; k < 2; ++k)
            add_wavelet(pulse_samples[k], relaxation * b(mv + static_cast<Eigen::Index>(k)),
                        rec.accel_mps2);
        baseline->minimise_displacement(rec.accel_mps2);
    }

    // Columns scaled to unit norm, then min |C x - r|^2 + lambda^2 |x|^2.
    static Eigen::VectorXd solve_regularised(Eigen::MatrixXd c, const Eigen::VectorXd& rhs) {
        Eigen::VectorXd col(c.cols());
        for (Eigen::Index j = 0; j < c.cols(); ++j) {
            col(j) = c.col(j).norm();
            if (col(j) > 0.0)
                c.col(j) /= col(j);
            else
                col(j) = 1.0;
        }
        Eigen::MatrixXd normal = c.transpose() * c;
        const double lambda2 =
            kRegularisation * normal.trace() / static_cast<double>(normal.rows());
        normal.diagonal().array() += lambda2;
        Eigen::VectorXd x = normal.ldlt().solve(c.transpose() * rhs);
        return x.cwiseQuotient(col);
    }
};

}  // namespace

MatchResult match_in_place(core::Record record, const Target& target, const MatchOptions& options) {
    validate_target(target.psa_5pct, kDamping);
    MatchResult res;
    res.record = std::move(record);
    Matcher m(target, options, res.record);
    // Start at rest: a raw synthetic record drifts by metres, and removing that after the first
    // pass would undo the long-period part of the match.
    m.baseline->minimise_displacement(res.record.accel_mps2);
    int raises = 0;
    // The iterate closest to the band, kept in case the limit is reached.
    std::vector<double> best = res.record.accel_mps2;
    double best_worst = 1e300;
    int last_check = -kCheckEvery;
    for (int it = 1; it <= options.max_iterations; ++it) {
        const Matcher::Peaks pk = m.peaks();
        if (pk.worst < best_worst) {
            best_worst = pk.worst;
            best = res.record.accel_mps2;
        }
        if (pk.worst <= 0.0) {
            m.baseline->correct(res.record.accel_mps2);
            res.acceptance = check_acceptance(res.record, target);
            res.iterations = it - 1;
            res.converged = true;
            if (res.acceptance.passed) return res;
            // Dips between the matching frequencies: raise the band a little, a few times; a PSD
            // gap, a cap breach or a realism range is not cured that way, so the caller tries
            // another setting.
            if (++raises > kMaxRaises) return res;
            m.opt.lower += kRaise;
            m.opt.aim += kRaise;
            best_worst = 1e300;
        }
        // Nearly in the band (competing peaks can keep one point just outside for many passes):
        // the full check on a baseline-corrected copy may already pass.
        if (pk.worst <= kNearBand && it - last_check >= kCheckEvery) {
            last_check = it;
            core::Record candidate = res.record;
            m.baseline->correct(candidate.accel_mps2);
            Acceptance a = check_acceptance_or_reject(candidate, target);
            if (a.passed) {
                res.record = std::move(candidate);
                res.acceptance = std::move(a);
                res.iterations = it - 1;
                return res;
            }
        }
        m.pass(pk, options.relaxation);
    }
    res.record.accel_mps2 = best;
    m.baseline->correct(res.record.accel_mps2);
    res.iterations = options.max_iterations;
    res.acceptance = check_acceptance(res.record, target);
    return res;
}

}  // namespace freestand::motion
