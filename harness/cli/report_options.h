// The reports a measuring command writes when it ends: the console table on standard output
// (colour on a terminal) and any `--report FORMAT:PATH` the user asked for (markdown for a PR
// comment or $GITHUB_STEP_SUMMARY, junit, json, html). Shared by run and compare.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "gate/policy.h"
#include "gate/verdict.h"
#include "store/results.h"

namespace raygate::cli {

void add_report_options(CLI::App& command, std::vector<std::string>& reports);

// Throws UsageError for a spec that is not FORMAT:PATH with a known format. Check the specs
// before measuring (parse_report_specs) so a typo does not cost a whole run.
void check_report_specs(const std::vector<std::string>& reports);

void emit_reports(const ResultsDocument& document, const GateResult& gate,
                  const GatePolicy& policy, const std::vector<std::string>& reports,
                  const std::filesystem::path& document_path);

}  // namespace raygate::cli
