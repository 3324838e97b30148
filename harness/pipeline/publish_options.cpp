#include "pipeline/publish_options.h"

#include <fmt/core.h>

#include <iostream>

#include "core/error.h"
#include "pipeline/output_failures.h"
#include "store/postgres_url.h"

namespace raygate {

void check_publish_targets(const PublishOptions& options, const std::string& output,
                           const std::string& option, const std::vector<NamedFile>& inputs) {
  const std::vector<ReportTarget> reports = parse_report_targets(options.reports);
  // "-" is standard output to report's -o; here it made a file named "-".
  if (output == "-") {
    throw UsageError(option +
                     " -: the results document is a file; for it on standard output, "
                     "--format json");
  }
  check_output_path(output, option);
  // A malformed URL is the user's mistake, found before measuring (exit 2, as import says it);
  // a well-formed one whose server cannot be reached is only a warning after measuring.
  const bool url = is_postgresql_url(options.store);
  if (!options.no_store && url) parse_postgresql_url(options.store);
  std::vector<NamedFile> files = inputs;
  files.push_back({option, output});
  std::vector<std::string> on_standard_output;
  for (std::size_t i = 0; i < reports.size(); ++i) {
    files.push_back({"--report " + options.reports[i], reports[i].path});
    if (reports[i].path == "-") on_standard_output.push_back(options.reports[i]);
  }
  // Two documents back to back on standard output are neither one: no reader takes them apart.
  if (on_standard_output.size() > 1) {
    throw UsageError(
        fmt::format("{} and {} both go to standard output (--format F, --report "
                    "F:-); write one of them to a file: --report FORMAT:PATH",
                    on_standard_output[0], on_standard_output[1]));
  }
  if (!options.no_store && !url) files.push_back({"--store", options.store});
  check_distinct_files(files);
}

PublishRequest publish_request(const PublishOptions& options,
                               const std::filesystem::path& document_path,
                               const std::filesystem::path& cache_dir, const GatePolicy& policy,
                               const Console& console) {
  PublishRequest request;
  request.document_path = document_path;
  if (!options.no_store) {
    request.store =
        options.store.empty() ? cache_dir / "results.db" : std::filesystem::path(options.store);
  }
  request.branch = options.branch;
  request.policy = policy;
  request.reports = report_targets_unchecked(options.reports);  // checked before measuring
  if (!console.quiet()) request.table = &std::cerr;             // chatter: standard error
  request.table_colour = console.colour(stderr);
  request.report_colour = console.colour(stdout);
  return request;
}

int publish_measured(const MeasuredDocument& measured, const PublishOptions& options,
                     const std::filesystem::path& cache_dir, const GatePolicy& policy,
                     const Console& console) {
  OutputFailures failures;
  for (const FailedWrite& failed : measured.unwritten) failures.add("the results document", failed);
  return publish(measured.document,
                 publish_request(options, measured.path, cache_dir, policy, console), console,
                 failures);
}

int merge_and_publish(MergeRequest request, const PublishOptions& options,
                      const std::filesystem::path& cache_dir, const Console& console) {
  if (request.out.empty()) throw UsageError("merge: --output is required (the merged document)");
  std::vector<NamedFile> shards;
  for (const std::string& shard : request.documents)
    shards.push_back({"the shard " + shard, shard, true});
  shards.push_back({"--policy", request.policy, true});
  check_publish_targets(options, request.out, "--output", shards);
  request.out = std::filesystem::absolute(request.out).string();
  OutputFailures failures;
  const MergedShards merged = merge_shard_documents(request, console, failures);
  return publish(merged.document,
                 publish_request(options, request.out, std::filesystem::absolute(cache_dir),
                                 merged.policy, console),
                 console, failures);
}

}  // namespace raygate
