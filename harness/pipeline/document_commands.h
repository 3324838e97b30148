// Commands over results documents already written, and over the machine, as library calls:
// `raygate scaling` (growth exponents fitted and judged), `raygate consistency` (one tracer's
// ratios across machines) and `raygate doctor` (is this machine fit to measure). A front end
// parses options, calls these and prints what they return.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "consistency/consistency.h"
#include "doctor/doctor_report.h"
#include "gate/verdict.h"
#include "pipeline/output_failures.h"
#include "results/results.h"
#include "scaling/scaling_analysis.h"

namespace raygate {

struct JudgedDocument {
  std::filesystem::path path;  // absolute: reports link its run folder's files
  ResultsDocument document;
  GatePolicy policy;
  GateResult gate;
};

// A results document read and gated (`raygate gate`, `raygate report`) by `policy_file`, else
// by the limits it recorded (`note` then says so): a report and the gate never disagree.
JudgedDocument judge_document(const std::string& results, const std::string& policy_file,
                              bool fail_on_inconclusive, std::string& note);

struct ScalingJudgement {
  ResultsDocument document;  // with its fits attached
  GatePolicy policy;         // the file given, else the limits the document recorded
  ScalingAnalysis analysis;
  GateResult gate;  // the growth exponents judged (families only); exit 1 when one failed
};

// Fits `results` again, writes the fits into it unless `no_write` (a failed write lands in
// `failures`), and judges the exponents. UsageError when no family was measured at 3 sizes.
ScalingJudgement judge_scaling(const std::string& results, const std::string& policy_file,
                               bool no_write, OutputFailures& failures);

// The documents' ratios compared (r² per pair, per-scene deviation). UsageError for fewer
// than 2; InfraError for a document that cannot be read: the command line was right, the file
// was not.
ConsistencyResult check_consistency(const std::vector<std::string>& documents,
                                    const ConsistencyOptions& options);

// The machine's facts and findings, then its noise score measured with `baseline` ("" = beside
// raygate) in `rounds` A/A pairs, or why that could not be done; `status` hears the line said
// before measuring. UsageError for fewer than 2 rounds.
DoctorReport examine_machine(int rounds, const std::string& baseline,
                             const std::function<void(const std::string&)>& status);

}  // namespace raygate
