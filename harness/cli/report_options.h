// The reports a measuring command writes when it ends: the console table on standard error
// (colour on a terminal; none with --quiet) and the reports the user asked for: `--format FORMAT`
// on standard output, `--report FORMAT:PATH` in files or on standard output (PATH -) (markdown
// for a PR comment or $GITHUB_STEP_SUMMARY, junit, json, html). Shared by run, compare, merge.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "cli/console.h"
#include "cli/output_failures.h"
#include "cli/store_options.h"
#include "gate/policy.h"
#include "gate/verdict.h"
#include "report/reporter.h"
#include "results/results.h"

namespace raygate::cli {

// --report FORMAT:PATH (repeatable) and --format FORMAT (the same as --report FORMAT:-).
void add_report_options(CLI::App& command, std::vector<std::string>& reports);

// Throws UsageError for a spec that is not FORMAT:PATH with a known format, or whose PATH cannot
// be written (check_output_path). Check the specs before measuring so a typo does not cost a
// whole run.
void check_report_specs(const std::vector<std::string>& reports);

// Throws UsageError, naming `option`, when a file could not be written at `path` the way
// documents and reports are (a temporary file beside it renamed over it, missing folders
// created): it is a directory or something else that is not a regular file (/dev/full), or the
// nearest existing folder above it is not a folder or is not writable. An empty path (the
// default place) passes.
void check_output_path(const std::filesystem::path& path, const std::string& option);

// The end of every command that writes a document (run, compare, merge), in the order that
// keeps the most when a disk is full: the document's file was written (or failed: `failures`
// already holds that), then the document is recorded in the store (store_options.h), gated by
// `policy`, and reported, each report tried even when one before it failed. Says where the
// document is and, when an output failed, which (cli/output_failures.h); returns the exit code:
// the gate's, or 3 when an output could not be written and the gate found no regression.
int record_gate_and_report(const ResultsDocument& document, const std::filesystem::path& path,
                           const RecordArgs& record, const std::filesystem::path& cache_dir,
                           const GatePolicy& policy, const std::vector<std::string>& reports,
                           const Console& console, OutputFailures& failures);

// The console table on standard error (unless --quiet), then each report of `reports`; a
// report that cannot be written is recorded in `failures` and the next one is still written.
void emit_reports(const ResultsDocument& document, const GateResult& gate,
                  const GatePolicy& policy, const std::vector<std::string>& reports,
                  const std::filesystem::path& document_path, const Console& console,
                  OutputFailures& failures, std::vector<TrendSeries> trends = {});

}  // namespace raygate::cli
