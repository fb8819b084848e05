// The command-line value parsers (cli/options.hpp): one splitter, numbers, key=value lists.
#include <catch2/catch.hpp>

#include "cli/options.hpp"
#include "core/errors.hpp"
#include "sliding/block_spec.hpp"
#include "cli/usage_error.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_cli_test_options {

using namespace freestand;

TEST_CASE("one splitter keeps empty items for the caller to name", "[cli][options]") {
    CHECK(cli::split_list("a,b,,c") == std::vector<std::string>{"a", "b", "", "c"});
    CHECK(cli::split_list("x") == std::vector<std::string>{"x"});
    CHECK(cli::split_list("x,") == std::vector<std::string>{"x", ""});
    CHECK(cli::parse_double_list("0.1,0.2", "--pga") == std::vector<double>{0.1, 0.2});
    CHECK_THROWS_WITH(cli::parse_double_list("0.1,,0.2", "--pga"),
                      Catch::Contains("--pga: expected a finite number; got \"\""));
    CHECK(cli::parse_key_values("b=0.15,h=0.6", "--block", {"b", "h", "m"}).size() == 2);
    CHECK_THROWS_WITH(cli::parse_key_values("b=0.15,", "--block", {"b", "h"}),
                      Catch::Contains("--block: expected key=value; got \"\""));
}

TEST_CASE("whole numbers: counts, seeds and threads are never truncated", "[cli][options]") {
    CHECK(cli::parse_whole("100", "--samples", 0, 1e6) == 100);
    CHECK(cli::parse_whole("1e2", "--samples", 0, 1e6) == 100);
    CHECK(cli::parse_whole("0", "--threads", 0, 1024) == 0);
    CHECK(cli::parse_whole("8999999999999999", "--seed", 0, 9e15) == 8999999999999999ULL);
    for (const char* bad : {"2.5", "-1", "1025", "nan", "", "3x"}) {
        INFO(bad);
        CHECK_THROWS_AS(cli::parse_whole(bad, "--threads", 0, 1024), UsageError);
    }
    CHECK_THROWS_WITH(cli::parse_whole("2.5", "--pool", 0, 100),
                      "--pool: expected a whole number in [0, 100]; got \"2.5\"");
}

TEST_CASE("the block options give the same block in both --cg forms", "[cli][options]") {
    const block::Block a =
        sliding::make_block(cli::box_from_options("b=0.2,h=0.5,m=10", std::string("0.25,0.4"), 1.5));
    const block::Block b = sliding::make_block(
        cli::box_from_options("b=0.2,h=0.5,m=10", std::string("x=0.05,h=0.4"), 1.5));
    CHECK(a.b_left_m == Approx(b.b_left_m));
    CHECK(a.b_right_m == Approx(b.b_right_m));
    CHECK(a.h_m == Approx(0.4));
    const block::Block u =
        sliding::make_block(cli::box_from_options("b=0.2,h=0.5", std::nullopt, std::nullopt));
    CHECK(u.mass_kg == 1.0);  // per unit mass by default, in every command
    CHECK(u.inertia_cg_kgm2 == Approx(block::uniform_inertia_cg_kgm2(1.0, 0.2, 0.5)));
}

}  // namespace freestand_test_cli_test_options
