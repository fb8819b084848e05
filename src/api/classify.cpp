#include "api/classify.hpp"

#include <cmath>

#include "core/errors.hpp"
#include "core/limits.hpp"
#include "rocking/checks.hpp"

namespace freestand::api {

const char* edge_name(block::Edge e) { return e == block::Edge::left ? "left" : "right"; }

ClassifyResult classify(const ClassifyRequest& request) {
    core::limits::require_in(request.mu_s, core::limits::friction, SourceLocation{"", 0, "mu_s"});
    require_in_range(request.a_h_g, 0.0, HUGE_VAL, SourceLocation{"", 0, "a_h_g"}, true, false);
    require_in_range(request.av_g, 0.0, 1.0, SourceLocation{"", 0, "av_g"}, true, false);
    const block::Block blk = sliding::make_block(request.box);
    return {request, sliding::classify_peak(blk, request.mu_s, request.a_h_g, request.av_g)};
}

json to_json(const sliding::Initiation& i) {
    json j;
    j["mode"] = sliding::to_string(i.mode);
    j["edge"] = edge_name(i.edge);
    j["tan_alpha"] = i.tan_alpha;
    j["A"] = i.A;
    j["mu_crit"] = number_or_null(i.mu_crit);
    if (!i.mu_crit) j["mu_crit_reason"] = i.mu_crit_reason;
    j["decided_by"] = sliding::describe(i.decided_by);
    return j;
}

json to_json(const ClassifyResult& result) {
    const sliding::PeakInitiation& p = result.initiation;
    const ClassifyRequest& r = result.request;
    json j = to_json(p.governing());
    j["mu_s"] = r.mu_s;
    j["a_h_g"] = r.a_h_g;
    j["av_g"] = r.av_g;
    j["vertical"] = "peak applied downward (worst case)";
    j["amplification_warning"] =
        rocking::amplification_warning(p.governing().mode, r.mu_s, p.governing().A);
    j["edges"] = json{{"left", to_json(p.left)}, {"right", to_json(p.right)}};
    return j;
}

}  // namespace freestand::api
