// Self and inclusive cost per function from callgrind (issue 27). Cachegrind records no calls, so
// a function whose callees got slower shows only as those callees; callgrind records each call
// with the inclusive cost it took, so a function's inclusive cost is its self cost plus what its
// calls cost. `--explain` in timed mode profiles base and head with it (instructions only: no
// cache simulation, which would double callgrind's slowdown). The file is read directly, per the
// callgrind format: "fn=" starts a function's cost lines, "cfn=" then "calls=COUNT TARGET" say the
// next cost line is a call's inclusive cost, names may be compressed as "(id) name" once and
// "(id)" after (one id space for files, one for functions, one for objects).
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "explain/function_profile.h"
#include "runner/cachegrind.h"

namespace raygate {

// Self cost from the function's own cost lines; inclusive = self + the costs of its calls to
// other functions. A direct recursive call (fn calls itself) is left out of the sum: its cost is
// the same function's, counted in self already (mutual recursion is still counted twice, as
// callgrind_annotate does). Throws InfraError naming origin:line for a cost line before any
// fn=, a count that is not a number, more counts than events, an undefined "(id)", or no
// "events:" line.
FunctionProfile parse_callgrind_profile(std::string_view text, const std::string& origin);

// The sum of every callgrind output file in `dir` (callgrind.out.*), one per process;
// InfraError when there is none.
FunctionProfile read_callgrind_profiles(const std::filesystem::path& dir);

// `spec` to run under callgrind (children traced), its output files in `out_dir` (created).
ProcessSpec under_callgrind(ProcessSpec spec, const Cachegrind& valgrind,
                            const std::filesystem::path& out_dir);

}  // namespace raygate
