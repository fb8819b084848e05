// `freestand merge` of fragility shards checks every sample against its run before it
// aggregates: the drawn friction, restitution and motion against the sample's own stream, the
// peaks' ranges, an overturn against theta/alpha; refused with exit 3 naming file, line and key.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <sstream>
#include <unistd.h>

#include "support/run_cli.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_fragility_test_shard_checks {

namespace fs = std::filesystem;
using Catch::Contains;
using freestand::test::run_cli;
using freestand::test::slurp;
using nlohmann::json;

namespace {

// A block that slides and rocks under two short sines (no history to generate), friction
// uniform on [0.2, 0.4]: one shard of 2 levels x 6 samples, none overturning at 0.2-0.4 g.
struct Scene {
    fs::path dir = fs::temp_directory_path() /
                   ("freestand_frag_shard_checks_" + std::to_string(::getpid()));
    fs::path shard = dir / "s" / "shard-1-of-1.jsonl";
    Scene() {
        fs::remove_all(dir);
        fs::create_directories(dir);
        for (const auto& [name, f_hz] : {std::pair{"a.csv", 1.5}, std::pair{"b.csv", 3.0}}) {
            std::ofstream out(dir / name);
            out << "time_s,accel_g\n";
            for (int i = 0; i <= 2000; ++i) {
                const double t = i * 0.002;
                out << t << "," << std::sin(2.0 * M_PI * f_hz * t) * std::min(1.0, t) << "\n";
            }
        }
        std::ofstream(dir / "block.toml") << R"([component]
name = "Test block"
mass_kg = 200.0
width_m = 0.4
depth_m = 0.4
height_m = 1.2
mu_s = 0.3
restitution = 0.9
allowable_slide_m = 0.02
[site]
pga_g = [0.3]
[options]
seed = 5
[uncertainty]
mu_s = { dist = "uniform", lo = 0.2, hi = 0.4 }
)";
        const auto r = run_cli("fragility '" + (dir / "block.toml").string() +
                               "' --pga 0.2:0.4:0.2 --samples 6 --records '" +
                               (dir / "a.csv").string() + "' '" + (dir / "b.csv").string() +
                               "' --threads 1 --shard 1/1 --out '" + (dir / "s").string() + "'");
        REQUIRE(r.exit_code == 0);
    }
    ~Scene() { fs::remove_all(dir); }

    std::vector<std::string> lines() const {
        std::vector<std::string> out;
        std::istringstream in(slurp(shard));
        for (std::string l; std::getline(in, l);) out.push_back(l);
        return out;
    }
    // The first sample line (1-based) whose JSON satisfies pick.
    int line_where(const std::function<bool(const json&)>& pick) const {
        const auto all = lines();
        for (std::size_t i = 1; i < all.size(); ++i)
            if (pick(json::parse(all[i]))) return static_cast<int>(i + 1);
        FAIL("no sample fits");
        return 0;
    }
    // Edits line (1-based) as JSON, merges the edited copy; nothing may be written.
    freestand::test::CliResult merge_edited(int line, const std::function<void(json&)>& edit) const {
        auto all = lines();
        json j = json::parse(all.at(static_cast<std::size_t>(line - 1)));
        edit(j);
        all[static_cast<std::size_t>(line - 1)] = j.dump();
        std::string text;
        for (const auto& l : all) text += l + "\n";
        fs::create_directories(dir / "e");
        std::ofstream(dir / "e" / "shard-1-of-1.jsonl", std::ios::binary) << text;
        const auto r = run_cli("merge '" + (dir / "e").string() + "' --out '" +
                               (dir / "m").string() + "'");
        CHECK_FALSE(fs::exists(dir / "m"));
        return r;
    }
    std::string at(int line) const {
        return (dir / "e" / "shard-1-of-1.jsonl").string() + ":" + std::to_string(line) + ": ";
    }
};

}  // namespace

