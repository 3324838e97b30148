// A repository's identity from its history (the root commit) or its origin URL.
#include "checkout/repository_identity.h"

#include <algorithm>
#include <cctype>

#include "checkout/git_handle.h"
#include "checkout/remote_cache.h"
#include "checkout/safe_directory.h"
#include "core/utf8.h"

namespace raygate {

namespace {

// libgit2 failures here only mean "unknown": clear them so no later message reports them.
std::string unknown() {
  git_error_clear();
  return {};
}

git::RepositoryPtr open_repository(const std::string& location,
                                   const std::filesystem::path& cache_dir) {
  git::RepositoryPtr repo;
  if (is_url(location)) {
    const std::filesystem::path clone =
        clone_cache_path(std::filesystem::absolute(cache_dir), location);
    if (git_repository_open_bare(repo.out(), clone.c_str()) < 0) repo.reset();
  } else if (open_repository_as_git_does(repo, location) < 0) {
    repo.reset();
  }
  return repo;
}

// Follows first parents: a merge of an unrelated history keeps the mainline's root.
std::string first_parent_root(git_repository* repo, const std::string& sha) {
  git_oid id;
  if (sha.size() != GIT_OID_HEXSZ || git_oid_fromstr(&id, sha.c_str()) < 0) return unknown();
  git::CommitPtr commit;
  if (git_commit_lookup(commit.out(), repo, &id) < 0) return unknown();
  while (git_commit_parentcount(commit.get()) > 0) {
    git::CommitPtr parent;
    if (git_commit_parent(parent.out(), commit.get(), 0) < 0) return unknown();
    commit = std::move(parent);
  }
  return git::to_hex(*git_commit_id(commit.get()));
}

std::string origin_url(git_repository* repo) {
  git::RemotePtr remote;
  if (git_remote_lookup(remote.out(), repo, "origin") < 0) return unknown();
  const char* url = git_remote_url(remote.get());
  return url != nullptr ? repaired_utf8(url) : "";  // a config value: bytes, like any other
}

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

std::string without_suffixes(std::string path) {
  while (!path.empty() && path.back() == '/') path.pop_back();
  if (path.ends_with(".git")) path.resize(path.size() - 4);
  while (!path.empty() && path.back() == '/') path.pop_back();
  return path;
}

}  // namespace

std::string repository_identity(const std::string& location, const std::string& sha,
                                const std::filesystem::path& cache_dir) {
  const git::Library library;
  const git::RepositoryPtr repo = open_repository(location, cache_dir);
  if (!repo) return unknown();
  if (git_repository_is_shallow(repo.get()) == 1) {
    const std::string url = origin_url(repo.get());
    return url.empty() ? std::string() : "url:" + normalize_remote_url(url);
  }
  const std::string root = first_parent_root(repo.get(), sha);
  return root.empty() ? std::string() : "root:" + root;
}

std::string normalize_remote_url(std::string_view url) {
  std::string text(url);
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
  std::string host;
  std::string path;
  if (const std::size_t scheme = text.find("://"); scheme != std::string::npos) {
    const std::string rest = text.substr(scheme + 3);
    const std::size_t slash = rest.find('/');
    host = rest.substr(0, slash);
    path = slash == std::string::npos ? "" : rest.substr(slash);
  } else if (is_url(text)) {  // scp-like: [user@]host:path
    const std::size_t colon = text.find(':');
    host = text.substr(0, colon);
    path = text.substr(colon + 1);
  } else {
    return without_suffixes(text);
  }
  if (const std::size_t at = host.rfind('@'); at != std::string::npos) host.erase(0, at + 1);
  path = without_suffixes(path);
  if (host.empty()) return path;  // file:///srv/tracer
  return lower(host) + (path.empty() || path.front() == '/' ? "" : "/") + path;
}

}  // namespace raygate
