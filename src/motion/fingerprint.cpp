#include "motion/fingerprint.hpp"

#include <fftw3.h>
#include <gnu/libc-version.h>

#include "core/version.hpp"

namespace freestand::motion {

namespace {

// A field added to one of these structures must be added to its writer and reader below, or
// a cached value would lack it: the sizes stop the build until they are updated together.
static_assert(sizeof(core::Record) == 3 * sizeof(std::string) + sizeof(double) +
                                          sizeof(std::vector<double>),
              "core::Record changed: update write_record and read_record");
static_assert(sizeof(Envelope) == 3 * sizeof(double), "Envelope changed: update its fingerprint");
static_assert(sizeof(MatchOptions) == 4 * sizeof(double) + 2 * sizeof(int) + sizeof(double),
              "MatchOptions changed: update its fingerprint");
// The sizes on the project's platform (x86-64, libstdc++); on another the numbers differ and
// the check is dropped rather than guessed.
#if defined(__x86_64__) && defined(__GLIBCXX__)
static_assert(sizeof(RealismLimits) == 88, "RealismLimits changed: update write_realism and read_realism");
static_assert(sizeof(Acceptance) == 352, "Acceptance changed: update write_acceptance and read_acceptance");
#endif

void write_spectrum(core::ByteWriter& w, const spectra::Spectrum& s) {
    w.f64(s.damping);
    w.f64s(s.frequency_hz);
    w.f64s(s.psa_g);
    w.text(s.label);
}

void write_range(core::ByteWriter& w, const Range& r) {
    w.f64(r.min);
    w.f64(r.max);
}

void write_opt_range(core::ByteWriter& w, const std::optional<Range>& r) {
    w.flag(r.has_value());
    if (r) write_range(w, *r);
}

Range read_range(core::ByteReader& r) {
    Range out;
    out.min = r.f64();
    out.max = r.f64();
    return out;
}

std::optional<Range> read_opt_range(core::ByteReader& r) {
    if (!r.flag()) return std::nullopt;
    return read_range(r);
}

void write_realism(core::ByteWriter& w, const RealismLimits& l) {
    write_range(w, l.pga_over_zpa);
    w.f64(l.d5_75_min_s);
    write_opt_range(w, l.va_mps_per_g);
    write_opt_range(w, l.adv2);
    w.opt_f64(l.da_max_m_per_g);
}

RealismLimits read_realism(core::ByteReader& r) {
    RealismLimits l;
    l.pga_over_zpa = read_range(r);
    l.d5_75_min_s = r.f64();
    l.va_mps_per_g = read_opt_range(r);
    l.adv2 = read_opt_range(r);
    l.da_max_m_per_g = r.opt_f64();
    return l;
}

void write_target(core::ByteWriter& w, const Target& t) {
    write_spectrum(w, t.psa_5pct);
    w.flag(t.psa_10pct.has_value());
    if (t.psa_10pct) write_spectrum(w, *t.psa_10pct);
    w.opt_f64(t.rg160_psd_pga_g);
    write_realism(w, t.realism);
    w.flag(t.horizontal);
    w.f64(t.g_mps2);
}

}  // namespace

void append_fingerprint(core::ByteWriter& w, const TargetSet& targets) {
    w.text(targets.label);
    write_target(w, targets.horizontal);
    write_target(w, targets.vertical);
    w.flag(targets.horizontal_2.has_value());
    if (targets.horizontal_2) write_target(w, *targets.horizontal_2);
}

void append_build_fingerprint(core::ByteWriter& w) {
    w.text(core::build_identity());
    w.text(fftw_version);
    w.text(gnu_get_libc_version());
}

void append_fingerprint(core::ByteWriter& w, const GenerateOptions& o) {
    w.u64(o.components.size());
    for (const std::string& c : o.components) w.text(c);
    w.f64(o.duration_s);
    w.f64(o.dt_s);
    w.u64(o.seed);
    w.u64(o.seed_records.size());
    for (const core::Record& r : o.seed_records) write_record(w, r);
    w.f64(o.envelope.rise_s);
    w.f64(o.envelope.strong_s);
    w.f64(o.envelope.end_level);
    w.f64(o.match.aim);
    w.f64(o.match.lower);
    w.f64(o.match.upper);
    w.f64(o.match.relaxation);
    w.i64(o.match.max_iterations);
    w.i64(o.match.match_per_decade);
    w.f64(o.match.rigid_wavelet_cycles_per_sample);
    w.i64(o.max_attempts);
}

void write_record(core::ByteWriter& w, const core::Record& r) {
    w.text(r.name);
    w.text(r.source);
    w.text(r.component);
    w.f64(r.dt_s);
    w.f64s(r.accel_mps2);
}

core::Record read_record(core::ByteReader& r) {
    core::Record out;
    out.name = r.text();
    out.source = r.text();
    out.component = r.text();
    out.dt_s = r.f64();
    out.accel_mps2 = r.f64s();
    return out;
}

void write_acceptance(core::ByteWriter& w, const Acceptance& a) {
    w.flag(a.passed);
    w.flag(a.srp_passed);
    w.flag(a.realism_passed);
    w.text(a.reason);
    w.u64(a.check_points);
    for (double v : {a.min_ratio, a.max_ratio, a.mean_ratio}) w.f64(v);
    w.i64(a.max_adjacent_below);
    w.f64(a.max_ratio_cap_band);
    for (const auto& v : {a.psd_min_ratio, a.ratio_10pct_min, a.ratio_10pct_max}) w.opt_f64(v);
    for (double v : {a.pga_g, a.pgv_mps, a.pgd_m, a.d5_75_s, a.d5_95_s, a.duration_s, a.dt_s,
                     a.final_velocity_mps, a.final_displacement_m, a.arias_mps, a.zpa_g,
                     a.pga_over_zpa, a.va_mps_per_g, a.adv2, a.da_m_per_g})
        w.f64(v);
    write_realism(w, a.realism);
    w.flag(a.horizontal);
}

Acceptance read_acceptance(core::ByteReader& r) {
    Acceptance a;
    a.passed = r.flag();
    a.srp_passed = r.flag();
    a.realism_passed = r.flag();
    a.reason = r.text();
    a.check_points = static_cast<std::size_t>(r.u64());
    for (double* v : {&a.min_ratio, &a.max_ratio, &a.mean_ratio}) *v = r.f64();
    a.max_adjacent_below = static_cast<int>(r.i64());
    a.max_ratio_cap_band = r.f64();
    for (auto* v : {&a.psd_min_ratio, &a.ratio_10pct_min, &a.ratio_10pct_max}) *v = r.opt_f64();
    for (double* v : {&a.pga_g, &a.pgv_mps, &a.pgd_m, &a.d5_75_s, &a.d5_95_s, &a.duration_s,
                      &a.dt_s, &a.final_velocity_mps, &a.final_displacement_m, &a.arias_mps,
                      &a.zpa_g, &a.pga_over_zpa, &a.va_mps_per_g, &a.adv2, &a.da_m_per_g})
        *v = r.f64();
    a.realism = read_realism(r);
    a.horizontal = r.flag();
    return a;
}

}  // namespace freestand::motion
