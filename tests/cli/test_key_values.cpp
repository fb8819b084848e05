// Key=value lists of option values (--block, --cg, --flexible, --sine's and --sine-y's ramp
// and phase): one parser, which refuses an unknown key and a key given twice.
#include <catch2/catch.hpp>

#include "support/cli_probes.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_cli_test_key_values {

namespace {

const std::string block = "--block b=0.15,h=0.6,m=38 ";
// A block that only slides (tan alpha = 0.5 > mu), as the biaxial model needs.
const std::string slider = "--block b=0.3,h=0.6,m=38 --mu 0.2 ";

using freestand::test::check_cli_probes;

}  // namespace

TEST_CASE("a key given twice in a key=value list is refused, in every option",
          "[cli][options]") {
    // A repeated key would otherwise silently take its last value.
    check_cli_probes({
        {"simulate " + slider + "--sine-y 0.4g,2Hz,2s,phase=90,phase=0",
         "--sine-y: key \"phase\" given twice", 2},
        {"simulate " + slider + "--sine-y 0.4g,2Hz,2s,ramp=1s,ramp=0.5s",
         "--sine-y: key \"ramp\" given twice", 2},
        {"simulate " + slider + "--sine-y 0.4g,2Hz,2s,spin=1",
         "--sine-y: unknown key \"spin\"; allowed: ramp, phase", 2},
        {"simulate " + block + "--mu 0.6 --sine 0.4g,2Hz,2s,phase=90",
         "--sine: unknown key \"phase\"; allowed: ramp", 2},
        {"simulate --block b=0.15,b=0.2,h=0.6 --mu 0.6 --sine 0.4g,2Hz,2s",
         "--block: key \"b\" given twice", 2},
        {"simulate " + block + "--cg x=0,x=0.01,h=0.6 --mu 0.6 --sine 0.4g,2Hz,2s",
         "--cg: key \"x\" given twice", 2},
        {"simulate " + block + "--mu 0.6 --sine 0.4g,2Hz,2s --flexible f=4,f=5",
         "--flexible: key \"f\" given twice", 2},
    });
}

}  // namespace freestand_test_cli_test_key_values
