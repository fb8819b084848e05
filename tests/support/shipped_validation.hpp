#pragma once
// The validation of the shipped cases (validate::run over cases/), computed once per test process
// and shared by the test files that read it (~20 s of CPU each time it is computed).
#include <filesystem>

#include "support/paths.hpp"
#include "validate/validate.hpp"

namespace freestand::test {

inline const validate::Validation& shipped_validation() {
    static const validate::Validation v =
        validate::run(std::filesystem::path(source_dir()) / "cases");
    return v;
}

}  // namespace freestand::test
