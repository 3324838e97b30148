// Turns a libgit2 commit into raygate's Revision record (sha, subject, author, ISO-8601 time).
// The record's text is always valid UTF-8 (core/utf8.h): a commit's bytes are whatever its
// author's editor wrote, and the results document, the store and JSON output need UTF-8.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "checkout/git_handle.h"
#include "checkout/worktree.h"

namespace raygate::git {

// Every text field is valid UTF-8: subject and author decoded as ISO-8859-1 when the commit
// declares that encoding (i18n.commitEncoding), otherwise with invalid sequences replaced by
// U+FFFD, as are `revision` and `ref_name`. Never refuses a commit for its bytes.
Revision describe_commit(git_commit* commit, std::string revision, std::string ref_name);

// Text taken from `commit` (its message or a signature's name) as valid UTF-8, by the rule
// describe_commit follows. Other declared encodings than Latin-1 are repaired, not decoded.
std::string commit_text(git_commit* commit, std::string_view bytes);

// "2023-11-14T22:13:20+01:00" for seconds since the epoch shown at a UTC offset in minutes.
std::string iso8601(std::int64_t seconds, int offset_minutes);

}  // namespace raygate::git
