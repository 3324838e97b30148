#include "checkout/tree_stamp.h"

#include <sys/stat.h>

#include <fmt/format.h>

#include <sstream>

namespace fs = std::filesystem;

namespace raygate {
namespace {

// First line of every stamp: a stamp of another layout is never trusted.
constexpr const char* kHeader = "raygate tree stamp 1\n";

// One line per file: "<size> <mtime seconds> <mtime nanoseconds> <mode> <path length>:<path>".
// The length prefix keeps any path (spaces, newlines are legal in git) unambiguous.
struct Entry {
  long long size = 0;
  long long seconds = 0;
  long long nanoseconds = 0;
  unsigned mode = 0;
  std::string path;
};

Entry entry_of(const struct stat& info, std::string path) {
  return {static_cast<long long>(info.st_size), static_cast<long long>(info.st_mtim.tv_sec),
          static_cast<long long>(info.st_mtim.tv_nsec), static_cast<unsigned>(info.st_mode),
          std::move(path)};
}

std::string line_of(const Entry& e) {
  return fmt::format("{} {} {} {:o} {}:{}\n", e.size, e.seconds, e.nanoseconds, e.mode,
                     e.path.size(), e.path);
}

std::optional<Entry> read_entry(std::istream& in) {
  Entry e;
  std::size_t length = 0;
  char colon = 0;
  if (!(in >> e.size >> e.seconds >> e.nanoseconds >> std::oct >> e.mode >> std::dec >> length)) {
    return std::nullopt;
  }
  if (!in.get(colon) || colon != ':') return std::nullopt;
  e.path.resize(length);
  if (!in.read(e.path.data(), static_cast<std::streamsize>(length)) || in.get() != '\n') {
    return std::nullopt;
  }
  return e;
}

}  // namespace

fs::path stamp_path_for(const fs::path& dir) {
  std::string name = ".";
  name += dir.filename().string();
  name += ".stamp";
  return dir.parent_path() / name;
}

std::string tree_stamp(const fs::path& root) {
  std::string text = kHeader;
  for (auto it = fs::recursive_directory_iterator(root); it != fs::recursive_directory_iterator();
       ++it) {
    struct stat info {};
    if (::lstat(it->path().c_str(), &info) != 0 || S_ISDIR(info.st_mode)) continue;
    // lexically: fs::relative would resolve a symlink to its target's name
    text += line_of(entry_of(info, it->path().lexically_relative(root).string()));
  }
  return text;
}

std::optional<std::string> stamp_difference(const fs::path& root, const std::string& stamp) {
  std::istringstream in(stamp);
  std::string header;
  if (!std::getline(in, header) || header + "\n" != kHeader) return "its stamp is unreadable";
  while (in.peek() != std::char_traits<char>::eof()) {
    const std::optional<Entry> expected = read_entry(in);
    if (!expected) return "its stamp is unreadable";
    struct stat info {};
    if (::lstat((root / expected->path).c_str(), &info) != 0) {
      return expected->path + " is missing";
    }
    const Entry found = entry_of(info, expected->path);
    if (found.size != expected->size || found.seconds != expected->seconds ||
        found.nanoseconds != expected->nanoseconds || found.mode != expected->mode) {
      return expected->path + " was modified";
    }
  }
  return std::nullopt;
}

}  // namespace raygate
