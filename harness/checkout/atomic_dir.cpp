#include "checkout/atomic_dir.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <string_view>

#include "core/error.h"

namespace fs = std::filesystem;

namespace raygate {
namespace {

// Hidden names beside the entry. (Appending, rather than "." + name, also avoids GCC 12's
// false -Wrestrict warning on operator+ with a literal on the left.)
std::string hidden_name(const fs::path& entry, std::string_view suffix) {
  std::string name = ".";
  name += entry.filename().string();
  name += suffix;
  return name;
}

std::string temp_prefix(const fs::path& final_path) { return hidden_name(final_path, ".tmp-"); }

void remove_leftovers(const fs::path& final_path) {
  const std::string prefix = temp_prefix(final_path);
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(final_path.parent_path(), ec)) {
    if (entry.path().filename().string().rfind(prefix, 0) == 0) {
      std::error_code ignored;  // a leftover that cannot be removed is merely wasted space
      fs::remove_all(entry.path(), ignored);
    }
  }
}

fs::path make_temp_dir(const fs::path& final_path) {
  std::string pattern = (final_path.parent_path() / (temp_prefix(final_path) + "XXXXXX")).string();
  if (::mkdtemp(pattern.data()) == nullptr) {
    throw InfraError("cannot create a directory beside " + final_path.string() + ": " +
                     std::strerror(errno));
  }
  return pattern;
}

// Flushes the finished tree to disk before the rename publishes it: after a power cut the
// final name must not point at files whose data never reached the disk.
void sync_filesystem_of(const fs::path& dir) {
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::syncfs(fd);
  ::close(fd);
}

}  // namespace

fs::path lock_path_for(const fs::path& dir) {
  return dir.parent_path() / hidden_name(dir, ".lock");
}

void build_directory_atomically(const fs::path& final_path,
                                const std::function<void(const fs::path&)>& fill) {
  std::error_code ec;
  fs::create_directories(final_path.parent_path(), ec);
  if (ec) {
    throw InfraError("cannot create " + final_path.parent_path().string() + ": " + ec.message());
  }
  remove_leftovers(final_path);
  const fs::path temp = make_temp_dir(final_path);
  try {
    fill(temp);
    ::chmod(temp.c_str(), 0755);  // mkdtemp made it private; the final entry is an ordinary dir
    sync_filesystem_of(temp);
    if (std::rename(temp.c_str(), final_path.c_str()) != 0) {
      throw InfraError("cannot move " + temp.string() + " to " + final_path.string() + ": " +
                       std::strerror(errno));
    }
  } catch (...) {
    fs::remove_all(temp, ec);
    throw;
  }
}

}  // namespace raygate
