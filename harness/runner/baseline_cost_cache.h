// The baseline's simulated cost, kept between jobs (--timing sim, docs/simulated-timing.md).
// raygate-baseline is deterministic, so under cachegrind its cost on a scene is a constant of
// (its source, the valgrind that counted it, the scene file, sampling, acceleration): a CI job
// that already knows it does not simulate the baseline again. A cost is only kept once two runs
// agreed exactly, so a cached number is one that was checked, not assumed, to be deterministic.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include "measure/simulated_cost.h"

namespace raygate {

struct BaselineCostKey {
  std::string baseline_source_sha256;
  std::string valgrind_version;
  std::string scene_sha256;  // the NFF file: scene, size and resolution
  std::string sampling;
  std::string accel;

  // 32 hex digits of the SHA-256 of every part (and the cost model's weights): the file name.
  std::string id() const;
};

class BaselineCostCache {
 public:
  // Files live in `dir` (usually <cache-dir>/simulated-baseline), one JSON document per key.
  explicit BaselineCostCache(std::filesystem::path dir) : dir_(std::move(dir)) {}

  // The cached counters; nullopt when unknown, or when the file is unreadable (then the
  // baseline is simply simulated again and the file rewritten).
  std::optional<SimulatedCounters> find(const BaselineCostKey& key) const;

  // A simulated run's counters. The first one per key is remembered; a later one equal to it is
  // written to the cache (true), a different one makes the key uncacheable for this process.
  bool observe(const BaselineCostKey& key, const SimulatedCounters& counters);

  const std::filesystem::path& dir() const { return dir_; }

 private:
  std::filesystem::path file(const BaselineCostKey& key) const;

  std::filesystem::path dir_;
  std::map<std::string, std::optional<SimulatedCounters>> first_seen_;  // nullopt: they differed
};

}  // namespace raygate
