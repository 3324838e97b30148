// Reading an NFF file from disk for the reader. Problems with the file itself (missing,
// a directory, unreadable) are ParseErrors at line 0, so callers handle one kind of error.
#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <system_error>

#include "nff/parser.h"

namespace raygate::nff {
namespace {

[[noreturn]] void fail_file(const std::string& path, const std::string& found) {
  throw ParseError(FileLoc{path, 0, 0}, "expected a readable NFF file, found " + found);
}

std::string system_message(int error) { return std::generic_category().message(error); }

// Refuses what cannot be an NFF file before opening it: a directory would open and then fail
// to read, a device such as /dev/zero would never end, and a FIFO with no writer blocks the
// open forever (issue 25, class 12). Process output comes in on stdin ("-") instead.
void check_kind(const std::string& path) {
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(path, error);
  switch (status.type()) {
    case std::filesystem::file_type::regular: return;
    case std::filesystem::file_type::fifo:
      fail_file(path, "a FIFO (named pipe), not a regular file; pipe a scene in as '-'");
    case std::filesystem::file_type::not_found: fail_file(path, "no such file");
    case std::filesystem::file_type::directory: fail_file(path, "a directory");
    case std::filesystem::file_type::none:
    case std::filesystem::file_type::unknown:
      fail_file(path, "a path it cannot inspect (" + system_message(error.value()) + ")");
    default: fail_file(path, "a device or socket, not a regular file");
  }
}

// The whole file in one string: the reader works on the text as a whole.
std::string read_all(const std::string& path) {
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"),
                                                             &std::fclose);
  if (!file) fail_file(path, "a file it cannot open (" + system_message(errno) + ")");
  std::string text;
  char buffer[1 << 16];
  for (;;) {
    const std::size_t got = std::fread(buffer, 1, sizeof buffer, file.get());
    text.append(buffer, got);
    if (got < sizeof buffer) break;
  }
  if (std::ferror(file.get()) != 0) {
    fail_file(path, "a read error (" + system_message(errno) + ")");
  }
  return text;
}

}  // namespace

Scene read_nff_file(const std::string& path) {
  check_kind(path);
  return parse_nff(read_all(path), path);
}

}  // namespace raygate::nff
