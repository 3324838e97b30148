#include "checkout/git_handle.h"

#include "core/error.h"

namespace raygate::git {
namespace {

void init_or_throw() {
  if (git_libgit2_init() < 0) {
    throw InfraError("initialising libgit2: " + last_error_message());
  }
}

}  // namespace

Library::Library() { init_or_throw(); }
Library::Library(const Library&) { init_or_throw(); }
Library::~Library() { git_libgit2_shutdown(); }

std::string last_error_message() {
  const git_error* error = git_error_last();
  if (error == nullptr || error->message == nullptr) return "unknown libgit2 error";
  return error->message;
}

int check(int rc, std::string_view doing) {
  if (rc >= 0) return rc;
  throw InfraError(std::string(doing) + ": " + last_error_message());
}

std::string to_hex(const git_oid& oid) {
  char hex[GIT_OID_HEXSZ + 1];
  git_oid_tostr(hex, sizeof hex, &oid);
  return hex;
}

}  // namespace raygate::git
