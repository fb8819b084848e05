#include "assess/history_cache.hpp"

#include "core/bytes.hpp"
#include "core/sha256.hpp"
#include "motion/fingerprint.hpp"

namespace freestand::assess {

namespace {

// Raised when the layout below changes (the key then differs too, so old entries are unused).
constexpr std::uint64_t format_version = 1;

static_assert(sizeof(HistorySet) == 3 * sizeof(core::Record) +
                                        sizeof(std::vector<motion::Acceptance>) +
                                        sizeof(std::vector<motion::Correlation>) +
                                        sizeof(bool) * 8 + sizeof(std::string),
              "HistorySet changed: update encode_history and decode_history");

}  // namespace

std::string history_key(const motion::TargetSet& targets, const motion::GenerateOptions& options,
                        std::uint64_t case_seed, std::size_t k) {
    core::ByteWriter w;
    w.text("freestand history set");
    w.u64(format_version);
    w.text(motion::generator_version);
    motion::append_build_fingerprint(w);
    motion::append_fingerprint(w, targets);
    motion::append_fingerprint(w, options);
    w.u64(case_seed);
    w.u64(k);
    return core::sha256_hex(w.bytes());
}

std::string encode_history(const HistorySet& set) {
    core::ByteWriter w;
    w.u64(format_version);
    for (const core::Record* r : {&set.h1, &set.h2, &set.v}) motion::write_record(w, *r);
    w.u64(set.acceptance.size());
    for (const motion::Acceptance& a : set.acceptance) motion::write_acceptance(w, a);
    w.u64(set.correlations.size());
    for (const motion::Correlation& c : set.correlations) {
        w.text(c.a);
        w.text(c.b);
        w.f64(c.rho);
    }
    w.flag(set.passed);
    w.text(set.method);
    return w.take();
}

std::optional<HistorySet> decode_history(std::string_view bytes) {
    core::ByteReader r(bytes);
    if (r.u64() != format_version) return std::nullopt;
    HistorySet set;
    for (core::Record* rec : {&set.h1, &set.h2, &set.v}) *rec = motion::read_record(r);
    const std::uint64_t n_acceptance = r.u64();
    for (std::uint64_t i = 0; i < n_acceptance && !r.failed(); ++i)
        set.acceptance.push_back(motion::read_acceptance(r));
    const std::uint64_t n_correlations = r.u64();
    for (std::uint64_t i = 0; i < n_correlations && !r.failed(); ++i) {
        motion::Correlation c;
        c.a = r.text();
        c.b = r.text();
        c.rho = r.f64();
        set.correlations.push_back(std::move(c));
    }
    set.passed = r.flag();
    set.method = r.text();
    if (r.failed() || !r.at_end()) return std::nullopt;
    return set;
}

}  // namespace freestand::assess
