#include "pipeline/store_commands.h"

#include <fmt/core.h>

#include <algorithm>
#include <fstream>
#include <string_view>

#include "core/error.h"
#include "core/format.h"
#include "pipeline/output_failures.h"
#include "store/document_files.h"
#include "store/postgres_url.h"
#include "store/schema.h"

namespace raygate {

std::string store_location_problem(const std::string& location) {
  if (!is_postgresql_url(location) && location.find("://") != std::string::npos) {
    return "unknown kind of URL; give a file path for an SQLite store or a postgresql:// URL";
  }
  return "";
}

std::string written_store_problem(const std::string& location) {
  if (std::string problem = store_location_problem(location); !problem.empty()) return problem;
  if (is_postgresql_url(location)) return "";
  std::error_code error;
  if (std::filesystem::exists(location, error) &&
      !std::filesystem::is_regular_file(location, error)) {
    return location +
           " is not a regular file (a folder, device, FIFO or socket); name an SQLite "
           "results store, or a file to create one in";
  }
  // A file that is there and is no SQLite database (a results document, a text file) was found
  // only once the measurement was done, and the store left unwritten with a warning.
  if (std::filesystem::file_size(location, error) > 0 && !error) {
    unsigned char header[64] = {};
    std::ifstream(location, std::ios::binary).read(reinterpret_cast<char*>(header), sizeof header);
    if (std::string_view(reinterpret_cast<const char*>(header), 16) !=
        std::string_view("SQLite format 3\0", 16)) {
      return location + " is not an SQLite database; name a raygate results store, or a new file";
    }
    // The schema version (SQLite's user_version, bytes 60..63 of the header, big-endian): a
    // newer raygate's store was found only after the whole measurement (sweep 12).
    const int version = (header[60] << 24) | (header[61] << 16) | (header[62] << 8) | header[63];
    if (const int known = store_migrations().back().version; version > known) {
      return fmt::format(
          "{}: schema version {} is newer than this raygate knows ({}); use a "
          "newer raygate, or another store",
          location, version, known);
    }
  }
  return output_file_problem(location);
}

namespace {

// The machine's own history for the drift rule: every document, any branch, any series (the
// rule compares each series only with itself).
HistoryQuery machine_query(const HistoryQuery& query) {
  HistoryQuery machine = query;
  machine.branch.clear();
  machine.last_commits = 0;
  machine.repository.clear();
  machine.adapter.clear();
  machine.suite.clear();
  machine.series.clear();
  return machine;
}

}  // namespace

std::filesystem::path history_page(const std::string& html_dir) {
  if (html_dir.empty()) return {};
  const std::filesystem::path page = std::filesystem::path(html_dir) / "history.html";
  check_output_path(page, "--html");
  return page;
}

HistoryView store_history_view(const std::string& location, const HistoryQuery& query) {
  const auto store = open_store(location, StoreOpen::must_exist);
  HistoryView view = make_history_view(store->measurements(query), query.last_commits,
                                       store->measurements(machine_query(query)));
  view.store = store->location();
  view.role = query.role;
  view.branch = query.branch;
  // A series the user named that is not there is a typo, as alert says (exit 2), not "no results".
  if (!query.series.empty() && view.tables.empty()) {
    throw UsageError(fmt::format(
        "--series {}: no series in {} matches it (with the other filters); `raygate history "
        "--format json` lists their ids",
        query.series, view.store));
  }
  return view;
}

AlertJudgement judge_store_history(const AlertRequest& request,
                                   const std::function<void(const std::string&)>& say) {
  const std::size_t points_needed = 2 * request.detection.min_segment;
  if (request.query.last_commits != 0 && request.query.last_commits < points_needed) {
    // Such a judgement could never alert, and would say OK: refused, not passed (a sweep).
    throw UsageError(fmt::format(
        "--min-segment {} needs {} commits, more than --last {} keeps: no change could be found",
        request.detection.min_segment, points_needed, request.query.last_commits));
  }
  const GatePolicy policy = request.policy.empty() ? GatePolicy{} : load_policy(request.policy);
  const auto store = open_store(request.store, StoreOpen::must_exist);
  const std::vector<HistoryRow> rows = store->history(request.query);
  say(fmt::format("judging the last {}{} of {}: {}",
                  count_text(request.query.last_commits, "commit"),
                  request.query.branch.empty() ? "" : " of branch " + request.query.branch,
                  store->location(), count_text(rows.size(), "measurement")));
  AlertJudgement judgement = judge_history(rows, policy, request.detection, request.action);
  if (judgement.series.empty()) {
    throw UsageError(
        fmt::format("no measured commits in {} match the filters; record some "
                    "with raygate run (or raygate import)",
                    store->location()));
  }
  return judgement;
}

namespace {

// Keys a newer raygate added are not stored, nor compared when a document is found stored
// already: said, not dropped silently (the tenth sweep).
std::string not_kept_line(const std::string& file, const std::vector<std::string>& keys) {
  if (keys.empty()) return "";
  constexpr std::size_t kShown = 5;
  std::string shown;
  for (std::size_t i = 0; i < std::min(keys.size(), kShown); ++i) {
    shown += (i == 0 ? "" : ", ") + keys[i].substr(0, 120);
  }
  if (keys.size() > kShown) shown += fmt::format(" and {} more", keys.size() - kShown);
  return fmt::format(
      "{}: warning: keys this raygate does not know are not stored (a newer raygate's? the "
      "file keeps them): {}\n",
      file, shown);
}

}  // namespace

std::string import_documents(const std::vector<std::string>& files, const std::string& location,
                             const std::string& branch) {
  std::vector<ImportedFile> documents;  // all checked before any is stored
  for (const std::string& file : files) documents.push_back(read_import_file(file));
  const auto store = open_store(location, StoreOpen::create_if_missing);
  std::size_t fresh = 0;
  std::string lines;
  for (std::size_t i = 0; i < documents.size(); ++i) {
    const std::string recorded = branch_of(documents[i].document, branch);
    AddOutcome outcome;
    try {
      outcome = store->add(documents[i].document, recorded);
    } catch (const InfraError& e) {  // a full disk said only "SQLite error 13 ... COMMIT"
      throw InfraError(fmt::format("{}: not stored: {} ({} of {} documents stored before it)",
                                   files[i], e.what(), fresh, documents.size()));
    }
    fresh += outcome.duplicate ? 0 : 1;
    lines += fmt::format("{}: {} document {}{}\n", files[i],
                         outcome.duplicate ? "already stored as" : "stored as", outcome.document_id,
                         recorded.empty() ? "" : " (branch " + recorded + ")");
    lines += not_kept_line(files[i], documents[i].keys_not_kept);
  }
  return lines + fmt::format("imported {} of {} documents into {}\n", fresh, documents.size(),
                             store->location());
}

std::string export_stored_documents(const ExportRequest& request) {
  if (request.out.empty()) {
    throw UsageError("export: --output is required (a directory or FILE.json)");
  }
  // Before the store is read: a path that cannot be written is the command line's fault.
  if (std::filesystem::path(request.out).extension() == ".json") {
    check_output_path(request.out, "--output");
    check_distinct_files({{"--output", request.out}, {"--store", request.store}});
  } else {
    std::error_code error;
    if (std::filesystem::is_regular_file(request.out, error)) {
      throw UsageError("--output " + request.out +
                       ": a file not named .json; export writes FILE.json, or a directory of "
                       "documents");
    }
    check_output_folder(request.out, "--output");
  }
  const auto store = open_store(request.store, StoreOpen::must_exist);
  DocumentQuery query;
  query.sha_prefix = checked_sha_prefix(request.sha);
  query.last = request.last;
  query.branch = request.branch;
  const std::vector<StoredDocument> documents = store->documents(query);
  if (documents.empty()) {
    throw UsageError(fmt::format("no document in {} matches{}{}", store->location(),
                                 request.sha.empty() ? "" : " --sha " + request.sha,
                                 request.branch.empty() ? "" : " --branch " + request.branch));
  }
  if (export_documents(documents, request.out).single_file) {
    return fmt::format("wrote document {} to {}\n", documents.front().id, request.out);
  }
  return fmt::format("wrote {} documents to {}\n", documents.size(), request.out);
}

}  // namespace raygate
