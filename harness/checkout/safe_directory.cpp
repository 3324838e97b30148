#include "checkout/safe_directory.h"

namespace fs = std::filesystem;

namespace raygate {
namespace {

std::string without_trailing_slash(std::string path) {
  while (path.size() > 1 && path.back() == '/') path.pop_back();
  return path;
}

// The values of one config level, in file order; nothing when that file does not exist.
void append_level(git_config* all, git_config_level_t level, std::vector<std::string>& out) {
  git::ConfigPtr config;
  if (git_config_open_level(config.out(), all, level) < 0) {
    git_error_clear();  // no file at this level
    return;
  }
  git::ConfigIteratorPtr values;
  if (git_config_multivar_iterator_new(values.out(), config.get(), "safe.directory", nullptr) < 0) {
    git_error_clear();
    return;
  }
  git_config_entry* entry = nullptr;
  while (git_config_next(&entry, values.get()) == 0) out.emplace_back(entry->value);
  git_error_clear();  // GIT_ITEROVER
}

}  // namespace

std::string repository_root(git_repository* repo) {
  const char* workdir = git_repository_workdir(repo);
  return without_trailing_slash(workdir != nullptr ? workdir : git_repository_path(repo));
}

std::optional<std::string> refused_for_ownership(const fs::path& path, int rc) {
  if (rc != GIT_ENOTFOUND && rc != GIT_EOWNER) return std::nullopt;
  int validating = 1;
  git_libgit2_opts(GIT_OPT_GET_OWNER_VALIDATION, &validating);
  if (validating == 0) return std::nullopt;
  git_libgit2_opts(GIT_OPT_SET_OWNER_VALIDATION, 0);
  git::RepositoryPtr repo;
  const int unchecked = git_repository_open_ext(repo.out(), path.c_str(), 0, nullptr);
  git_libgit2_opts(GIT_OPT_SET_OWNER_VALIDATION, 1);
  if (unchecked < 0) return std::nullopt;
  return repository_root(repo.get());
}

bool safe_directory_trusts(const std::vector<std::string>& values, const std::string& root) {
  bool trusted = false;
  const std::string wanted = without_trailing_slash(root);
  for (const std::string& value : values) {
    if (value.empty()) {
      trusted = false;
    } else if (value == "*" || without_trailing_slash(value) == wanted) {
      trusted = true;
    }
  }
  return trusted;
}

std::vector<std::string> protected_safe_directories() {
  std::vector<std::string> values;
  git::ConfigPtr all;
  if (git_config_open_default(all.out()) < 0) {
    git_error_clear();
    return values;
  }
  for (const git_config_level_t level :
       {GIT_CONFIG_LEVEL_SYSTEM, GIT_CONFIG_LEVEL_XDG, GIT_CONFIG_LEVEL_GLOBAL}) {
    append_level(all.get(), level, values);
  }
  return values;
}

int open_repository_as_git_does(git::RepositoryPtr& repo, const fs::path& path) {
  const int rc = git_repository_open_ext(repo.out(), path.c_str(), 0, nullptr);
  const std::optional<std::string> root = refused_for_ownership(path, rc);
  if (!root || !safe_directory_trusts(protected_safe_directories(), *root)) return rc;
  git_error_clear();
  git_libgit2_opts(GIT_OPT_SET_OWNER_VALIDATION, 0);
  const int trusted = git_repository_open_ext(repo.out(), path.c_str(), 0, nullptr);
  git_libgit2_opts(GIT_OPT_SET_OWNER_VALIDATION, 1);
  return trusted;
}

}  // namespace raygate
