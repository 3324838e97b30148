#include "core/replace_directory.h"

#include <fcntl.h>
#include <stdio.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>

#include "core/fs.h"

namespace raygate {

namespace {

std::string system_reason() { return std::strerror(errno); }

// Removes a temporary on every way out that did not swap it in.
class TemporaryDirectory {
 public:
  explicit TemporaryDirectory(std::filesystem::path path) : path_(std::move(path)) {}
  ~TemporaryDirectory() {
    if (path_.empty()) return;
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TemporaryDirectory(const TemporaryDirectory&) = delete;
  TemporaryDirectory& operator=(const TemporaryDirectory&) = delete;
  const std::filesystem::path& path() const { return path_; }
  void set(std::filesystem::path path) { path_ = std::move(path); }

 private:
  std::filesystem::path path_;
};

std::filesystem::path make_temporary(const std::filesystem::path& target) {
  // "." + name + ".new-XXXXXX", built step by step (GCC 12 warns falsely on the one-liner).
  std::string name = ".";
  name += target.filename().string();
  name += ".new-XXXXXX";
  std::string pattern = (target.parent_path() / name).string();
  if (::mkdtemp(pattern.data()) == nullptr) {
    throw WriteError(target, "cannot create a temporary folder beside it: " + system_reason());
  }
  return pattern;
}

void sync_file(const std::filesystem::path& file) {
  const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw WriteError(file, "cannot open it to sync it: " + system_reason());
  const bool synced = ::fsync(fd) == 0;
  const std::string reason = synced ? "" : system_reason();
  ::close(fd);
  if (!synced) throw WriteError(file, "cannot sync it: " + reason);
}

// Every regular file and folder under `root`, and `root` itself, on disk.
void sync_tree(const std::filesystem::path& root) {
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
    if (entry.is_symlink()) continue;
    if (entry.is_directory()) {
      sync_directory(entry.path());
    } else if (entry.is_regular_file()) {
      sync_file(entry.path());
    }
  }
  sync_directory(root);
}

// The new directory takes the old one's permissions (a golden folder in a repository is 0755,
// a temporary from mkdtemp 0700).
void copy_permissions(const std::filesystem::path& from, const std::filesystem::path& to) {
  std::error_code ec;
  const std::filesystem::perms perms = std::filesystem::status(from, ec).permissions();
  if (ec || perms == std::filesystem::perms::unknown) {
    std::filesystem::permissions(to, std::filesystem::perms(0755), ec);
  } else {
    std::filesystem::permissions(to, perms, ec);
  }
}

// Puts `fresh` at `target`. Returns where the old contents now are (to remove), or "" when
// there were none.
std::filesystem::path swap_in(const std::filesystem::path& fresh,
                              const std::filesystem::path& target) {
  if (!std::filesystem::exists(target)) {
    if (std::rename(fresh.c_str(), target.c_str()) != 0) {
      throw WriteError(target,
                       "cannot rename " + fresh.string() + " into place: " + system_reason());
    }
    return {};
  }
  if (::renameat2(AT_FDCWD, fresh.c_str(), AT_FDCWD, target.c_str(), RENAME_EXCHANGE) == 0) {
    return fresh;  // the old contents now have the temporary's name
  }
  if (errno != EINVAL && errno != ENOSYS && errno != ENOTSUP) {
    throw WriteError(target, "cannot swap in " + fresh.string() + ": " + system_reason());
  }
  // No atomic exchange on this file system: two renames, with the old put back on failure.
  const std::filesystem::path aside = fresh.string() + ".old";
  if (std::rename(target.c_str(), aside.c_str()) != 0) {
    throw WriteError(target, "cannot move it aside: " + system_reason());
  }
  if (std::rename(fresh.c_str(), target.c_str()) != 0) {
    const std::string reason = system_reason();
    std::rename(aside.c_str(), target.c_str());
    throw WriteError(target, "cannot rename " + fresh.string() + " into place: " + reason);
  }
  return aside;
}

}  // namespace

void replace_directory(const std::filesystem::path& target,
                       const std::function<void(const std::filesystem::path&)>& fill) {
  std::error_code ec;
  const std::filesystem::path where = std::filesystem::is_symlink(target, ec)
                                          ? std::filesystem::canonical(target)
                                          : std::filesystem::absolute(target);
  std::filesystem::create_directories(where.parent_path(), ec);
  if (ec) {
    throw WriteError(where, "cannot create " + where.parent_path().string() + ": " + ec.message());
  }
  TemporaryDirectory fresh(make_temporary(where));
  copy_permissions(where, fresh.path());
  fill(fresh.path());
  sync_tree(fresh.path());
  const std::filesystem::path old = swap_in(fresh.path(), where);
  fresh.set(old);  // the destructor now removes the old contents
  sync_directory(where.parent_path());
}

void link_tree(const std::filesystem::path& from, const std::filesystem::path& to) {
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(from)) {
    const std::filesystem::path into = to / entry.path().filename();
    if (entry.is_symlink()) {
      std::filesystem::copy_symlink(entry.path(), into, ec);
    } else if (entry.is_directory()) {
      std::filesystem::create_directory(into, entry.path(), ec);
      if (!ec) link_tree(entry.path(), into);
    } else if (entry.is_regular_file()) {
      std::filesystem::create_hard_link(entry.path(), into, ec);
      if (ec) std::filesystem::copy_file(entry.path(), into, ec);  // no links here (vfat, ...)
    }
    // A full disk can refuse even a new folder entry: said as the write it is.
    if (ec) throw WriteError(into, ec.message());
  }
}

bool is_replacement_temporary(const std::filesystem::path& entry) {
  const std::string name = entry.filename().string();
  return name.size() > 1 && name.front() == '.' && name.find(".new-") != std::string::npos;
}

}  // namespace raygate
