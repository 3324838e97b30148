// What a results document records about the shard of a CI matrix it measured (`settings.shard`):
// the split itself, apart from how a suite is split (results/shard.h), so the document's settings
// can hold it without the splitting code.
#pragma once

#include <string>
#include <vector>

namespace raygate {

struct ShardSpec {
  int index = 1;  // 1-based: 1 <= index <= count
  int count = 1;

  bool operator==(const ShardSpec&) const = default;
};

// What a shard's document records under settings.shard.
struct ShardRecord {
  ShardSpec spec;
  std::vector<std::string> suite_scenes;  // every selected scene of the suite, in suite order
  std::string cost_basis = "equal";       // "equal", or which document's times were the costs
  // The selected scenes' content (id, generator, size, resolution, sampling), hashed: shards of
  // one suite name with other sizes must not merge (sweep 13). "" in documents before it.
  std::string suite_sha256;

  bool operator==(const ShardRecord&) const = default;
};

}  // namespace raygate
