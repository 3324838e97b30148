// Choosing a backend for a --store location (both are the one SQL store, store/sql_store.h, over
// their dialect's handle), and the backend-independent parts of the interface.
#include "store/store.h"

#include <fmt/core.h>

#include "core/error.h"
#include "store/history.h"
#include "store/postgres_url.h"
#include "store/sql_store.h"
#include "store/store_rows.h"

namespace raygate {

std::vector<HistoryRow> ResultsStore::history(const HistoryQuery& query) {
  return latest_per_commit(measurements(query), query.last_commits);
}

std::unique_ptr<ResultsStore> open_store(const std::string& location, StoreOpen mode) {
  if (location.empty()) return open_store(kDefaultStorePath, mode);
  if (is_postgresql_url(location)) return open_postgres_store(location, mode);
  if (location.find("://") != std::string::npos) {
    throw UsageError(
        fmt::format("--store {}: unknown kind of URL; give a file path for an "
                    "SQLite store or a postgresql:// URL for the team store",
                    redact_postgresql_url(location)));
  }
  // A directory is a usage error, not a store that could not be opened: the user named the
  // wrong thing, and nothing about this machine failed.
  std::error_code error;
  if (std::filesystem::is_directory(location, error)) {
    throw UsageError(fmt::format("--store {}: is a directory; give the store's file, e.g. {}",
                                 location,
                                 (std::filesystem::path(location) / "results.db").string()));
  }
  return open_sqlite_store(std::filesystem::absolute(location), mode);
}

std::string branch_of(const ResultsDocument& document, const std::string& fallback) {
  for (const Role role : {Role::tracer, Role::head}) {
    const RevisionRecord* revision = document.revision(role);
    if (revision && !revision->worktree.ref_name.empty()) {
      return short_ref_name(revision->worktree.ref_name);
    }
  }
  return fallback;
}

}  // namespace raygate
