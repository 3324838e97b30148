// Repositories raygate reaches by URL (a --repo URL, a submodule's URL) live as bare clones in
// the cache, one per URL: cloned once, fetched when they may be stale. Remote branches are kept
// as remote-tracking refs (origin/main), tags as tags, HEAD at origin's default branch.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "checkout/git_handle.h"

namespace raygate {

// True when `location` is something to clone rather than a directory to open: it has a scheme
// ("https://", "ssh://", "file://") or is scp-like ("git@host:path", a ':' before any '/').
bool is_url(std::string_view location);

// "<cache_dir>/repos/<first 16 hex digits of the URL's SHA-256>".
std::filesystem::path clone_cache_path(const std::filesystem::path& cache_dir,
                                       std::string_view url);

// A submodule URL as git reads it: "./x" and "../x" are relative to the superproject's URL (or
// directory); anything else is returned unchanged. Throws UsageError when "../" climbs too far.
std::string resolve_relative_url(std::string_view url, std::string_view base);

enum class Fetch { always, never };

// Opens the cached bare clone of `url`, cloning it first when absent. With Fetch::always an
// existing clone is brought up to date (branches, tags, pruning deleted branches). Clones and
// fetches hold the entry's FileLock. Throws InfraError naming the URL when git fails.
git::RepositoryPtr open_cached_clone(const std::filesystem::path& cache_dir, const std::string& url,
                                     Fetch fetch);

}  // namespace raygate
