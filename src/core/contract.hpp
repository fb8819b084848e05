#pragma once
/// Debug-only invariant checks at the solvers' contracts, in the manner of MFEM's
/// MFEM_ASSERT: a condition that must hold whatever the input, checked when
/// FREESTAND_CHECK_CONTRACTS is defined (the asan preset and Debug builds) and compiled out
/// otherwise, so release timings are unaffected. A violation is a bug: it aborts with the
/// condition, the message and the source location (exit 70 is reserved for bugs the CLI
/// catches; an abort is what sanitizer and fuzz runs report).
#include <cstdio>
#include <cstdlib>

#if defined(FREESTAND_CHECK_CONTRACTS) || !defined(NDEBUG)
#define FREESTAND_EXPECT(condition, message)                                                  \
    do {                                                                                      \
        if (!(condition)) {                                                                   \
            std::fprintf(stderr, "freestand: contract violated: %s (%s) at %s:%d\n",          \
                         #condition, message, __FILE__, __LINE__);                            \
            std::abort();                                                                     \
        }                                                                                     \
    } while (false)
#else
#define FREESTAND_EXPECT(condition, message) \
    do {                                     \
        (void)sizeof(condition);             \
    } while (false)
#endif
