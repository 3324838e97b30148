#include "results/merge.h"

#include <fmt/core.h>
#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <utility>

#include "core/error.h"
#include "core/path_component.h"
#include "results/scores.h"
#include "results/settings_json.h"
#include "results/shard.h"

namespace raygate {

namespace {

using nlohmann::json;

// Settings that name places on the runner that wrote the document (or the shard itself), not
// how it measured.
bool per_runner_setting(const std::string& key) {
  return key == "shard" || key == "golden_dir" || key == "policy_file";
}

struct Shard {
  const MergeInput* input = nullptr;
  ShardRecord record;
};

const std::string& origin(const Shard& shard) { return shard.input->origin; }
const ResultsDocument& doc(const Shard& shard) { return shard.input->document; }

// The merged document's names later become paths (golden bless --from-run, run folders), so a
// crafted shard cannot smuggle one in: each is checked as a path component, naming the field.
void check_names(const MergeInput& input) {
  const ResultsDocument& d = input.document;
  const std::string at = "merge: " + input.origin + ": ";
  checked_component(d.suite, at + "suite");
  for (std::size_t i = 0; i < d.scenes.size(); ++i) {
    checked_component(d.scenes[i].entry.id, at + "scenes[" + std::to_string(i) + "].entry.id");
  }
  for (std::size_t i = 0; i < d.revisions.size(); ++i) {
    checked_component(d.revisions[i].adapter_name,
                      at + "revisions[" + std::to_string(i) + "].adapter.name");
  }
}

// The top-level "shard" label must say what settings.shard records: a label that disagrees
// (or is not K/N at all) means the document was edited, and would be carried into reports.
void check_shard_label(const MergeInput& input, const ShardRecord& record) {
  const std::string& label = input.document.shard;
  const bool recorded = input.document.settings.shard.has_value();
  if (!recorded || label.empty() || label == to_string(record.spec)) return;
  throw UsageError(fmt::format("merge: {}: shard '{}' disagrees with settings.shard ({})",
                               input.origin, label, to_string(record.spec)));
}

// settings.shard, or for a document that only has the top-level "K/N", that.
ShardRecord shard_record(const MergeInput& input) {
  check_names(input);
  if (const std::optional<ShardRecord>& record = input.document.settings.shard) {
    for (std::size_t i = 0; i < record->suite_scenes.size(); ++i) {
      checked_component(record->suite_scenes[i], "merge: " + input.origin +
                                                     ": settings.shard.suite_scenes[" +
                                                     std::to_string(i) + "]");
    }
    return *record;
  }
  if (!input.document.shard.empty()) {
    ShardRecord record;
    record.spec = parse_shard(input.document.shard);
    return record;
  }
  throw UsageError(
      fmt::format("merge: {} records no shard (settings.shard): merge combines the "
                  "documents of jobs run with --shard K/N",
                  input.origin));
}

void same(const Shard& a, const Shard& b, const std::string& field, const std::string& value_a,
          const std::string& value_b) {
  if (value_a == value_b) return;
  throw UsageError(
      fmt::format("merge: {} and {} differ in {} ('{}' vs '{}'): the shards of one "
                  "matrix must measure the same thing the same way",
                  origin(a), origin(b), field, value_a, value_b));
}

void check_header(const Shard& a, const Shard& b) {
  same(a, b, "schema_version", std::to_string(doc(a).schema_version),
       std::to_string(doc(b).schema_version));
  same(a, b, "kind", std::string(to_string(doc(a).kind)), std::string(to_string(doc(b).kind)));
  same(a, b, "suite", doc(a).suite, doc(b).suite);
  const BaselineRecord& x = doc(a).baseline;
  const BaselineRecord& y = doc(b).baseline;
  same(a, b, "baseline.version", x.version, y.version);
  same(a, b, "baseline.source_sha256", x.source_sha256, y.source_sha256);
  same(a, b, "baseline.accel", x.accel, y.accel);
  same(a, b, "baseline.sampling", x.sampling, y.sampling);
  same(a, b, "baseline.timing", x.timing, y.timing);
}

// "base,head": a document's roles as the message names them.
std::string role_list(const ResultsDocument& document) {
  std::vector<std::string_view> words;
  for (const Role role : scored_roles(document)) words.push_back(to_string(role));
  return fmt::format("{}", fmt::join(words, ","));
}

void check_revisions(const Shard& a, const Shard& b) {
  same(a, b, "revisions (roles)", role_list(doc(a)), role_list(doc(b)));
  for (std::size_t i = 0; i < doc(a).revisions.size(); ++i) {
    const RevisionRecord& x = doc(a).revisions[i];
    const RevisionRecord& y = doc(b).revisions[i];
    const std::string at = "revisions[" + role_name(x.role) + "]";
    same(a, b, at + ".worktree.sha", x.worktree.sha, y.worktree.sha);
    same(a, b, at + ".worktree.dirty", x.worktree.dirty ? "true" : "false",
         y.worktree.dirty ? "true" : "false");
    same(a, b, at + ".adapter.hash", x.adapter_hash, y.adapter_hash);
  }
}

// Every setting by the name the document gives it, known to this raygate or not, in the words
// the document has them (results/settings_json.h), so the message quotes what the files say.
void check_settings(const Shard& a, const Shard& b) {
  const json x = to_json(doc(a).settings);
  const json y = to_json(doc(b).settings);
  std::set<std::string> keys;
  for (const json* settings : {&x, &y}) {
    for (const auto& item : settings->items()) keys.insert(item.key());
  }
  for (const std::string& key : keys) {
    if (per_runner_setting(key)) continue;
    const json value_x = x.contains(key) ? x.at(key) : json();
    const json value_y = y.contains(key) ? y.at(key) : json();
    same(a, b, "settings." + key, value_x.dump(), value_y.dump());
  }
}

void check_shard_records(const Shard& a, const Shard& b) {
  same(a, b, "shard count (settings.shard.count)", std::to_string(a.record.spec.count),
       std::to_string(b.record.spec.count));
  same(a, b, "the suite's selected scenes (settings.shard.suite_scenes)",
       fmt::format("{}", fmt::join(a.record.suite_scenes, ",")),
       fmt::format("{}", fmt::join(b.record.suite_scenes, ",")));
  same(a, b, "settings.shard.cost_basis", a.record.cost_basis, b.record.cost_basis);
  if (!a.record.suite_sha256.empty() && !b.record.suite_sha256.empty()) {
    same(a, b, "the suite's scenes, sizes and resolutions (settings.shard.suite_sha256)",
         a.record.suite_sha256, b.record.suite_sha256);
  }
  if (a.record.spec.index == b.record.spec.index) {
    throw UsageError(
        fmt::format("merge: {} and {} are both shard {} (settings.shard.index): "
                    "give each shard's document once",
                    origin(a), origin(b), to_string(a.record.spec)));
  }
}

std::vector<Shard> checked_shards(const std::vector<MergeInput>& inputs) {
  if (inputs.empty()) throw UsageError("merge: no documents given");
  std::vector<Shard> shards;
  for (const MergeInput& input : inputs) shards.push_back({&input, shard_record(input)});
  std::stable_sort(shards.begin(), shards.end(), [](const Shard& x, const Shard& y) {
    return x.record.spec.index < y.record.spec.index;
  });
  for (std::size_t i = 1; i < shards.size(); ++i) {
    check_header(shards.front(), shards[i]);
    check_revisions(shards.front(), shards[i]);
    check_shard_records(shards.front(), shards[i]);
    check_shard_records(shards[i - 1], shards[i]);  // equal indices sort next to each other
    check_settings(shards.front(), shards[i]);
  }
  for (const Shard& shard : shards) check_shard_label(*shard.input, shard.record);
  return shards;
}

// With equal costs the split is known from the selection alone (round-robin in suite order): a
// scene in a shard the split did not give it is a shard index edited by hand, and merged silently
// before (two shards' documents with their indexes swapped). Split by another document's times,
// the costs are not recorded, so only overlaps and gaps are found.
void check_split(const Shard& shard, std::size_t position) {
  const ShardRecord& record = shard.record;
  if (record.cost_basis != "equal") return;
  const std::vector<long long> equal(record.suite_scenes.size(), 1);
  const std::vector<int> split = assign_shards(equal, record.spec.count);
  if (position >= split.size() || split[position] == record.spec.index) return;
  throw UsageError(
      fmt::format("merge: {}: scene '{}' belongs to shard {}/{} of the split, not to {} "
                  "(settings.shard.index edited?)",
                  origin(shard), record.suite_scenes[position], split[position], record.spec.count,
                  to_string(record.spec)));
}

// Scenes of every shard, each once, in suite order (shard order where a document has no list).
std::vector<SceneResult> collect_scenes(const std::vector<Shard>& shards) {
  const std::vector<std::string>& suite = shards.front().record.suite_scenes;
  std::map<std::string, const Shard*> owner;
  std::vector<std::pair<std::size_t, const SceneResult*>> positioned;
  for (const Shard& shard : shards) {
    for (const SceneResult& scene : doc(shard).scenes) {
      const std::string& id = scene.entry.id;
      const auto at = std::find(suite.begin(), suite.end(), id);
      if (!suite.empty() && at == suite.end()) {
        throw UsageError(
            fmt::format("merge: {} has scene '{}', which is not in the selection "
                        "its shard was split from (settings.shard.suite_scenes)",
                        origin(shard), id));
      }
      if (const auto [it, fresh] = owner.emplace(id, &shard); !fresh) {
        throw UsageError(
            fmt::format("merge: scene '{}' is in both {} and {}: the shards "
                        "overlap; were they split from different selections?",
                        id, origin(*it->second), origin(shard)));
      }
      if (!suite.empty()) check_split(shard, static_cast<std::size_t>(at - suite.begin()));
      positioned.emplace_back(suite.empty() ? positioned.size() : std::size_t(at - suite.begin()),
                              &scene);
    }
  }
  std::stable_sort(positioned.begin(), positioned.end(),
                   [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<SceneResult> scenes;
  for (const auto& [position, scene] : positioned) scenes.push_back(*scene);
  return scenes;
}

// Shards not given, as "K/N" texts.
std::vector<std::string> missing_shards(const std::vector<Shard>& shards) {
  std::set<int> given;
  for (const Shard& shard : shards) given.insert(shard.record.spec.index);
  std::vector<std::string> missing;
  const int count = shards.front().record.spec.count;
  for (int index = 1; index <= count; ++index) {
    if (!given.contains(index)) missing.push_back(to_string(ShardSpec{index, count}));
  }
  return missing;
}

std::vector<std::string> unmeasured_scenes(const std::vector<Shard>& shards,
                                           const std::vector<SceneResult>& scenes) {
  std::vector<std::string> missing;
  for (const std::string& id : shards.front().record.suite_scenes) {
    const bool found = std::any_of(scenes.begin(), scenes.end(),
                                   [&](const SceneResult& s) { return s.entry.id == id; });
    if (!found) missing.push_back(id);
  }
  return missing;
}

MergedShard shard_summary(const Shard& shard) {
  const ResultsDocument& d = doc(shard);
  MergedShard summary{shard.record.spec,
                      origin(shard),
                      d.raygate_version,
                      d.started_at,
                      d.finished_at,
                      d.complete,
                      {},
                      d.machine};
  for (const SceneResult& scene : d.scenes) summary.scenes.push_back(scene.entry.id);
  return summary;
}

// The header of the first shard, times spanning all shards, and every shard's own record.
ResultsDocument merged_header(const std::vector<Shard>& shards) {
  ResultsDocument merged = doc(shards.front());
  merged.scenes.clear();
  merged.shard.clear();
  merged.complete = true;
  std::vector<MergedShard> summaries;
  for (const Shard& shard : shards) {
    const ResultsDocument& d = doc(shard);
    merged.started_at = std::min(merged.started_at, d.started_at);
    merged.finished_at = merged.finished_at.empty() || d.finished_at.empty()
                             ? std::string()
                             : std::max(merged.finished_at, d.finished_at);
    merged.complete = merged.complete && d.complete;
    summaries.push_back(shard_summary(shard));
  }
  merged.settings.shard.reset();
  merged.settings.merged_shards = std::move(summaries);
  return merged;
}

}  // namespace

MergeResult merge_shards(const std::vector<MergeInput>& inputs, const MergeOptions& options) {
  const std::vector<Shard> shards = checked_shards(inputs);
  MergeResult result;
  const std::vector<std::string> missing = missing_shards(shards);
  if (!missing.empty()) {
    const std::string which = fmt::format("{}", fmt::join(missing, ", "));
    if (!options.allow_partial) {
      throw UsageError(
          fmt::format("merge: shard {} missing: give every shard's document, or "
                      "--allow-partial to merge what there is (the result is "
                      "incomplete and the gate exits 3)",
                      which));
    }
    result.warnings.push_back("shard " + which + " missing: the merged document is incomplete");
  }
  for (const Shard& shard : shards) {
    if (doc(shard).raygate_version != doc(shards.front()).raygate_version) {
      result.warnings.push_back(fmt::format("{} was written by raygate {}, {} by {}", origin(shard),
                                            doc(shard).raygate_version, origin(shards.front()),
                                            doc(shards.front()).raygate_version));
    }
  }
  result.document = merged_header(shards);
  result.document.scenes = collect_scenes(shards);
  const std::vector<std::string> unmeasured = unmeasured_scenes(shards, result.document.scenes);
  if (!unmeasured.empty()) {
    result.document.complete = false;
    result.warnings.push_back(
        fmt::format("not measured by any shard given: {}", fmt::join(unmeasured, ", ")));
  }
  if (!missing.empty()) result.document.complete = false;
  result.document.scores = suite_scores(result.document.scenes, scored_roles(result.document));
  return result;
}

}  // namespace raygate
