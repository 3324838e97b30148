#include "checkout/tree_writer.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>

#include "core/error.h"
#include "core/utf8.h"

namespace fs = std::filesystem;

namespace raygate::git {
namespace {

struct TreeWriter {
  git_repository* repo;
  git_oid commit_id;
  fs::path dir;
  std::string where;
  std::vector<Gitlink> gitlinks;

  // Paths are bytes in git; messages are text, so a path is repaired to UTF-8 where it is shown.
  static std::string shown(std::string_view path) { return repaired_utf8(path); }

  [[noreturn]] void fail_io(const std::string& what, const std::string& path) const {
    throw InfraError(fmt::format("{} {} (checking out {} from {}): {}", what, shown(path),
                                 to_hex(commit_id), where, std::strerror(errno)));
  }

  void check_name(std::string_view name, const std::string& parent) const {
    const bool unsafe = name.empty() || name == "." || name == ".." ||
                        name.find('/') != std::string_view::npos ||
                        (name.size() == 4 && ::strncasecmp(name.data(), ".git", 4) == 0);
    if (unsafe) {
      throw InfraError(fmt::format("refusing tree entry '{}' under '{}' in commit {} of {}",
                                   shown(name), shown(parent), to_hex(commit_id), where));
    }
  }

  void make_directory(const std::string& rel) const {
    if (::mkdir((dir / rel).c_str(), 0755) != 0) fail_io("cannot create directory", rel);
  }

  void write_bytes(const std::string& rel, std::string_view bytes, bool executable) const {
    const fs::path target = dir / rel;
    const int fd = ::open(target.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW,
                          executable ? 0755 : 0644);
    if (fd < 0) fail_io("cannot create", rel);
    while (!bytes.empty()) {
      const ssize_t n = ::write(fd, bytes.data(), bytes.size());
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) {
        ::close(fd);
        fail_io("cannot write", rel);
      }
      bytes.remove_prefix(static_cast<std::size_t>(n));
    }
    if (::close(fd) != 0) fail_io("cannot write", rel);
  }

  BlobPtr blob_of(const git_tree_entry* entry, const std::string& rel) const {
    BlobPtr blob;
    check(git_blob_lookup(blob.out(), repo, git_tree_entry_id(entry)),
          fmt::format("reading '{}' of commit {} in {}", shown(rel), to_hex(commit_id), where));
    return blob;
  }

  void write_file(const git_tree_entry* entry, const std::string& rel, bool executable) const {
    BlobPtr blob = blob_of(entry, rel);
    git_blob_filter_options options = GIT_BLOB_FILTER_OPTIONS_INIT;
    // The default options carry GIT_BLOB_FILTER_CHECK_FOR_BINARY, with which libgit2 hands back
    // an EMPTY buffer for a blob that looks binary: textures and test images came out 0 bytes.
    // Without it the filters decide as `git checkout` does (text=auto leaves binary alone).
    options.flags &= ~static_cast<std::uint32_t>(GIT_BLOB_FILTER_CHECK_FOR_BINARY);
    options.flags |= GIT_BLOB_FILTER_ATTRIBUTES_FROM_COMMIT;
    git_oid_cpy(&options.attr_commit_id, &commit_id);
    Buf filtered;
    check(git_blob_filter(filtered.out(), blob.get(), rel.c_str(), &options),
          fmt::format("filtering '{}' of commit {} in {}", shown(rel), to_hex(commit_id), where));
    write_bytes(rel, filtered.str(), executable);
  }

  void write_symlink(const git_tree_entry* entry, const std::string& rel) const {
    BlobPtr blob = blob_of(entry, rel);
    const std::string link_target(static_cast<const char*>(git_blob_rawcontent(blob.get())),
                                  static_cast<std::size_t>(git_blob_rawsize(blob.get())));
    if (::symlink(link_target.c_str(), (dir / rel).c_str()) != 0)
      fail_io("cannot create symlink", rel);
  }

  void write_tree(git_tree* tree, const std::string& prefix) {
    const std::size_t count = git_tree_entrycount(tree);
    for (std::size_t i = 0; i < count; ++i) {
      const git_tree_entry* entry = git_tree_entry_byindex(tree, i);
      const std::string_view name = git_tree_entry_name(entry);
      check_name(name, prefix);
      write_entry(entry, prefix + std::string(name));
    }
  }

  void write_entry(const git_tree_entry* entry, const std::string& rel) {
    switch (git_tree_entry_filemode(entry)) {
      case GIT_FILEMODE_TREE: {
        make_directory(rel);
        TreePtr subtree;
        check(git_tree_lookup(subtree.out(), repo, git_tree_entry_id(entry)),
              fmt::format("reading directory '{}' of commit {} in {}", shown(rel),
                          to_hex(commit_id), where));
        write_tree(subtree.get(), rel + "/");
        return;
      }
      case GIT_FILEMODE_BLOB: write_file(entry, rel, false); return;
      case GIT_FILEMODE_BLOB_EXECUTABLE: write_file(entry, rel, true); return;
      case GIT_FILEMODE_LINK: write_symlink(entry, rel); return;
      case GIT_FILEMODE_COMMIT:
        make_directory(rel);
        gitlinks.push_back(Gitlink{rel, *git_tree_entry_id(entry)});
        return;
      default:
        throw InfraError(fmt::format("unsupported file mode {:o} of '{}' in commit {} of {}",
                                     static_cast<unsigned>(git_tree_entry_filemode(entry)),
                                     shown(rel), to_hex(commit_id), where));
    }
  }
};

}  // namespace

std::vector<Gitlink> write_commit_tree(git_repository* repo, git_commit* commit,
                                       const fs::path& dir, std::string_view where) {
  TreeWriter writer{repo, *git_commit_id(commit), dir, std::string(where), {}};
  TreePtr tree;
  check(git_commit_tree(tree.out(), commit),
        fmt::format("reading the tree of commit {} in {}", to_hex(writer.commit_id), where));
  writer.write_tree(tree.get(), "");
  return std::move(writer.gitlinks);
}

}  // namespace raygate::git