TEST_CASE("merge refuses a fragility shard whose samples contradict their run",
          "[fragility][shard][errors]") {
    const Scene s;
    const int line = 2;  // level 1, sample 1
    SECTION("the shard as written merges") {
        const auto r = run_cli("merge '" + (s.dir / "s").string() + "' --out '" +
                               (s.dir / "m").string() + "'");
        CHECK(r.exit_code == 0);
    }
    SECTION("mu_s 5, outside the run's friction law") {
        const auto r = s.merge_edited(line, [](json& j) { j["mu_s"] = 5.0; });
        CHECK(r.exit_code == 3);
        CHECK_THAT(r.err, Contains(s.at(line) + "mu_s: value 5 is out of range; expected [0.2, 0.4]"));
    }
    SECTION("a mu_s within the law but not the sample's draw") {
        double drawn = 0.0;
        const auto r = s.merge_edited(line, [&](json& j) {
            drawn = j["mu_s"].get<double>();
            j["mu_s"] = drawn == 0.3 ? 0.31 : 0.3;
        });
        CHECK(r.exit_code == 3);
        CHECK_THAT(r.err, Contains(s.at(line) + "mu_s: malformed fragility shard: "));
        CHECK_THAT(r.err, Contains("that sample 1 of level 1 draws from its stream (seed 5)"));
    }
    SECTION("another motion than the sample draws") {
        const auto r = s.merge_edited(line, [](json& j) {
            j["motion"] = j["motion"] == "a.csv" ? "b.csv" : "a.csv";
        });
        CHECK(r.exit_code == 3);
        CHECK_THAT(r.err, Contains(s.at(line) + "motion: malformed fragility shard: "));
    }
    SECTION("a negative slide") {
        const auto r = s.merge_edited(line, [](json& j) { j["slide_max_m"] = -0.01; });
        CHECK(r.exit_code == 3);
        CHECK_THAT(r.err, Contains(s.at(line) + "slide_max_m: value -0.01 must be a finite number >= 0"));
    }
    SECTION("a negative theta/alpha") {
        const auto r = s.merge_edited(line, [](json& j) { j["rock_max_over_alpha"] = -0.5; });
        CHECK(r.exit_code == 3);
        CHECK_THAT(r.err, Contains(s.at(line) + "rock_max_over_alpha: value -0.5 must be a finite number >= 0"));
    }
    SECTION("overturned flipped on a sample that stayed below theta = alpha") {
        const int standing = s.line_where([](const json& j) {
            return !j["overturned"].get<bool>() && j["rock_max_over_alpha"].get<double>() < 0.9;
        });
        const auto r = s.merge_edited(standing, [](json& j) { j["overturned"] = true; });
        CHECK(r.exit_code == 3);
        CHECK_THAT(r.err, Contains(s.at(standing) + "overturned: malformed fragility shard: true "
                                                    "with theta/alpha "));
    }
    SECTION("a level outside the run") {
        const auto r = s.merge_edited(line, [](json& j) { j["level"] = 7; });
        CHECK(r.exit_code == 3);
        CHECK_THAT(r.err, Contains(s.at(line) + "level: malformed fragility shard: 7; expected 0 to 1"));
    }
    SECTION("a sample given twice") {
        const auto r = s.merge_edited(3, [&](json& j) {
            j = json::parse(s.lines()[1]);
        });
        CHECK(r.exit_code == 3);
        CHECK_THAT(r.err, Contains(s.at(3) + "sample: malformed fragility shard: sample 1 of level 1 "
                                             "is also at " + s.at(2).substr(0, s.at(2).size() - 2)));
    }
    SECTION("an edited law in the header") {
        const auto r = s.merge_edited(1, [](json& j) { j["run"]["meta"]["laws"]["mu_s"]["b"] = 0.1; });
        CHECK(r.exit_code == 3);
        CHECK_THAT(r.err, Contains(s.at(1) + "run.meta.laws.mu_s.b: value 0.1 is out of range; "
                                             "expected [0.2, 10]"));
    }
    SECTION("a required factor of safety below 1") {
        const auto r = s.merge_edited(1, [](json& j) { j["run"]["meta"]["required_overturn_fs"] = 0.5; });
        CHECK(r.exit_code == 3);
        CHECK_THAT(r.err, Contains(s.at(1) + "run.meta.required_overturn_fs: value 0.5 is out of range"));
    }
    SECTION("a count of samples that is not a whole number") {
        const auto r = s.merge_edited(1, [](json& j) { j["run"]["meta"]["samples"] = 6.5; });
        CHECK(r.exit_code == 3);
        CHECK_THAT(r.err, Contains(s.at(1) + "run.meta.samples: malformed fragility shard: expected "
                                             "a whole number; got 6.5"));
    }
}

}  // namespace freestand_test_fragility_test_shard_checks
