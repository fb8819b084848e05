#include "api/validate.hpp"

#include <fmt/format.h>

#include "core/errors.hpp"

namespace freestand::api {

ValidateResult validate(const ValidateRequest& request) {
    if (!validate::has_cases(request.cases_dir)) {
        std::string names;
        for (const std::string& n : validate::case_names())
            names += (names.empty() ? "" : ", ") + n;
        throw IoError(fmt::format("{}: expected the shipped cases {} (the repository's cases "
                                  "folder)",
                                  request.cases_dir.string(), names));
    }
    validate::Validation v = validate::run(request.cases_dir);
    report::Stamp stamp = report::validation_stamp(v, request.commit);
    report::ValidationReport reports = report::render_validation(v, stamp);
    return {request, std::move(v), std::move(stamp), std::move(reports)};
}

}  // namespace freestand::api
