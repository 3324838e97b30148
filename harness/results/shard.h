// Splitting a suite across the jobs of a CI matrix (`--shard K/N` on run and compare); the record
// of that split in a results document's settings (`settings.shard`, results/shard_record.h) is
// what `raygate merge` checks the shards it combines against. The split is a pure function of the selected
// scenes (in suite order) and their expected costs, computed in integer milliseconds, so every
// job of a matrix gets the same partition whatever machine it runs on (docs/shards.md).
#pragma once

#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "runner/suite.h"
#include "results/results.h"
#include "results/shard_record.h"

namespace raygate {

// "K/N" with 1 <= K <= N; anything else is a UsageError saying what a shard looks like.
ShardSpec parse_shard(const std::string& text);
std::string to_string(const ShardSpec& shard);

// The shard (1-based) of each scene, given expected costs in suite order (milliseconds, >= 1).
// Longest first: scenes in decreasing cost (ties: suite order) each go to the shard with the
// least cost so far (ties: the lowest index). Equal costs make it round-robin in suite order;
// with count <= scenes every shard gets at least one scene.
std::vector<int> assign_shards(std::span<const long long> expected_milliseconds, int count);

// The scenes of `spec` in suite order. `expected_seconds` by scene id (empty: all scenes cost
// the same); a scene it does not name costs the median of those it does. A shard that would be
// empty (more shards than scenes) is a UsageError.
std::vector<SuiteScene> shard_scenes(const std::vector<SuiteScene>& scenes, const ShardSpec& spec,
                                     const std::map<std::string, double>& expected_seconds);

// Expected costs from an earlier results document of the suite: each measured scene's
// seconds_spent (all rounds of all contenders, what a shard's job actually spends).
std::map<std::string, double> expected_seconds_from(const ResultsDocument& document);

}  // namespace raygate
