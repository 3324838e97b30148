#include "store/document_files.h"

#include <fmt/core.h>

#include <algorithm>
#include <cctype>

#include "core/error.h"
#include "core/fs.h"
#include "core/json_reader.h"
#include "core/path_component.h"

namespace raygate {

namespace {

std::string short_sha_of(const nlohmann::json& document) {
  for (const nlohmann::json& revision : document.value("revisions", nlohmann::json::array())) {
    const std::string sha = revision.at("worktree").value("short_sha", std::string());
    if (!sha.empty()) return sha;
  }
  return "unknown";
}

// The document's text exactly as write_results writes it.
std::string document_text(const StoredDocument& stored) { return stored.document.dump(1) + "\n"; }

// The JSON paths of keys in `read` that `written` lacks, where both are objects or arrays.
void keys_missing(const nlohmann::json& read, const nlohmann::json& written,
                  const std::string& path, std::vector<std::string>& missing) {
  if (read.is_object() && written.is_object()) {
    for (const auto& [key, value] : read.items()) {
      const auto kept = written.find(key);
      if (kept == written.end()) {
        missing.push_back(path + "." + key);
      } else {
        keys_missing(value, *kept, path + "." + key, missing);
      }
    }
  } else if (read.is_array() && written.is_array()) {
    for (std::size_t i = 0; i < std::min(read.size(), written.size()); ++i) {
      keys_missing(read[i], written[i], fmt::format("{}[{}]", path, i), missing);
    }
  }
}

nlohmann::json results_json_file(const std::filesystem::path& file) {
  // Duplicate keys and out-of-range numbers refused with where they are (core/json_reader.h).
  nlohmann::json json = read_json_file(file);
  const bool looks_like_results = json.is_object() && json.contains("schema_version") &&
                                  json.contains("revisions") && json.contains("scenes");
  if (!looks_like_results) {
    throw UsageError(
        fmt::format("{}: not a raygate results document (no schema_version, "
                    "revisions and scenes); import takes the results.json that "
                    "`raygate run` writes",
                    file.string()));
  }
  return json;
}

// -o's files are written whole: a link there is refused before anything is written.
void refuse_symbolic_link(const std::filesystem::path& file) {
  if (const std::string problem = symbolic_link_problem(file); !problem.empty()) {
    throw UsageError("-o: " + problem);
  }
}

}  // namespace

ResultsDocument load_results_file(const std::filesystem::path& file) {
  return results_from_json(results_json_file(file), file.string());
}

ImportedFile read_import_file(const std::filesystem::path& file) {
  const nlohmann::json json = results_json_file(file);
  ImportedFile imported{results_from_json(json, file.string()), {}};
  keys_missing(json, to_json(imported.document), "$", imported.keys_not_kept);
  return imported;
}

std::string checked_sha_prefix(std::string sha) {
  std::transform(sha.begin(), sha.end(), sha.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  const bool hex =
      std::all_of(sha.begin(), sha.end(), [](unsigned char c) { return std::isxdigit(c) != 0; });
  if (!hex || sha.size() > 40) {
    throw UsageError(fmt::format("--sha {}: not a commit sha or a prefix of one", sha));
  }
  return sha;
}

ExportedFiles export_documents(const std::vector<StoredDocument>& documents,
                               const std::filesystem::path& out) {
  if (out.extension() == ".json") {
    if (documents.size() != 1) {
      throw UsageError(
          fmt::format("{} documents match but -o {} names one file; give a "
                      "directory, or narrow with --sha or --last 1",
                      documents.size(), out.string()));
    }
    refuse_symbolic_link(out);
    write_file_atomically(out, document_text(documents.front()));
    return {{out}, true};
  }
  // The sha is read back from the store, which holds whatever was imported.
  ExportedFiles exported;
  for (const StoredDocument& stored : documents) {
    const std::string sha = checked_component(
        short_sha_of(stored.document),
        fmt::format("stored document {}: revisions[].worktree.short_sha", stored.id));
    exported.files.push_back(join_component(out, fmt::format("{}-{}", stored.id, sha),
                                            "exported document name", ".json"));
    refuse_symbolic_link(exported.files.back());
  }
  for (std::size_t i = 0; i < documents.size(); ++i) {
    write_file_atomically(exported.files[i], document_text(documents[i]));
  }
  return exported;
}

}  // namespace raygate
