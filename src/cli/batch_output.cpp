#include "cli/batch_output.hpp"

#include <nlohmann/json.hpp>
#include <fmt/format.h>

#include <iostream>

#include "core/errors.hpp"
#include "core/printable.hpp"
#include "report/summary.hpp"

namespace freestand::cli {

int write_batch_outputs(const batch::BatchRun& run, const std::filesystem::path& out, bool json,
                        const std::string& note) {
    batch::write_batch(out, run);
    if (json) {
        std::cout << report::summary_json(run.summary).dump(2) << "\n";
    } else {
        for (const report::SummaryRow& row : run.summary.rows)
            std::cout << batch::row_line(row) << "\n";
        std::cout << fmt::format("wrote {}: {} components, {} failed{}\n",
                                 core::printable_name(out.string()),
                                 run.summary.rows.size(), run.failed(), note);
    }
    return run.all_assessed() ? 0 : static_cast<int>(ExitCode::failure);
}

}  // namespace freestand::cli
