// The NFF reader (spd-spec.md §1.6): token-based, so a `c` on one line or three both work.
// Every error names the place, what was expected and what was found.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

#include "nff/scene.h"

namespace raygate::nff {

// A malformed or unreadable scene. what() is the whole one-line message:
// "path:line:column: expected <what>, found <what>".
class ParseError : public std::runtime_error {
 public:
  ParseError(FileLoc loc, const std::string& message);
  const FileLoc& loc() const { return loc_; }
  // The message without the location prefix.
  const std::string& detail() const { return detail_; }

 private:
  FileLoc loc_;
  std::string detail_;
};

// Parses NFF text; `path` is used only in locations and messages.
Scene parse_nff(std::string_view text, const std::string& path);

// Reads and parses a file. Missing, unreadable or directory paths are ParseErrors at line 0.
Scene read_nff_file(const std::string& path);

}  // namespace raygate::nff
