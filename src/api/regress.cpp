#include "api/regress.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "api/assess.hpp"
#include "core/errors.hpp"
#include "core/file_io.hpp"
#include "report/verdict_line.hpp"
#include "validate/validate.hpp"

namespace freestand::api {

namespace regress_detail {

namespace fs = std::filesystem;

void compare(const json& a, const json& b, const std::string& path, double rtol,
             std::vector<Difference>& out) {
    if (a.is_number() && b.is_number()) {
        const double x = a.get<double>();
        const double y = b.get<double>();
        if (std::abs(x - y) > rtol * std::max(std::abs(x), std::abs(y)))
            out.push_back({path, a.dump(), b.dump()});
        return;
    }
    if (a.type() != b.type()) {
        out.push_back({path, a.dump(), b.dump()});
        return;
    }
    if (a.is_object()) {
        for (const auto& [key, value] : a.items()) {
            const std::string p = path + "/" + key;
            if (path.empty() && key == "stamp") continue;
            if (!b.contains(key)) {
                out.push_back({p, value.dump(), "(missing)"});
            } else {
                compare(value, b.at(key), p, rtol, out);
            }
        }
        for (const auto& [key, value] : b.items()) {
            if (!a.contains(key) && !(path.empty() && key == "stamp"))
                out.push_back({path + "/" + key, "(missing)", value.dump()});
        }
        return;
    }
    if (a.is_array()) {
        if (a.size() != b.size()) {
            out.push_back({path + "/length", std::to_string(a.size()), std::to_string(b.size())});
            return;
        }
        for (std::size_t i = 0; i < a.size(); ++i)
            compare(a[i], b[i], path + "/" + std::to_string(i), rtol, out);
        return;
    }
    if (a != b) out.push_back({path, a.dump(), b.dump()});
}

std::vector<fs::path> case_files(const fs::path& dir) {
    if (!fs::is_directory(dir)) throw IoError(dir.string() + ": not a folder of case files");
    std::vector<fs::path> out;
    for (const auto& e : fs::directory_iterator(dir)) {
        if (e.is_regular_file() && e.path().extension() == ".toml") out.push_back(e.path());
    }
    std::sort(out.begin(), out.end());
    return out;
}

// A headline value (a JSON pointer into the document) as one line: a string as it is, anything
// else as JSON.
std::string headline_text(const json& doc, const std::string& headline) {
    const json::json_pointer at(headline);
    if (!doc.contains(at)) return "(none)";
    const auto& h = doc.at(at);
    return h.is_string() ? h.get<std::string>() : h.dump();
}

// Compares a fresh result.json with the golden in entry.dir.
void check(RegressEntry& entry, const std::string& fresh_json, double rtol) {
    const fs::path golden_file = entry.dir / "result.json";
    const json fresh = json::parse(fresh_json);
    entry.fresh_headline = headline_text(fresh, entry.headline);
    if (!fs::exists(golden_file)) {
        entry.status = RegressEntry::Status::missing;
        return;
    }
    json golden;
    try {
        golden = json::parse(core::read_text_file(golden_file));
    } catch (const json::parse_error& e) {
        throw InputError(SourceLocation{golden_file.string(), 0, ""},
                         std::string("not valid JSON: ") + e.what());
    }
    entry.differences = compare_results(golden, fresh, rtol);
    if (entry.differences.empty()) return;
    entry.status = RegressEntry::Status::changed;
    entry.golden_headline = headline_text(golden, entry.headline);
}

RegressEntry regress_case(const fs::path& case_file, const RegressRequest& request) {
    RegressEntry entry;
    entry.name = case_file.stem().string();
    entry.dir = request.reports_dir / entry.name;
    entry.headline = "/verdict";
    AssessRequest one;
    one.case_file = case_file;
    one.commit = request.commit;
    one.run = request.run;
    AssessReport r = assess_report(one);
    if (!request.update) {
        check(entry, r.rendered.json, request.rtol);
        return entry;
    }
    entry.status = RegressEntry::Status::updated;
    entry.fresh_headline = report::verdict_line(r.assessed.result);
    entry.report = std::move(r.rendered);
    return entry;
}

// The validation against the thesis (reports/validation/), when the cases folder holds the
// shipped cases it assesses.
RegressEntry regress_validation(const RegressRequest& request) {
    RegressEntry entry;
    entry.name = "validation";
    entry.dir = request.reports_dir / entry.name;
    entry.headline = "/summary/text";
    if (!validate::has_cases(request.cases_dir)) {
        entry.status = RegressEntry::Status::skipped;
        return entry;
    }
    const validate::Validation v = validate::run(request.cases_dir);
    report::ValidationReport rendered =
        report::render_validation(v, report::validation_stamp(v, request.commit));
    if (!request.update) {
        check(entry, rendered.json, request.rtol);
        return entry;
    }
    entry.status = RegressEntry::Status::updated;
    entry.fresh_headline = headline_text(json::parse(rendered.json), entry.headline);
    entry.validation = std::move(rendered);
    return entry;
}

}  // namespace regress_detail

std::vector<Difference> compare_results(const json& golden, const json& fresh, double rtol) {
    std::vector<Difference> out;
    regress_detail::compare(golden, fresh, "", rtol, out);
    return out;
}

bool RegressResult::all_ok() const {
    return std::none_of(entries.begin(), entries.end(), [](const RegressEntry& e) {
        return e.status == RegressEntry::Status::changed ||
               e.status == RegressEntry::Status::missing;
    });
}

RegressResult regress(const RegressRequest& request) {
    if (!std::isfinite(request.rtol) || request.rtol < 0.0)
        throw InputError(SourceLocation{"", 0, "rtol"},
                         fmt::format("expected a number >= 0; got {}", request.rtol));
    RegressResult out;
    const auto done = [&](RegressEntry entry) {
        if (request.on_entry) request.on_entry(entry);
        out.entries.push_back(std::move(entry));
    };
    for (const std::filesystem::path& case_file : regress_detail::case_files(request.cases_dir))
        done(regress_detail::regress_case(case_file, request));
    done(regress_detail::regress_validation(request));
    return out;
}

}  // namespace freestand::api
