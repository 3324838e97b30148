// Which repository a measured commit came from, told apart from every other tracer's repository
// however it was reached (a local path, a clone by URL, a CI checkout elsewhere): the results
// store keeps one history series per repository (results/series.h), so two tracers' commits never
// share a trend.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace raygate {

// "root:<sha>" for the root commit reached from `sha` along first parents (the same for every
// clone of a history); "url:<normalized origin URL>" when the history is shallow (a CI checkout
// with fetch-depth 1 has no real root); "" when neither can be told (not a git repository, an
// uncommitted tree on an unborn HEAD, a commit missing from the repository). `location` is a
// path or a URL as Repository::open takes it; a URL's cached clone is opened, never fetched.
// Never throws: an identity raygate cannot work out must not fail a measurement.
std::string repository_identity(const std::string& location, const std::string& sha,
                                const std::filesystem::path& cache_dir);

// A remote URL in one spelling for every way of writing it: no scheme, user or password, host
// lower-cased, no trailing ".git" or "/", scp-like "git@host:a/b" as "host/a/b". So
// "https://GitHub.com/a/b.git" and "git@github.com:a/b" are both "github.com/a/b".
std::string normalize_remote_url(std::string_view url);

}  // namespace raygate
