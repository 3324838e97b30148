// Fuzz target: the results-document reader (core/json_reader + results/results_check) on any
// bytes: a document or a UsageError. A document it accepts must write and read back to the same
// JSON: what the check lets through, the writer must be able to keep.
#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "core/error.h"
#include "core/json_reader.h"
#include "fuzz_input.h"
#include "results/results.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  raygate::ResultsDocument document;
  try {
    const nlohmann::json json =
        raygate::parse_json_input(raygate::fuzz::as_text(data, size), "fuzz-results.json");
    document = raygate::results_from_json(json, "fuzz-results.json");
  } catch (const raygate::UsageError&) {
    return 0;
  }
  const std::string written = raygate::to_json(document).dump();
  const raygate::ResultsDocument again =
      raygate::results_from_json(raygate::parse_json_input(written, "written"), "written");
  if (raygate::to_json(again).dump() != written) std::abort();  // not kept as it was read
  return 0;
}
