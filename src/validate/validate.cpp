#include "validate/validate.hpp"

#include "validate/glovebox.hpp"
#include "validate/joined.hpp"
#include "validate/specimens.hpp"

namespace freestand::validate {

const char* to_string(Agreement a) {
    switch (a) {
        case Agreement::agrees:
            return "agrees";
        case Agreement::differs:
            return "differs";
        case Agreement::not_comparable:
            return "not comparable";
    }
    return "?";
}

const std::vector<std::string>& case_names() {
    static const std::vector<std::string> names{"glovebox-single.toml", "glovebox-steel-pads.toml",
                                                "glovebox-pair.toml", unbraced_pair_case};
    return names;
}

bool has_cases(const std::filesystem::path& cases_dir) {
    for (const std::string& n : case_names()) {
        if (!std::filesystem::is_regular_file(cases_dir / n)) return false;
    }
    return true;
}

Validation run(const std::filesystem::path& cases_dir) {
    Validation v;
    v.groups = {specimen_group(), worked_group(), modes_group(), joined_group(),
                flexible_group()};
    v.rows = specimen_rows();
    const GloveBoxRuns runs = run_glove_boxes(cases_dir);
    for (auto* part : {&worked_rows, &mode_rows, &flexible_rows}) {
        std::vector<Row> rows = (*part)(runs);
        v.rows.insert(v.rows.end(), rows.begin(), rows.end());
    }
    const std::vector<Row> joined = joined_rows(cases_dir);
    v.rows.insert(v.rows.end(), joined.begin(), joined.end());
    v.notes = specimen_notes();
    for (const std::string& n : case_names()) v.case_files.push_back(cases_dir / n);
    return v;
}

}  // namespace freestand::validate
