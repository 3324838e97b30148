// Where a measurement's results document is kept while it is measured and when it ends. The
// document the user named (-o) may sit on a disk that fills up or a folder that disappears
// mid-run; the measurement must not die of it, so each write falls back to the run's own
// folder on the cache disk, and the failure is reported at the end (exit 3), never thrown.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/fs.h"
#include "results/results.h"

namespace raygate {

// Where a document was written, and the writes that failed on the way.
struct KeptDocument {
  std::optional<std::filesystem::path> path;  // nullopt: nowhere (only in memory)
  std::vector<FailedWrite> failed;
};

// Writes `document` to `requested`; when that fails, to `fallback` instead (unless it is the
// same file). When the requested write succeeds, a stale fallback copy left by an earlier
// failed write is removed, so the run folder never holds an older document than -o. Only
// WriteError is caught: any other error is a bug and travels up.
KeptDocument keep_document(const ResultsDocument& document, const std::filesystem::path& requested,
                           const std::filesystem::path& fallback);

// "cannot write R: reason; kept in F instead", "...; not kept in any file: F: reason", or "" if
// nothing failed: for the line an interrupted or finished measurement ends with.
std::string describe_kept(const KeptDocument& kept);

}  // namespace raygate
