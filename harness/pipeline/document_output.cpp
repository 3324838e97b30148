#include "pipeline/document_output.h"

namespace raygate {

namespace {

// Write `document` at `path`; the failure, if any.
std::optional<FailedWrite> try_write(const ResultsDocument& document,
                                     const std::filesystem::path& path) {
  try {
    write_results(document, path);
    return std::nullopt;
  } catch (const WriteError& e) {
    return e.failure();
  }
}

}  // namespace

KeptDocument keep_document(const ResultsDocument& document, const std::filesystem::path& requested,
                           const std::filesystem::path& fallback) {
  KeptDocument kept;
  if (const auto failed = try_write(document, requested); !failed) {
    kept.path = requested;
    std::error_code ignored;  // a stale copy that cannot be removed misleads no one who reads -o
    if (fallback != requested) std::filesystem::remove(fallback, ignored);
    return kept;
  } else {
    kept.failed.push_back(*failed);
  }
  if (fallback == requested) return kept;
  if (const auto failed = try_write(document, fallback); failed) {
    kept.failed.push_back(*failed);
  } else {
    kept.path = fallback;
  }
  return kept;
}

std::string describe_kept(const KeptDocument& kept) {
  std::string text;
  for (const FailedWrite& failed : kept.failed) {
    text += (text.empty() ? "cannot write " : "; cannot write ") + failed.path.string() + ": " +
            failed.reason;
  }
  if (text.empty()) return text;
  if (kept.path) return text + "; kept in " + kept.path->string() + " instead";
  return text + "; the document is kept in no file";
}

}  // namespace raygate
