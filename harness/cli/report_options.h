// The options of the commands that publish a results document (run, compare, merge, scaling):
// `--format FORMAT` on standard output, `--report FORMAT:PATH` in files or on standard output
// (PATH -), bound into the pipeline's PublishOptions (pipeline/publish_options.h makes the
// request pipeline/publish.h carries out from them).
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "cli/store_options.h"
#include "pipeline/publish_options.h"

namespace raygate::cli {

// --report FORMAT:PATH (repeatable) and --format FORMAT (the same as --report FORMAT:-).
void add_report_options(CLI::App& command, std::vector<std::string>& reports);

// -o/--output (with the deprecated --out) for the document, --store, --no-store, --branch, and
// --report/--format: what every command that publishes a document takes.
void add_publish_options(CLI::App& command, std::string& output, const std::string& output_help,
                         PublishOptions& options);

}  // namespace raygate::cli
