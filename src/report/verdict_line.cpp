#include "report/verdict_line.hpp"

#include <fmt/format.h>

#include "assess/verdict.hpp"
#include "core/printable.hpp"
#include "report/joined.hpp"
#include "report/render.hpp"

namespace freestand::report {

std::string verdict_line(const assess::AssessmentResult& r) {
    // One line on a terminal: a name's line breaks and bidirectional overrides are shown, not
    // obeyed (a CR would let the name overwrite the verdict).
    if (r.joined) return core::printable_name(joined_verdict_line(r));
    const assess::Verdict& v = r.overall.verdict;
    std::string out =
        fmt::format("{}: {} (governing {}, margin {}, decided by {})", r.input.component.name,
                    assess::verdict_text(v), headline_level(r), assess::margin_text(v),
                    assess::to_string(v.decided_by));
    for (const std::string& c : v.conditions) out += "; open condition: " + c;
    return core::printable_name(out);
}

}  // namespace freestand::report
