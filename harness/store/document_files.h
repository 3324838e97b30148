// Results documents in and out of the store as files: `raygate import` reads them (refusing JSON
// that is something else, clearly), `raygate export` writes stored ones back byte for byte, each
// file named from what the store holds only after that name is checked.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "results/results.h"
#include "store/store.h"

namespace raygate {

// A results document from `file`; UsageError naming the file for text that is not JSON or JSON
// that is not a results document (an adapter, a suite, a build record).
ResultsDocument load_results_file(const std::filesystem::path& file);

// A document as import reads it, and the keys of its file that are not stored: this raygate
// stores what it knows (and settings' and machine's unknown keys), so a newer raygate's added
// keys elsewhere are dropped, and import says which ("$.scenes[0].extra").
struct ImportedFile {
  ResultsDocument document;
  std::vector<std::string> keys_not_kept;  // JSON paths, in the file's order
};
ImportedFile read_import_file(const std::filesystem::path& file);

// A commit sha or prefix, lower-cased; UsageError for anything else.
std::string checked_sha_prefix(std::string sha);

// Where export wrote: one FILE.json, or one <id>-<short sha>.json per document in a directory.
struct ExportedFiles {
  std::vector<std::filesystem::path> files;
  bool single_file = false;
};

// `out` ending in .json takes exactly one document; anything else is a directory. Every name is
// checked before anything is written, so a bad one leaves the directory untouched.
ExportedFiles export_documents(const std::vector<StoredDocument>& documents,
                               const std::filesystem::path& out);

}  // namespace raygate
