// What a front end's options say about publishing a finished document (run, compare, merge,
// scaling): the store and branch it is recorded under, and the reports asked for, turned into
// the PublishRequest pipeline/publish.h carries out. Here rather than in the command line so
// that every front end (and a test) gets the same defaults: the store is <cache-dir>/results.db
// unless named or refused, the console table goes to standard error unless --quiet.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "gate/policy.h"
#include "pipeline/merge_stage.h"
#include "pipeline/publish.h"
#include "pipeline/suite_measurement.h"
#include "report/terminal.h"

namespace raygate {

struct PublishOptions {
  std::string store;  // "" -> <cache-dir>/results.db
  bool no_store = false;
  std::string branch;                // recorded when the revision names no branch
  std::vector<std::string> reports;  // FORMAT:PATH specs; PATH - is standard output
};

// Refuses, before anything is measured, a report spec or an output path (`output`, the
// document's -o; "" for the default) that could not be written: UsageError naming `option`;
// a --store URL that is not a valid PostgreSQL URL (UsageError naming --store); and two of the
// outputs, the store and `inputs` (files the command reads) that are one file.
void check_publish_targets(const PublishOptions& options, const std::string& output,
                           const std::string& option, const std::vector<NamedFile>& inputs = {});

// Where the document at `document_path`, its record and its reports go, as the options and
// the console say: the store is options.store, else <cache_dir>/results.db, none with
// no_store; the console table on standard error (none when quiet), colour as the console
// chooses for each stream. UsageError for a bad report spec.
PublishRequest publish_request(const PublishOptions& options,
                               const std::filesystem::path& document_path,
                               const std::filesystem::path& cache_dir, const GatePolicy& policy,
                               const Console& console);

// The end of run and compare: the measured document's failed writes counted, then publish()
// with the request above; returns the exit code.
int publish_measured(const MeasuredDocument& measured, const PublishOptions& options,
                     const std::filesystem::path& cache_dir, const GatePolicy& policy,
                     const Console& console);

// `raygate merge` from end to end: request.out required and checked (a folder or a device is
// refused before any shard is read), the shards merged into it (pipeline/merge_stage.h), then
// published like a measured document, the default store under `cache_dir`.
int merge_and_publish(MergeRequest request, const PublishOptions& options,
                      const std::filesystem::path& cache_dir, const Console& console);

}  // namespace raygate
