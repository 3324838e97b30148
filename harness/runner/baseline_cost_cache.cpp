#include "runner/baseline_cost_cache.h"

#include <fmt/core.h>

#include "core/fs.h"
#include "core/sha256.h"

namespace raygate {

std::string BaselineCostKey::id() const {
  // The weights are in the key: a changed model must not read costs computed by the old one.
  const std::string text = fmt::format(
      "baseline={}\nvalgrind={}\nscene={}\nsampling={}\naccel={}\nmodel=Ir+{}*L1+{}*LL\n",
      baseline_source_sha256, valgrind_version, scene_sha256, sampling, accel, kL1MissCycles,
      kLastLevelMissCycles);
  return sha256_hex(text).substr(0, 32);
}

std::filesystem::path BaselineCostCache::file(const BaselineCostKey& key) const {
  return dir_ / (key.id() + ".json");
}

std::optional<SimulatedCounters> BaselineCostCache::find(const BaselineCostKey& key) const {
  const std::filesystem::path path = file(key);
  std::error_code error;
  if (!std::filesystem::exists(path, error)) return std::nullopt;
  try {
    return nlohmann::json::parse(read_file(path)).at("counters").get<SimulatedCounters>();
  } catch (const std::exception&) {
    return std::nullopt;  // a damaged entry costs one simulation, never a wrong number
  }
}

bool BaselineCostCache::observe(const BaselineCostKey& key, const SimulatedCounters& counters) {
  const std::string id = key.id();
  const auto seen = first_seen_.find(id);
  if (seen == first_seen_.end()) {
    first_seen_.emplace(id, counters);
    return false;
  }
  if (!seen->second || !(*seen->second == counters)) {
    seen->second.reset();
    return false;
  }
  const nlohmann::json document = {{"baseline_source_sha256", key.baseline_source_sha256},
                                   {"valgrind_version", key.valgrind_version},
                                   {"scene_sha256", key.scene_sha256},
                                   {"sampling", key.sampling},
                                   {"accel", key.accel},
                                   {"counters", counters}};
  write_file_atomically(file(key), document.dump(2) + "\n");
  return true;
}

}  // namespace raygate
