// [uncertainty] of a case file: the distributions of mu_s and restitution.
#include "assess/case_detail.hpp"

#include <fmt/format.h>

#include "core/limits.hpp"

namespace freestand::assess {

namespace {

// One uncertain property: { dist = "uniform", lo, hi } or { dist = "lognormal", median, beta }.
core::Distribution read_distribution(TableReader& outer, const std::string& key, Range values,
                                     std::optional<double> truncate_at, const std::string& file) {
    TableReader r(outer.table(key), file, "uncertainty." + key);
    core::Distribution d;
    const std::string dist = r.required_string("dist");
    if (dist == "uniform") {
        d.a = r.required_number("lo", values);
        d.b = r.required_number("hi", values);
        if (d.b < d.a) r.fail("hi", fmt::format("{} is below lo = {}; expected lo <= hi", d.b, d.a));
        r.finish({"dist", "lo", "hi"});
        return d;
    }
    if (dist != "lognormal")
        r.fail("dist", fmt::format("\"{}\"; expected \"uniform\" or \"lognormal\"", dist));
    d.kind = core::Distribution::Kind::lognormal;
    d.a = r.required_number("median", Range{0.0, values.hi, false, true});
    d.b = r.required_number("beta", Range{0.0, 2.0, false, true});
    d.upper = truncate_at;
    r.finish({"dist", "median", "beta"});
    return d;
}

}  // namespace

namespace case_detail {

Uncertainty read_uncertainty(TableReader& r, const std::string& file) {
    Uncertainty u;
    // A drawn friction is a case's friction (core::limits::friction): a lognormal law is
    // truncated at its top, as restitution's at 1, so no sample leaves the model's range.
    if (r.has("mu_s"))
        u.mu_s = read_distribution(r, "mu_s", core::limits::friction, core::limits::friction.hi,
                                   file);
    if (r.has("restitution"))
        u.restitution = read_distribution(r, "restitution", Range{0.0, 1.0}, 1.0, file);
    r.finish({"mu_s", "restitution"});
    return u;
}

}  // namespace case_detail

}  // namespace freestand::assess
