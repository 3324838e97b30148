#include "checkout/tree_stamp.h"

#include <sys/stat.h>

#include <fmt/format.h>

#include <charconv>
#include <string_view>

namespace fs = std::filesystem;

namespace raygate {
namespace {

// First line of every stamp: a stamp of another layout is never trusted. Layout 2 marks trees
// written since the checkout keeps binary files (layout 1 trees could hold them empty); layout 3
// adds the inode, so a file replaced whole (an editor's or a tool's write-and-rename) within the
// file system's timestamp tick, same size, is still seen (a test saw it missed under load).
constexpr const char* kHeader = "raygate tree stamp 3\n";
constexpr std::string_view kHeaderPrefix = "raygate tree stamp ";

// One line per file:
// "<size> <mtime seconds> <mtime nanoseconds> <mode> <inode> <path length>:<path>".
// The length prefix keeps any path (spaces, newlines are legal in git) unambiguous.
struct Entry {
  long long size = 0;
  long long seconds = 0;
  long long nanoseconds = 0;
  unsigned mode = 0;
  unsigned long long inode = 0;
  std::string path;
};

Entry entry_of(const struct stat& info, std::string path) {
  return {static_cast<long long>(info.st_size),         static_cast<long long>(info.st_mtim.tv_sec),
          static_cast<long long>(info.st_mtim.tv_nsec), static_cast<unsigned>(info.st_mode),
          static_cast<unsigned long long>(info.st_ino), std::move(path)};
}

bool matches(const struct stat& info, const Entry& e) {
  return static_cast<long long>(info.st_size) == e.size &&
         static_cast<long long>(info.st_mtim.tv_sec) == e.seconds &&
         static_cast<long long>(info.st_mtim.tv_nsec) == e.nanoseconds &&
         static_cast<unsigned>(info.st_mode) == e.mode &&
         static_cast<unsigned long long>(info.st_ino) == e.inode;
}

std::string line_of(const Entry& e) {
  return fmt::format("{} {} {} {:o} {} {}:{}\n", e.size, e.seconds, e.nanoseconds, e.mode, e.inode,
                     e.path.size(), e.path);
}

// Parsed by hand from a string_view: a stream-based parser took most of the verification time.
class StampReader {
 public:
  explicit StampReader(std::string_view text) : rest_(text) {}
  bool done() const { return rest_.empty(); }

  std::optional<Entry> next() {
    Entry e;
    std::size_t length = 0;
    if (!number(e.size, ' ') || !number(e.seconds, ' ') || !number(e.nanoseconds, ' ') ||
        !number(e.mode, ' ', 8) || !number(e.inode, ' ') || !number(length, ':') ||
        rest_.size() < length + 1 || rest_[length] != '\n') {
      return std::nullopt;
    }
    e.path = rest_.substr(0, length);
    rest_.remove_prefix(length + 1);
    return e;
  }

 private:
  template <typename T>
  bool number(T& value, char end, int base = 10) {
    const auto [ptr, ec] = std::from_chars(rest_.data(), rest_.data() + rest_.size(), value, base);
    if (ec != std::errc() || ptr == rest_.data() + rest_.size() || *ptr != end) return false;
    rest_.remove_prefix(static_cast<std::size_t>(ptr - rest_.data()) + 1);
    return true;
  }

  std::string_view rest_;
};

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

bool stamp_is_outdated(const std::string& stamp) {
  return stamp.starts_with(kHeaderPrefix) && !stamp.starts_with(kHeader);
}

std::optional<std::string> stamp_difference(const fs::path& root, const std::string& stamp) {
  const std::string_view header = kHeader;
  if (stamp.compare(0, header.size(), header) != 0) return "its stamp is unreadable";
  StampReader reader(std::string_view(stamp).substr(header.size()));
  std::string path = root.string() + "/";
  const std::size_t prefix = path.size();
  while (!reader.done()) {
    const std::optional<Entry> expected = reader.next();
    if (!expected) return "its stamp is unreadable";
    path.resize(prefix);
    path += expected->path;
    struct stat info {};
    if (::lstat(path.c_str(), &info) != 0) return expected->path + " is missing";
    if (!matches(info, *expected)) return expected->path + " was modified";
  }
  return std::nullopt;
}

}  // namespace raygate
