// Turns a libgit2 commit into raygate's Revision record (sha, subject, author, ISO-8601 time).
#pragma once

#include <cstdint>
#include <string>

#include "checkout/git_handle.h"
#include "checkout/worktree.h"

namespace raygate::git {

Revision describe_commit(git_commit* commit, std::string revision, std::string ref_name);

// "2023-11-14T22:13:20+01:00" for seconds since the epoch shown at a UTC offset in minutes.
std::string iso8601(std::int64_t seconds, int offset_minutes);

}  // namespace raygate::git
