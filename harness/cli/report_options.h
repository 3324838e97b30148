// The options of the commands that publish a results document (run, compare, merge, scaling):
// `--format FORMAT` on standard output, `--report FORMAT:PATH` in files or on standard output
// (PATH -), and the request pipeline/publish.h carries out from them, the console table on
// standard error (colour on a terminal; none with --quiet).
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "cli/console.h"
#include "cli/store_options.h"
#include "gate/policy.h"
#include "pipeline/publish.h"
#include "pipeline/suite_measurement.h"

namespace raygate::cli {

// --report FORMAT:PATH (repeatable) and --format FORMAT (the same as --report FORMAT:-).
void add_report_options(CLI::App& command, std::vector<std::string>& reports);

// -o/--output (with the deprecated --out) for the document, --store, --no-store, --branch, and
// --report/--format: what every command that publishes a document takes.
void add_publish_options(CLI::App& command, std::string& output, const std::string& output_help,
                         RecordArgs& record, std::vector<std::string>& reports);

// Where the document, its record and its reports go, as the options and the console say. The
// store is --store, else <cache_dir>/results.db, none with --no-store. UsageError for a bad
// report spec (pipeline/publish.h, parse_report_targets).
PublishRequest publish_request(const std::filesystem::path& document_path,
                               const RecordArgs& record, const std::filesystem::path& cache_dir,
                               const GatePolicy& policy, const std::vector<std::string>& reports,
                               const Console& console);

// The end of run and compare: the measured document's failed writes counted, then publish()
// with the request above; returns the exit code.
int publish_measured(const MeasuredDocument& measured, const RecordArgs& record,
                     const std::filesystem::path& cache_dir, const GatePolicy& policy,
                     const std::vector<std::string>& reports, const Console& console);

}  // namespace raygate::cli
