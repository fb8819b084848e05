// Debug-only invariant checks (core/contract.hpp): a violated contract aborts, naming itself.
#ifndef FREESTAND_CHECK_CONTRACTS  // the contracts build defines it for every file
#define FREESTAND_CHECK_CONTRACTS
#endif
#include "core/contract.hpp"

#include <catch2/catch.hpp>

#include <csignal>
#include <sys/wait.h>
#include <unistd.h>

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_core_test_contract {

TEST_CASE("a violated contract aborts, a kept one does nothing", "[core][contract]") {
    FREESTAND_EXPECT(1 + 1 == 2, "arithmetic");
    const pid_t child = ::fork();
    REQUIRE(child >= 0);
    if (child == 0) {
        std::freopen("/dev/null", "w", stderr);
        FREESTAND_EXPECT(1 + 1 == 3, "arithmetic");
        std::_Exit(0);
    }
    int status = 0;
    REQUIRE(::waitpid(child, &status, 0) == child);
    CHECK(WIFSIGNALED(status));
    CHECK(WTERMSIG(status) == SIGABRT);
}

}  // namespace freestand_test_core_test_contract
