// The one reader for every JSON document raygate takes as input: adapters, policies, suites,
// results documents read from disk (gate, report, merge, import, golden bless), golden
// manifests. nlohmann's parser alone is wrong for input a person wrote or a stranger sent: of a
// key given twice it silently keeps the last ("max_slowdown": 0.03, "max_slowdown": 5 gated at
// +500%), and a number past a double's range (1e400) is an out_of_range exception that no
// caller expected. Here both are usage errors that say where, as syntax errors already did:
// "FILE:LINE:COLUMN: $.json.path: what is wrong".
#pragma once

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <string_view>

#include "core/error.h"

namespace raygate {

// A JSON input that cannot be taken as it is. what() is the whole message; the parts are kept
// for callers that phrase it their own way.
class JsonInputError : public UsageError {
 public:
  JsonInputError(std::string origin, std::size_t line, std::size_t column, std::string json_path,
                 std::string problem);
  const std::string& origin() const { return origin_; }
  std::size_t line() const { return line_; }
  std::size_t column() const { return column_; }
  const std::string& json_path() const { return json_path_; }  // "" for a syntax error
  const std::string& problem() const { return problem_; }

 private:
  std::string origin_;
  std::size_t line_;
  std::size_t column_;
  std::string json_path_;
  std::string problem_;
};

// Parses `text`, read from `origin` (a file name, "<stdin>"). Throws JsonInputError for text
// that is not JSON ("not JSON: <the parser's reason>"), for a key given twice in one object
// (at the second one, with the path of the object holding it) and for a number no double holds
// (with the path of the field).
nlohmann::json parse_json_input(std::string_view text, const std::string& origin);

// A JSON input's text: read_file's, refused (UsageError) past 256 MiB before it is read. A results
// document of 13 scenes and 200 rounds is about 8 MB; an 8 GB file of NULs was read whole (17 GB
// of memory, 35 s) before its first byte was found not JSON (a sweep).
std::string read_json_text(const std::filesystem::path& file);

// The file's text parsed by parse_json_input; a file that cannot be read is a UsageError too.
nlohmann::json read_json_file(const std::filesystem::path& file);

// An exception's text without nlohmann's "[json.exception.out_of_range.403] " label, for a
// message a user reads ("key 'parse_seconds' not found"); other exceptions' text as it is.
std::string plain_exception_text(const std::exception& e);

}  // namespace raygate
