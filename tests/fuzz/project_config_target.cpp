// Fuzz target: the raygate.toml reader (harness/pipeline/project_config) on any bytes, through
// a file as raygate reads one: defaults or a UsageError, nothing else.
#include <cstddef>
#include <cstdint>

#include "core/error.h"
#include "pipeline/project_config.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path file =
      raygate::fuzz::scratch_file(raygate::fuzz::as_text(data, size), "raygate.toml");
  try {
    static_cast<void>(raygate::read_project_config(file));
  } catch (const raygate::UsageError&) {
  }
  return 0;
}
