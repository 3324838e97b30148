#include "pipeline/publish.h"

#include <fmt/core.h>

#include <cerrno>
#include <cstdio>
#include <iostream>

#include "core/error.h"
#include "history/store_trends.h"
#include "store/postgres_url.h"
#include "store/store.h"

namespace raygate {

std::vector<ReportTarget> report_targets_unchecked(const std::vector<std::string>& specs) {
  std::vector<ReportTarget> targets;
  for (const std::string& spec : specs) {
    const std::size_t colon = spec.find(':');
    if (colon == std::string::npos || colon + 1 == spec.size()) {
      throw UsageError(
          fmt::format("--report {}: expected FORMAT:PATH, e.g. html:report.html", spec));
    }
    targets.push_back({parse_report_format(spec.substr(0, colon)), spec.substr(colon + 1)});
  }
  return targets;
}

std::vector<ReportTarget> parse_report_targets(const std::vector<std::string>& specs) {
  std::vector<ReportTarget> targets = report_targets_unchecked(specs);
  for (const ReportTarget& target : targets) {
    if (target.path != "-") check_output_path(target.path, "--report " + target.path.string());
  }
  return targets;
}

void record_document(const ResultsDocument& document, const PublishRequest& request,
                     const PublishSink& sink) {
  if (request.store.empty()) return;
  const std::string location = request.store.string();
  try {
    const auto store = open_store(location, StoreOpen::create_if_missing);
    const std::string branch = branch_of(document, request.branch);
    const AddOutcome outcome = store->add(document, branch);
    sink.info(fmt::format("{} {} as document {}{}",
                          outcome.duplicate ? "already stored in" : "stored in", store->location(),
                          outcome.document_id, branch.empty() ? "" : " (branch " + branch + ")"));
  } catch (const std::exception& e) {  // raygate's errors and the file system's
    const std::filesystem::path& path = request.document_path;
    std::error_code ignored;
    if (!std::filesystem::is_regular_file(path, ignored)) {
      sink.problem(
          fmt::format("raygate: warning: results not stored: {}\n  and the document is "
                      "in no file; only the reports keep it\n",
                      e.what()));
      return;
    }
    // A URL's password stays out of the message.
    sink.problem(
        fmt::format("raygate: warning: results not stored: {}\n  the document is kept "
                    "at {}; store it later with: raygate import {} --store {}\n",
                    e.what(), path.string(), path.string(), redact_postgresql_url(location)));
  }
}

int publish(const ResultsDocument& document, const PublishRequest& request, const PublishSink& sink,
            OutputFailures& failures) {
  if (!failures.failed(request.document_path)) {
    sink.info(fmt::format("results: {}", request.document_path.string()));
  }
  record_document(document, request, sink);
  const GateResult gate = evaluate_gate(document, request.policy);
  StoreTrends trends = trends_from_store(request.store, document);
  if (!trends.warning.empty()) sink.warning(trends.warning);
  publish_reports(document, gate, request, sink, failures, std::move(trends.trends));
  failures.say_summary(failures.exit_code(gate.exit_code));
  return failures.exit_code(gate.exit_code);
}

void publish_reports(const ResultsDocument& document, const GateResult& gate,
                     const PublishRequest& request, const PublishSink& sink,
                     OutputFailures& failures, std::vector<TrendSeries> trends) {
  // The outputs that failed so far (-o, when it could not be written), and the real exit code.
  ReportInput input{document,
                    gate,
                    request.policy,
                    std::move(trends),
                    request.document_path.parent_path(),
                    failures.summary(),
                    failures.exit_code(gate.exit_code)};
  ReportOptions options;
  options.colour = request.report_colour;
  // Report files first, so the table's closing line knows the real exit code; their "written"
  // lines still follow the table, as before.
  std::vector<std::string> written_lines;
  for (const ReportTarget& target : request.reports) {
    if (target.path == "-") continue;
    const std::string output =
        fmt::format("--report {}:{}", to_string(target.format), target.path.string());
    if (failures.attempt(output, [&] { write_reports(input, {target}, options); })) {
      written_lines.push_back(
          fmt::format("{} report: {}", to_string(target.format), target.path.string()));
    }
  }
  // Standard output first: a full disk behind `> file` is then in the table's last line, whose
  // exit code would otherwise say 0 above a process that exits 3.
  for (const ReportTarget& target : request.reports) {
    if (target.path != "-") continue;
    const std::string output = fmt::format("--report {}:-", to_string(target.format));
    int error_number = 0;  // why standard output failed, before anything else sets errno
    failures.attempt(output, [&] {
      errno = 0;
      write_reports(input, {target}, options);
      error_number = errno;
    });
    check_standard_output(failures, output, error_number);
  }
  if (request.table != nullptr) {
    input.outputs_failed = failures.summary();
    input.exit_code_with_outputs = failures.exit_code(gate.exit_code);
    ReportOptions table;
    table.colour = request.table_colour;
    std::fflush(stderr);  // C stdio chatter before it, when the table goes to std::cerr
    make_reporter(ReportFormat::console, table)->write(input, *request.table);
    request.table->flush();
  }
  for (const std::string& line : written_lines) sink.info(line);
}

}  // namespace raygate
