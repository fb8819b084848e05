#include "api/assess.hpp"

#include "assess/case.hpp"
#include "assess/pipeline.hpp"
#include "core/errors.hpp"
#include "core/file_io.hpp"
#include "report/result_document.hpp"

namespace freestand::api {

namespace assess_detail {

// The case as the request gives it: its text (read or given) with the overrides written in,
// then its levels replaced.
assess::Case request_case(const AssessRequest& request, const std::string& bytes) {
    assess::Case c = assess::parse_case(bytes, request.case_file.string(), request.overrides);
    if (request.pga_g) c = assess::with_pga_levels(std::move(c), *request.pga_g);
    return c;
}

}  // namespace assess_detail

AssessResult assess(const AssessRequest& request) {
    const std::string bytes =
        request.case_bytes ? *request.case_bytes : core::read_input_file(request.case_file);
    const assess::Case c = assess_detail::request_case(request, bytes);
    const std::string label = request.case_file.string();
    if (!c.units.empty() && request.single_component)
        throw InputError(SourceLocation{label, 0, "unit"},
                         "two [[unit]] tables where one component is expected (a batch's row "
                         "is one component; assess the pair on its own)");
    if (!c.units.empty() && c.options.fragility.enabled)
        throw InputError(SourceLocation{label, 0, "options.fragility"},
                         "not available for two [[unit]] tables (the fragility analysis takes "
                         "one component)");
    AssessResult out;
    out.request = request;
    out.result = assess::assess(c, request.run);
    if (c.options.fragility.enabled) {
        fragility::Config config;
        config.pga_g = c.options.fragility.pga_g;
        config.samples = c.options.fragility.samples;
        config.seed = c.options.seed;
        // The case's own fragility is decided by the models its levels are.
        config.models = fragility::case_models(c, config.pga_g).models;
        out.fragility = fragility::run_all(c, config, request.run);
    }
    if (c.site.dbe_pga_g) {
        out.goal = goal::evaluate_headline_goal(out.result, request.run);
        goal::apply_goal(out.result, *out.goal);
    }
    out.stamp = report::make_stamp(bytes, label, c.options.seed, request.commit);
    out.stamp.inputs = report::stamped_inputs(c);
    return out;
}

json to_json(const AssessResult& r) {
    return report::result_json(r.result, r.stamp, r.fragility ? &*r.fragility : nullptr,
                               r.goal ? &*r.goal : nullptr);
}

}  // namespace freestand::api
