#pragma once
/// The glove-box pair of the thesis (s.2.4.2, s.6.3, s.7.3): the relative displacement at the
/// tunnel that freestand's assessment of cases/glovebox-pair-unbraced.toml predicts at 0.2, 0.3
/// and 0.4 g, beside what the shake table showed (docs/methods.md s.10), and the braced pair's
/// integrity.
#include <filesystem>
#include <vector>

#include "validate/validate.hpp"

namespace freestand::validate {

/// The shipped case the rows assess.
inline constexpr const char* unbraced_pair_case = "glovebox-pair-unbraced.toml";

Group joined_group();

/// Assesses the shipped unbraced pair at 0.2, 0.3 and 0.4 g (IoError / InputError from the
/// reader) and compares its tunnel demand with the thesis; then the braced pair's integrity
/// (s.7.3), which the braced case keeps by construction.
std::vector<Row> joined_rows(const std::filesystem::path& cases_dir);

}  // namespace freestand::validate
