#include "checkout/git_fixture.h"

#include <sys/stat.h>

#include <fstream>

#include "core/error.h"

namespace fs = std::filesystem;

namespace raygate::testing {
namespace {

// libgit2 wants a git_strarray of patterns; "*" means everything.
struct AllPaths {
  char star[2] = {'*', '\0'};
  char* strings[1] = {star};
  git_strarray array{strings, 1};
};

}  // namespace

GitFixture::GitFixture(const fs::path& dir) : path_(fs::absolute(dir)) {
  fs::create_directories(path_);
  git_repository_init_options options = GIT_REPOSITORY_INIT_OPTIONS_INIT;
  options.flags = GIT_REPOSITORY_INIT_MKPATH;
  options.initial_head = "main";
  git::check(git_repository_init_ext(repo_.out(), path_.c_str(), &options),
             "initialising a test repository in " + path_.string());
}

std::string GitFixture::url() const { return "file://" + path_.string(); }

void GitFixture::write(const std::string& relative, std::string_view content, bool executable) {
  const fs::path file = path_ / relative;
  fs::create_directories(file.parent_path());
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(content.data(), static_cast<std::streamsize>(content.size()));
  out.close();
  if (!out) throw InfraError("fixture cannot write " + file.string());
  ::chmod(file.c_str(), executable ? 0755 : 0644);
}

void GitFixture::write_symlink(const std::string& relative, const std::string& target) {
  const fs::path link = path_ / relative;
  fs::create_directories(link.parent_path());
  fs::remove(link);
  fs::create_symlink(target, link);
}

void GitFixture::remove(const std::string& relative) { fs::remove_all(path_ / relative); }

git::SignaturePtr GitFixture::signature(const std::string& name, std::int64_t time,
                                        int offset) const {
  git::SignaturePtr sig;
  git::check(git_signature_new(sig.out(), name.c_str(), "tester@raygate.invalid", time, offset),
             "making a test signature");
  return sig;
}

git::ObjectPtr GitFixture::commit_object(const std::string& revspec) const {
  git::ObjectPtr object;
  git::check(git_revparse_single(object.out(), repo_.get(), (revspec + "^{commit}").c_str()),
             "fixture resolving " + revspec);
  return object;
}

std::string GitFixture::commit(const std::string& message, const CommitOptions& options) {
  git::IndexPtr index;
  git::check(git_repository_index(index.out(), repo_.get()), "opening the fixture's index");
  AllPaths all;
  git::check(git_index_add_all(index.get(), &all.array, GIT_INDEX_ADD_DEFAULT, nullptr, nullptr),
             "staging the fixture's files");
  git::check(git_index_update_all(index.get(), &all.array, nullptr, nullptr),
             "staging the fixture's removals");
  for (const auto& [relative, pin] : submodules_) {
    git_index_entry entry{};
    entry.mode = GIT_FILEMODE_COMMIT;
    entry.path = relative.c_str();
    git::check(git_oid_fromstr(&entry.id, pin.second.c_str()), "parsing pin " + pin.second);
    git::check(git_index_add(index.get(), &entry), "staging submodule " + relative);
  }
  git::check(git_index_write(index.get()), "writing the fixture's index");
  git_oid tree_id;
  git::check(git_index_write_tree(&tree_id, index.get()), "writing the fixture's tree");
  git::TreePtr tree;
  git::check(git_tree_lookup(tree.out(), repo_.get(), &tree_id), "reading the fixture's tree");

  clock_ = options.time != 0 ? options.time : clock_ + 60;
  const git::SignaturePtr author = signature(options.author, clock_, options.offset_minutes);

  std::vector<git::ObjectPtr> parents;
  git::ObjectPtr head;
  if (!options.root && git_revparse_single(head.out(), repo_.get(), "HEAD^{commit}") == 0) {
    parents.push_back(std::move(head));
  }
  git_error_clear();
  for (const std::string& sha : options.merge_parents) parents.push_back(commit_object(sha));
  std::vector<const git_commit*> raw_parents;
  for (const auto& parent : parents)
    raw_parents.push_back(reinterpret_cast<const git_commit*>(parent.get()));

  // HEAD is rewritten after the fact for root commits: git_commit_create insists that the
  // first parent is the current tip when it updates a ref.
  const char* update_ref = options.root ? nullptr : "HEAD";
  const std::string text = message.empty() || message.back() != '\n' ? message + "\n" : message;
  git_oid id;
  const char* encoding = options.encoding.empty() ? nullptr : options.encoding.c_str();
  git::check(git_commit_create(&id, repo_.get(), update_ref, author.get(), author.get(), encoding,
                               text.c_str(), tree.get(), raw_parents.size(), raw_parents.data()),
             "committing '" + message + "' in the fixture");
  if (options.root) {
    git::ReferencePtr head_ref;
    git::check(git_repository_head(head_ref.out(), repo_.get()), "reading the fixture's HEAD");
    git::ReferencePtr moved;
    git::check(git_reference_set_target(moved.out(), head_ref.get(), &id, "fixture root commit"),
               "moving the fixture's branch");
  }
  return git::to_hex(id);
}

void GitFixture::branch(const std::string& name, const std::string& at) {
  const git::ObjectPtr target = commit_object(at);
  git::ReferencePtr ref;
  git::check(git_branch_create(ref.out(), repo_.get(), name.c_str(),
                               reinterpret_cast<const git_commit*>(target.get()), 1),
             "creating branch " + name);
}

void GitFixture::switch_to(const std::string& name) {
  const git::ObjectPtr target = commit_object("refs/heads/" + name);
  git_checkout_options options = GIT_CHECKOUT_OPTIONS_INIT;
  options.checkout_strategy = GIT_CHECKOUT_FORCE | GIT_CHECKOUT_REMOVE_UNTRACKED;
  git::check(git_checkout_tree(repo_.get(), target.get(), &options), "checking out " + name);
  git::check(git_repository_set_head(repo_.get(), ("refs/heads/" + name).c_str()),
             "switching HEAD to " + name);
}

void GitFixture::tag(const std::string& name, const std::string& at) {
  const git::ObjectPtr target = commit_object(at);
  git_oid id;
  git::check(git_tag_create_lightweight(&id, repo_.get(), name.c_str(), target.get(), 0),
             "creating tag " + name);
}

void GitFixture::annotated_tag(const std::string& name, const std::string& message,
                               const std::string& at) {
  const git::ObjectPtr target = commit_object(at);
  const git::SignaturePtr tagger = signature("Tag Maker", clock_, 0);
  git_oid id;
  git::check(git_tag_create(&id, repo_.get(), name.c_str(), target.get(), tagger.get(),
                            message.c_str(), 0),
             "creating annotated tag " + name);
}

void GitFixture::set_submodule(const std::string& relative, const std::string& url,
                               const std::string& sha) {
  submodules_[relative] = {url, sha};
  std::string text;
  for (const auto& [path, pin] : submodules_) {
    text += "[submodule \"" + path + "\"]\n\tpath = " + path + "\n\turl = " + pin.first + "\n";
  }
  write(".gitmodules", text);
}

std::string GitFixture::sha(const std::string& revspec) const {
  const git::ObjectPtr object = commit_object(revspec);
  return git::to_hex(*git_object_id(object.get()));
}

}  // namespace raygate::testing
