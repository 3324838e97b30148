// Fuzz target: the suite reader (harness/runner/suite) on any bytes, through a file as raygate
// reads one: a suite or a UsageError, nothing else.
#include <cstddef>
#include <cstdint>

#include "core/error.h"
#include "fuzz_input.h"
#include "runner/suite.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path file =
      raygate::fuzz::scratch_file(raygate::fuzz::as_text(data, size), "fuzz-suite.json");
  try {
    const raygate::Suite suite = raygate::load_suite(file.string(), file.parent_path());
    static_cast<void>(raygate::select_scenes(suite, {}));
  } catch (const raygate::UsageError&) {
  }
  return 0;
}
