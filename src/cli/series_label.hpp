#pragma once
/// The excitation's label on a series CSV's comment line (simulate --out).
#include <string>

#include "core/printable.hpp"

namespace freestand::cli {

/// The label (from a file name) on one line: control characters as \xNN and a line break or tab
/// as a blank, so a file named with ESC, BEL or a newline cannot put them raw into the CSV.
inline std::string one_line_label(const std::string& label) {
    std::string s = core::printable(label);
    for (char& c : s)
        if (c == '\n' || c == '\t') c = ' ';
    return s;
}

}  // namespace freestand::cli
