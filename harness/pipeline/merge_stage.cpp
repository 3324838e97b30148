#include "pipeline/merge_stage.h"

#include <fmt/core.h>

#include "core/format.h"
#include "core/error.h"
#include "results/merge.h"

namespace raygate {
namespace {

void say_scores(const ResultsDocument& document, const PublishSink& sink) {
  for (const auto& [key, score] : document.scores) {
    const std::string_view role = to_string(key);
    sink.info(
        fmt::format("suite score {} (geometric mean of normalized ratios): {:.3f} "
                    "[{:.3f}, {:.3f}] over {}",
                    role, score.score, score.interval.lower, score.interval.upper,
                    count_text(score.scenes, "scene")));
  }
}

}  // namespace

MergedShards merge_shard_documents(const MergeRequest& request, const PublishSink& sink,
                                   OutputFailures& failures) {
  std::vector<MergeInput> inputs;
  for (const std::string& path : request.documents) inputs.push_back({path, read_results(path)});
  // Without --policy the shards' own limits judge the merge (merge checked that they agree).
  std::string note;
  MergedShards merged;
  merged.policy =
      request.policy.empty() || inputs.empty()
          ? recorded_policy(
                inputs.empty() ? MeasurementSettings{} : inputs.front().document.settings, note)
          : load_policy(request.policy);
  merged.policy.fail_on_inconclusive =
      merged.policy.fail_on_inconclusive || request.fail_on_inconclusive;
  MergeOptions options;
  options.allow_partial = request.allow_partial;
  MergeResult result = merge_shards(inputs, options);
  // Said once the shards are accepted: a policy line above a refusal read as if it had judged.
  if (!note.empty()) sink.info(fmt::format("gate policy: {}", note));
  for (const std::string& warning : result.warnings) sink.warning(warning);
  merged.document = std::move(result.document);
  const ResultsDocument& document = merged.document;
  // A full disk under -o must not lose the merge: the store still gets it, and the reports.
  failures.attempt("the merged document (--output)", [&] { write_results(document, request.out); });
  sink.info(fmt::format("merged {} shard documents of suite {}: {}{}", inputs.size(),
                        document.suite, count_text(document.scenes.size(), "scene"),
                        document.complete ? "" : " (incomplete)"));
  say_scores(document, sink);
  return merged;
}

}  // namespace raygate
