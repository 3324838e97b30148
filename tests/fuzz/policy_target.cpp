// Fuzz target: the gate policy reader (harness/gate/policy) on any bytes: a policy or a
// UsageError, nothing else.
#include <cstddef>
#include <cstdint>

#include "core/error.h"
#include "fuzz_input.h"
#include "gate/policy.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    static_cast<void>(
        raygate::parse_policy(raygate::fuzz::as_text(data, size), "fuzz-policy.json"));
  } catch (const raygate::UsageError&) {
  }
  return 0;
}
