// The pipeline's far end (DESIGN.md §2): a finished results document recorded in the store,
// gated, given its trends from the store, and reported, in the order that keeps the most when a
// disk is full. run, compare and merge end here, scaling's reports too; a front end only says
// where things go (PublishRequest) and passes a sink for what publishing says, so a test runs
// compare -> gate -> report without the command line.
#pragma once

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "core/message_sink.h"
#include "gate/policy.h"
#include "gate/verdict.h"
#include "pipeline/output_failures.h"
#include "report/reporter.h"
#include "results/results.h"

namespace raygate {

// What publishing says while it works (the command line's Console says it on standard error).
using PublishSink = MessageSink;

struct PublishRequest {
  std::filesystem::path document_path;  // where the document was written (or was to be)
  std::filesystem::path store;          // the store it is recorded in; "" = not recorded
  std::string branch;                   // recorded when the revision names no branch (--branch)
  GatePolicy policy;
  std::vector<ReportTarget> reports;
  // The console table for whoever watches (standard error), or nullptr (--quiet).
  std::ostream* table = nullptr;
  bool table_colour = false;
  bool report_colour = false;  // for reports on standard output
};

// --report FORMAT:PATH specs as targets; UsageError for a spec that is not FORMAT:PATH with a
// known format, or whose PATH cannot be written (check_output_path). Called before measuring.
std::vector<ReportTarget> parse_report_targets(const std::vector<std::string>& specs);

// The same targets, their paths not checked again: once measured, a place that can no longer
// be written (its folder removed mid-run) is a failed output (exit 3), not a usage error.
std::vector<ReportTarget> report_targets_unchecked(const std::vector<std::string>& specs);

// Records `document` in request.store (complete or not: the store keeps the flag) and says
// where. A store that cannot be written is a problem said, not a failure of the measurement:
// the document file stays, and the message says how to import it later.
void record_document(const ResultsDocument& document, const PublishRequest& request,
                     const PublishSink& sink);

// Says where the document is (unless its write failed: `failures` holds that), records it,
// gates it by request.policy, reads its trends, and writes every report, each tried even when
// one before it failed. Returns the exit code: the gate's, or 3 when an output could not be
// written and the gate found no regression; says that summary when an output failed.
int publish(const ResultsDocument& document, const PublishRequest& request, const PublishSink& sink,
            OutputFailures& failures);

// The console table (request.table), then each report; a report that cannot be written is
// recorded in `failures` and the next one is still written.
void publish_reports(const ResultsDocument& document, const GateResult& gate,
                     const PublishRequest& request, const PublishSink& sink,
                     OutputFailures& failures, std::vector<TrendSeries> trends = {});

}  // namespace raygate
