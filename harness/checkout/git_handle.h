// RAII over libgit2: one owning handle type per libgit2 object kind, a guard that keeps the
// library initialised while anything uses it, and the one place where libgit2's integer
// failures become exceptions that say what raygate was doing and what libgit2 said.
#pragma once

#include <git2.h>

#include <cstddef>
#include <string>
#include <string_view>
#include <utility>

namespace raygate::git {

// libgit2 counts init/shutdown calls, so every owner of libgit2 state (a Repository, a test
// fixture) holds one of these as its first member: the library outlives the handles declared
// after it, and no process-wide global is needed.
class Library {
 public:
  Library();
  ~Library();
  Library(const Library& other);
  Library& operator=(const Library&) { return *this; }  // both already count one reference
};

// Owns one libgit2 pointer and frees it with Free. Move-only.
template <typename T, void (*Free)(T*)>
class Handle {
 public:
  Handle() = default;
  explicit Handle(T* raw) : raw_(raw) {}
  Handle(Handle&& other) noexcept : raw_(std::exchange(other.raw_, nullptr)) {}
  Handle& operator=(Handle&& other) noexcept {
    if (this != &other) reset(std::exchange(other.raw_, nullptr));
    return *this;
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  ~Handle() { reset(); }

  T* get() const { return raw_; }
  explicit operator bool() const { return raw_ != nullptr; }
  // For libgit2's `T** out` parameters: frees what was held and hands out the slot.
  T** out() {
    reset();
    return &raw_;
  }
  // Gives up ownership (for handing the pointer to another handle type).
  T* release() { return std::exchange(raw_, nullptr); }
  void reset(T* raw = nullptr) {
    if (raw_ != nullptr) Free(raw_);
    raw_ = raw;
  }

 private:
  T* raw_ = nullptr;
};

using RepositoryPtr = Handle<git_repository, &git_repository_free>;
using ObjectPtr = Handle<git_object, &git_object_free>;
using CommitPtr = Handle<git_commit, &git_commit_free>;
using TreePtr = Handle<git_tree, &git_tree_free>;
using TreeEntryPtr = Handle<git_tree_entry, &git_tree_entry_free>;
using BlobPtr = Handle<git_blob, &git_blob_free>;
using TagPtr = Handle<git_tag, &git_tag_free>;
using ReferencePtr = Handle<git_reference, &git_reference_free>;
using RevwalkPtr = Handle<git_revwalk, &git_revwalk_free>;
using RemotePtr = Handle<git_remote, &git_remote_free>;
using SubmodulePtr = Handle<git_submodule, &git_submodule_free>;
using IndexPtr = Handle<git_index, &git_index_free>;
using ConfigPtr = Handle<git_config, &git_config_free>;
using ConfigIteratorPtr = Handle<git_config_iterator, &git_config_iterator_free>;
using BranchIteratorPtr = Handle<git_branch_iterator, &git_branch_iterator_free>;
using StatusListPtr = Handle<git_status_list, &git_status_list_free>;
using SignaturePtr = Handle<git_signature, &git_signature_free>;
using TreeBuilderPtr = Handle<git_treebuilder, &git_treebuilder_free>;

// Owns a struct the caller provides and libgit2 fills in place (git_buf, git_strarray), and
// disposes of what libgit2 put in it with Dispose. Neither copied nor moved: libgit2 writes
// through the address out() hands it.
template <typename T, void (*Dispose)(T*)>
class Disposed {
 public:
  Disposed() = default;
  ~Disposed() { Dispose(&value_); }
  Disposed(const Disposed&) = delete;
  Disposed& operator=(const Disposed&) = delete;
  T* out() { return &value_; }

 protected:
  const T& value() const { return value_; }

 private:
  T value_{};  // all zero, as GIT_BUF_INIT and an empty git_strarray are
};

class Buf : public Disposed<git_buf, &git_buf_dispose> {
 public:
  std::string str() const {
    return value().ptr == nullptr ? std::string() : std::string(value().ptr, value().size);
  }
};

class StrArray : public Disposed<git_strarray, &git_strarray_dispose> {
 public:
  std::size_t size() const { return value().count; }
  std::string_view operator[](std::size_t i) const { return value().strings[i]; }
};

// libgit2's message for the last failure on this thread; git_error_last() may be NULL.
std::string last_error_message();

// Throws InfraError("<doing>: <libgit2's message>") when rc < 0; returns rc otherwise.
int check(int rc, std::string_view doing);

// The 40-hex form of an object id.
std::string to_hex(const git_oid& oid);

}  // namespace raygate::git
