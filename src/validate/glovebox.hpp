#pragma once
/// The glove box of the thesis (Chapters 5-7): its ASCE 4 and energy worked examples (s.5.5,
/// s.6.4) reproduced with freestand's sliding functions (docs/methods.md s.4), the shipped cases
/// assessed by freestand's pipeline (docs/methods.md s.6), and the modes the thesis saw on PVC
/// and on steel pads.
#include <filesystem>
#include <string>
#include <vector>

#include "assess/result.hpp"
#include "validate/validate.hpp"

namespace freestand::validate {

/// The shipped cases assessed as a user would, at the thesis's levels, with simulate = "always"
/// so every level has its simulated peaks and the energy method its DeltaD.
struct GloveBoxRuns {
    assess::AssessmentResult pvc;    ///< glovebox-single.toml at 0.1, 0.15, 0.2, 0.3 g
    assess::AssessmentResult steel;  ///< glovebox-steel-pads.toml at 0.1, 0.2, 0.3, 0.4 g
    assess::AssessmentResult pair;   ///< glovebox-pair.toml at 0.2, 0.3 g
};

/// Reads and assesses the three cases from cases_dir (IoError / InputError from the reader).
GloveBoxRuns run_glove_boxes(const std::filesystem::path& cases_dir);

/// The level of r at pga_g in direction x; std::logic_error if absent.
const assess::LevelResult& level_x(const assess::AssessmentResult& r, double pga_g);

/// Worked examples: the thesis's arithmetic with its own inputs, then the shipped cases.
Group worked_group();
std::vector<Row> worked_rows(const GloveBoxRuns& runs);

/// Frequency-induced rocking on steel pads: the flexible-body model (glovebox_flexible.cpp).
Group flexible_group();
std::vector<Row> flexible_rows(const GloveBoxRuns& runs);

/// Modes on PVC and on steel pads.
Group modes_group();
std::vector<Row> mode_rows(const GloveBoxRuns& runs);

}  // namespace freestand::validate
