// Fuzz target: the adapter reader (harness/adapter) on any bytes. Bad input is a UsageError naming
// where; an adapter it accepts must hash (the build cache's key) without throwing.
#include <cstddef>
#include <cstdint>

#include "adapter/adapter.h"
#include "core/error.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const raygate::Adapter adapter =
        raygate::parse_adapter(raygate::fuzz::as_text(data, size), "fuzz-adapter.json");
    static_cast<void>(raygate::adapter_hash(adapter));
  } catch (const raygate::UsageError&) {
  }
  return 0;
}
