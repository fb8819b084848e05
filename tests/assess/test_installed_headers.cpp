// The installed headers (cmake/install.cmake: every src/<stage>/*.hpp but *_detail.hpp) leave
// toml++ to the case reader's sources: a project using the package needs no TOML library.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "support/paths.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_assess_test_installed_headers {

namespace fs = std::filesystem;

TEST_CASE("no installed header includes toml++") {
    const fs::path src = fs::path(freestand::test::source_dir()) / "src";
    std::vector<std::string> offenders;
    std::size_t installed = 0;
    for (const auto& entry : fs::recursive_directory_iterator(src)) {
        const std::string name = entry.path().filename().string();
        if (entry.path().extension() != ".hpp" || name.ends_with("_detail.hpp")) continue;
        ++installed;
        std::ifstream in(entry.path());
        std::stringstream text;
        text << in.rdbuf();
        if (text.str().find("#include <toml++") != std::string::npos)
            offenders.push_back(fs::relative(entry.path(), src).string());
    }
    CHECK(installed > 50);  // the walk saw the stages' headers
    CHECK(offenders == std::vector<std::string>{});
}

}  // namespace freestand_test_assess_test_installed_headers
