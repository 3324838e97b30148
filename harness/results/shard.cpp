#include "results/shard.h"

#include <fmt/core.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numeric>
#include <utility>

#include "core/error.h"
#include "core/format.h"

namespace raygate {

namespace {

// A whole decimal number, nothing around it; nullopt otherwise.
std::optional<int> whole_number(std::string_view text) {
  int value = 0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (text.empty() || error != std::errc() || stop != end) return std::nullopt;
  return value;
}

long long to_milliseconds(double seconds) {
  if (!std::isfinite(seconds)) return 1;
  return std::max(1LL, std::llround(seconds * 1000.0));
}

double median_of(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2.0;
}

}  // namespace

ShardSpec parse_shard(const std::string& text) {
  const std::size_t slash = text.find('/');
  const auto bad = [&](const std::string& why) {
    return UsageError(
        fmt::format("--shard '{}': {}; give K/N with 1 <= K <= N, e.g. --shard 2/4 "
                    "for the second of four jobs",
                    text, why));
  };
  if (slash == std::string::npos) throw bad("not of the form K/N");
  const std::optional<int> index = whole_number(std::string_view(text).substr(0, slash));
  const std::optional<int> count = whole_number(std::string_view(text).substr(slash + 1));
  if (!index || !count) throw bad("K and N must be whole numbers");
  if (*count < 1) throw bad("N must be at least 1");
  if (*index < 1 || *index > *count) throw bad(fmt::format("K must be between 1 and {}", *count));
  return {*index, *count};
}

std::string to_string(const ShardSpec& shard) {
  return fmt::format("{}/{}", shard.index, shard.count);
}

std::vector<int> assign_shards(std::span<const long long> expected_milliseconds, int count) {
  std::vector<std::size_t> order(expected_milliseconds.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return expected_milliseconds[a] > expected_milliseconds[b];
  });
  // Integer sums: the same partition on every machine, whatever its floating point does.
  std::vector<long long> load(static_cast<std::size_t>(std::max(count, 1)), 0);
  std::vector<int> shard_of(expected_milliseconds.size(), 1);
  for (const std::size_t scene : order) {
    const auto lightest = std::min_element(load.begin(), load.end());  // first of equals
    *lightest += expected_milliseconds[scene];
    shard_of[scene] = static_cast<int>(lightest - load.begin()) + 1;
  }
  return shard_of;
}

std::vector<SuiteScene> shard_scenes(const std::vector<SuiteScene>& scenes, const ShardSpec& spec,
                                     const std::map<std::string, double>& expected_seconds) {
  if (std::cmp_greater(spec.count, scenes.size())) {
    throw UsageError(fmt::format(
        "--shard {}: the selection has only {}, so some shards "
        "would measure nothing; use at most {}",
        to_string(spec), count_text(scenes.size(), "scene"), count_text(scenes.size(), "shard")));
  }
  std::vector<double> known;
  for (const SuiteScene& scene : scenes) {
    if (const auto found = expected_seconds.find(scene.id); found != expected_seconds.end()) {
      known.push_back(found->second);
    }
  }
  const double unknown_seconds = known.empty() ? 1.0 : median_of(known);
  std::vector<long long> costs;
  for (const SuiteScene& scene : scenes) {
    const auto found = expected_seconds.find(scene.id);
    costs.push_back(
        to_milliseconds(found == expected_seconds.end() ? unknown_seconds : found->second));
  }
  const std::vector<int> shard_of = assign_shards(costs, spec.count);
  std::vector<SuiteScene> selected;
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    if (shard_of[i] == spec.index) selected.push_back(scenes[i]);
  }
  return selected;
}

std::map<std::string, double> expected_seconds_from(const ResultsDocument& document) {
  std::map<std::string, double> seconds;
  for (const SceneResult& scene : document.scenes) {
    if (scene.status == SceneStatus::measured && std::isfinite(scene.runs.seconds_spent) &&
        scene.runs.seconds_spent > 0.0) {
      seconds[scene.entry.id] = scene.runs.seconds_spent;
    }
  }
  return seconds;
}

}  // namespace raygate
