// Throwaway git repositories for tests, built with libgit2 alone (no git binary, no network):
// write files, commit with a chosen message and time, branch, tag, pin submodules, and hand the
// repository out by path or by file:// URL. Put one in a raygate::TempDir.
//
//   GitFixture repo(dir.path() / "tracer");
//   repo.write("src/main.cpp", "int main() {}\n");
//   const std::string first = repo.commit("first");
//   repo.tag("v1");
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "checkout/git_handle.h"

namespace raygate::testing {

struct CommitOptions {
  std::int64_t time = 0;   // seconds since the epoch; 0: one minute after the last commit
  int offset_minutes = 0;  // the author's UTC offset
  std::string author = "Ada Tester";
  std::vector<std::string> merge_parents = {};  // shas after HEAD: makes a merge commit
  bool root = false;  // no parents at all: starts an unrelated history on HEAD's branch
  // The commit's "encoding" header, as git writes it with i18n.commitEncoding; the message and
  // author bytes are stored as given, so a Latin-1 commit is written with Latin-1 bytes.
  std::string encoding = "";
};

class GitFixture {
 public:
  // Initialises a non-bare repository in `dir` (created), HEAD on the unborn branch "main".
  explicit GitFixture(const std::filesystem::path& dir);

  const std::filesystem::path& path() const { return path_; }
  std::string url() const;  // "file:///..." for the clone-by-URL path
  git_repository* raw() const { return repo_.get(); }

  // Working-tree edits; they are staged by the next commit().
  void write(const std::string& relative, std::string_view content, bool executable = false);
  void remove(const std::string& relative);
  // A symbolic link at `relative` pointing at `target` (not resolved; may dangle).
  void write_symlink(const std::string& relative, const std::string& target);

  // Stages the whole working tree (like `git add -A`, plus the submodule pins) and commits on
  // HEAD's branch. Returns the new commit's sha.
  std::string commit(const std::string& message, const CommitOptions& options = {});

  void branch(const std::string& name, const std::string& at = "HEAD");  // creates or moves
  // HEAD to refs/heads/<name>; index and working tree follow (uncommitted edits are lost).
  void switch_to(const std::string& name);
  void tag(const std::string& name, const std::string& at = "HEAD");
  void annotated_tag(const std::string& name, const std::string& message,
                     const std::string& at = "HEAD");

  // Pins the submodule at `relative` to `sha`: a gitlink in the next commit, and an entry with
  // `url` (absolute, or relative like "../sub") in .gitmodules, rewritten in the working tree.
  void set_submodule(const std::string& relative, const std::string& url, const std::string& sha);

  std::string sha(const std::string& revspec) const;  // full sha of the commit it names

 private:
  git::ObjectPtr commit_object(const std::string& revspec) const;
  git::SignaturePtr signature(const std::string& name, std::int64_t time, int offset) const;

  git::Library library_;
  git::RepositoryPtr repo_;
  std::filesystem::path path_;
  std::int64_t clock_ = 1700000000;                                        // 2023-11-14T22:13:20Z
  std::map<std::string, std::pair<std::string, std::string>> submodules_;  // path -> url, sha
};

}  // namespace raygate::testing
