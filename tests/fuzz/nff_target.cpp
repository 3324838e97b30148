// Fuzz target: the NFF reader (baseline/nff) on any bytes. A malformed scene is a ParseError with
// its line and column; nothing else may escape.
#include <cstddef>
#include <cstdint>

#include "fuzz_input.h"
#include "nff/parser.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const raygate::nff::Scene scene =
        raygate::nff::parse_nff(raygate::fuzz::as_text(data, size), "fuzz.nff");
    static_cast<void>(scene.primitive_count());
  } catch (const raygate::nff::ParseError&) {
  }
  return 0;
}
