#pragma once
/// `freestand simulate --model 3d`: the 3D body's --block syntax, text and series CSV
/// (docs/methods.md s.11).
#include <string>

#include "api/simulate.hpp"

namespace freestand::cli {

/// --block "b=HALF_X,d=HALF_Y,h=CG_HEIGHT[,m=MASS][,height=TOTAL]" and the step --dt as the
/// 3D body. Throws UsageError naming --block for a missing or unknown key.
api::Body3dSpec body3d_from_options(const std::string& block, double dt_s);

/// The series CSV of a 3D run (--out).
std::string body3d_series_csv(const api::Body3dRun& run, const std::string& label);

/// The text `simulate --model 3d` prints.
void print_body3d(const api::Body3dRun& run);

}  // namespace freestand::cli
