// A mutation-based fuzzer of our own, for the fuzz targets where libFuzzer is not built (gcc
// builds; the `fuzz` preset builds libFuzzer binaries with clang): it takes the corpus, changes
// random inputs the way input goes wrong (bits, bytes, cut and repeated ranges, pieces of other
// inputs, tokens such as 1e400, -1, null, a NUL, a duplicated key) and runs the target on each,
// for a given time. No coverage guidance, so it finds less than libFuzzer per execution; it
// needs nothing but the target.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace raygate::fuzz {

struct MutationRun {
  std::uint64_t executions = 0;
  double seconds = 0.0;
};

// Runs `target` on mutations of `corpus` (not empty) for `seconds`, seeded by `seed`. An input
// that crashes, aborts (an escaping exception ends in std::terminate) or runs past
// `timeout_seconds` is written to `<findings>/crash-<pid>` before the process dies, and the
// process then dies as it would have.
MutationRun mutate_for(int (*target)(const std::uint8_t*, std::size_t),
                       const std::vector<std::string>& corpus, double seconds, std::uint64_t seed,
                       const std::filesystem::path& findings, unsigned timeout_seconds);

}  // namespace raygate::fuzz
