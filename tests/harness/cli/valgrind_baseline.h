// Skipping a test case that runs raygate-baseline under valgrind, in the builds where valgrind
// cannot run it. Under the sanitizers (the asan preset) the baseline carries AddressSanitizer,
// whose runtime must be the first library loaded; valgrind preloads its own first, so the
// baseline stops at once ("ASan runtime does not come first in initial library list"). CMake then
// defines RAYGATE_NO_VALGRIND_BASELINE to the reason (tests/harness/CMakeLists.txt). The case is
// reported skipped with that reason, never passed. Release and debug builds run every case.
#pragma once

#include <gtest/gtest.h>

#ifdef RAYGATE_NO_VALGRIND_BASELINE
#define RAYGATE_SKIP_UNLESS_VALGRIND_RUNS_BASELINE() GTEST_SKIP() << RAYGATE_NO_VALGRIND_BASELINE
#else
#define RAYGATE_SKIP_UNLESS_VALGRIND_RUNS_BASELINE() static_cast<void>(0)
#endif
