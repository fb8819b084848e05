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
        case Agreement::not_runnable:
            return "not runnable";
    }
    return "?";
}

const char* to_string(Kind k) {
    switch (k) {
        case Kind::by_construction:
            return "by construction";
        case Kind::outcome:
            return "outcome";
        case Kind::quantitative:
            return "quantitative";
    }
    return "?";
}

std::vector<Tally> tally(const std::vector<Row>& rows) {
    std::vector<Tally> out;
    for (Kind k : {Kind::by_construction, Kind::outcome, Kind::quantitative}) {
        Tally t;
        t.kind = k;
        for (const Row& r : rows) {
            if (r.kind != k) continue;
            ++t.rows;
            switch (r.agreement) {
                case Agreement::agrees:
                    ++t.agrees;
                    break;
                case Agreement::differs:
                    ++t.differs;
                    break;
                case Agreement::not_comparable:
                    ++t.not_comparable;
                    break;
                case Agreement::not_runnable:
                    ++t.not_runnable;
                    break;
            }
        }
        out.push_back(t);
    }
    return out;
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
    const GloveBoxRuns runs = run_glove_boxes(cases_dir);
    const RandomRuns random = run_random(runs.pvc.input, "glovebox-single.toml");
    Validation v;
    v.groups = {specimen_group(), rest_group(),   random_group(random), worked_group(),
                modes_group(),    joined_group(), flexible_group()};
    const auto append = [&v](const std::vector<Row>& rows) {
        v.rows.insert(v.rows.end(), rows.begin(), rows.end());
    };
    append(specimen_rows());
    append(rest_rows());
    append(random_rows(random));
    for (auto* part : {&worked_rows, &mode_rows, &flexible_rows}) append((*part)(runs));
    append(joined_rows(cases_dir));
    v.notes = specimen_notes();
    v.notes.push_back(random_note(random));
    for (const std::string& n : case_names()) v.case_files.push_back(cases_dir / n);
    return v;
}

}  // namespace freestand::validate
