// Revision resolution: any revspec git understands (branch, tag, sha, HEAD~3, origin/main) to a
// commit, with errors the user can act on (an unknown name lists the branches and tags).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "checkout/git_handle.h"

namespace raygate::git {

struct ResolvedCommit {
  CommitPtr commit;
  std::string ref_name;  // full name of the ref the revspec named, if any; valid UTF-8 (repaired)
};

// Resolves `revspec` in `repo`, peeling tags to their commit. `where` names the repository in
// messages. When the revspec names nothing and `fallback_prefix` is set ("origin/"), the
// prefixed spec is tried too: a cached clone keeps branches only as remote-tracking refs.
// Throws UsageError for unknown, ambiguous or non-commit revisions, InfraError otherwise.
ResolvedCommit resolve_commit(git_repository* repo, const std::string& revspec,
                              std::string_view where, std::string_view fallback_prefix = {});

// Looks a commit up by its full sha (InfraError when missing).
CommitPtr lookup_commit(git_repository* repo, const git_oid& id, std::string_view where);

// Short names of branches (remote ones as "origin/x") and of tags, sorted, as valid UTF-8;
// for messages.
std::vector<std::string> branch_names(git_repository* repo);
std::vector<std::string> tag_names(git_repository* repo);

}  // namespace raygate::git
