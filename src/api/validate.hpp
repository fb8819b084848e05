#pragma once
/// validate: the thesis's tests and worked examples against freestand's models
/// (docs/methods.md s.13), rendered as report.md, report.html and result.json.
#include <filesystem>
#include <string>

#include "report/json.hpp"
#include "report/validation.hpp"
#include "validate/validate.hpp"

namespace freestand::api {

struct ValidateRequest {
    std::filesystem::path cases_dir = "cases";  ///< folder of the shipped glove-box cases
    std::string commit;                         ///< the build's commit, stamped into the reports
};

struct ValidateResult {
    ValidateRequest request;
    validate::Validation validation;
    report::Stamp stamp;
    report::ValidationReport reports;  ///< report.md, report.html and result.json
};

/// Every comparison, with its reports; IoError naming cases_dir when it lacks a shipped case.
ValidateResult validate(const ValidateRequest& request);

}  // namespace freestand::api
