#include "checkout/resolve.h"

#include <fmt/format.h>

#include <algorithm>

#include "core/error.h"
#include "core/utf8.h"

namespace raygate::git {
namespace {

constexpr std::size_t kNamesShown = 10;

bool names_nothing(int rc) { return rc == GIT_ENOTFOUND || rc == GIT_EINVALIDSPEC; }

// "main, dev, v1" or "none"; long lists end with "and 12 more".
std::string list_for_message(const std::vector<std::string>& names) {
  if (names.empty()) return "none";
  std::string out;
  for (std::size_t i = 0; i < names.size() && i < kNamesShown; ++i) {
    if (i > 0) out += ", ";
    out += names[i];
  }
  if (names.size() > kNamesShown) out += fmt::format(" and {} more", names.size() - kNamesShown);
  return out;
}

// A shallow clone (CI checkouts are, by default) lacks older commits: say so, since "unknown
// revision" alone sends the user looking for a typo in a sha that is right.
std::string shallow_note(git_repository* repo) {
  if (git_repository_is_shallow(repo) != 1) return "";
  return "; the clone is shallow, so older commits are missing: fetch them with "
         "`git fetch --unshallow` (in GitHub Actions: actions/checkout with fetch-depth: 0)";
}

[[noreturn]] void throw_unknown(git_repository* repo, const std::string& revspec,
                                std::string_view where) {
  throw UsageError(fmt::format(
      "unknown revision '{}' in {} (branches: {}; tags: {}); give a branch, tag or commit sha{}",
      revspec, where, list_for_message(branch_names(repo)), list_for_message(tag_names(repo)),
      shallow_note(repo)));
}

int revparse(ObjectPtr& object, ReferencePtr& ref, git_repository* repo, const std::string& spec) {
  return git_revparse_ext(object.out(), ref.out(), repo, spec.c_str());
}

// Past any name git gives a commit (a ref is a file path; PATH_MAX is 4096): such a revision is
// refused before libgit2 sees it, which otherwise fails on the path it makes of it, an error
// that is not the user's own ("exit 3") and that echoed all of it back, twice.
constexpr std::size_t kMaxRevisionChars = 4096;

void check_revision_text(const std::string& revspec, std::string_view where) {
  const bool control = std::any_of(revspec.begin(), revspec.end(), [](char c) {
    return static_cast<unsigned char>(c) < 0x20 || c == 0x7f;
  });
  if (revspec.size() <= kMaxRevisionChars && !control) return;
  const std::string shown = repaired_utf8(revspec.substr(0, 60));
  throw UsageError(fmt::format(
      "revision '{}{}' ({} characters) cannot name anything in {}: {}; give a branch, tag or "
      "commit sha",
      shown, revspec.size() > 60 ? "..." : "", revspec.size(), where,
      control ? "it holds a control character" : "a revision is at most 4096 characters"));
}

}  // namespace

ResolvedCommit resolve_commit(git_repository* repo, const std::string& revspec,
                              std::string_view where, std::string_view fallback_prefix) {
  if (revspec.empty()) throw_unknown(repo, revspec, where);
  check_revision_text(revspec, where);
  ObjectPtr object;
  ReferencePtr ref;
  int rc = revparse(object, ref, repo, revspec);
  if (names_nothing(rc) && !fallback_prefix.empty()) {
    rc = revparse(object, ref, repo, std::string(fallback_prefix) + revspec);
  }
  if (names_nothing(rc)) throw_unknown(repo, revspec, where);
  if (rc == GIT_EAMBIGUOUS) {
    throw UsageError(
        fmt::format("revision '{}' is ambiguous in {} ({}); give more digits of the sha", revspec,
                    where, last_error_message()));
  }
  check(rc, fmt::format("resolving '{}' in {}", revspec, where));

  ObjectPtr peeled;
  if (git_object_peel(peeled.out(), object.get(), GIT_OBJECT_COMMIT) < 0) {
    throw UsageError(fmt::format("revision '{}' in {} names a {}, not a commit", revspec, where,
                                 git_object_type2string(git_object_type(object.get()))));
  }
  ResolvedCommit out;
  out.commit.reset(reinterpret_cast<git_commit*>(peeled.release()));
  if (ref) out.ref_name = repaired_utf8(git_reference_name(ref.get()));
  return out;
}

CommitPtr lookup_commit(git_repository* repo, const git_oid& id, std::string_view where) {
  CommitPtr commit;
  const int rc = git_commit_lookup(commit.out(), repo, &id);
  if (rc == GIT_ENOTFOUND && git_repository_is_shallow(repo) == 1) {
    throw UsageError(
        fmt::format("commit {} is not in {}{}", to_hex(id), where, shallow_note(repo)));
  }
  check(rc, fmt::format("looking up commit {} in {}", to_hex(id), where));
  return commit;
}

std::vector<std::string> branch_names(git_repository* repo) {
  std::vector<std::string> names;
  BranchIteratorPtr it;
  if (git_branch_iterator_new(it.out(), repo, GIT_BRANCH_ALL) < 0) return names;
  git_reference* raw = nullptr;
  git_branch_t type{};
  while (git_branch_next(&raw, &type, it.get()) == 0) {
    ReferencePtr ref(raw);
    const char* name = nullptr;
    if (git_branch_name(&name, ref.get()) < 0 || name == nullptr) continue;
    const std::string_view view(name);
    if (view.size() >= 5 && view.substr(view.size() - 5) == "/HEAD") continue;  // origin/HEAD
    names.push_back(repaired_utf8(name));  // ref names are bytes in git
  }
  std::sort(names.begin(), names.end());
  return names;
}

std::vector<std::string> tag_names(git_repository* repo) {
  std::vector<std::string> names;
  StrArray tags;
  if (git_tag_list(tags.out(), repo) < 0) return names;
  for (std::size_t i = 0; i < tags.size(); ++i) names.push_back(repaired_utf8(tags[i]));
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace raygate::git
