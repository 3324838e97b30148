// Every kind of entry a git tree can hold, committed and checked out byte for byte: binary
// blobs (once written empty: libgit2's default blob filter options hand back nothing for
// them), executables, symlinks, CRLF text by .gitattributes, a Git LFS pointer, an empty file
// and a file of several MiB. Also: a tree cached by a raygate with that bug is not trusted.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdint>
#include <string>

#include "checkout/git_fixture.h"
#include "checkout/repository.h"
#include "checkout/tree_stamp.h"
#include "core/fs.h"

namespace fs = std::filesystem;

namespace raygate {
namespace {

// The first bytes of a PNG file: a signature with CR LF, LF and 0x1A in it, then a chunk
// with NUL bytes. A text filter that touched it would change its line ends.
std::string png_like_bytes() {
  static constexpr char kHeader[] =
      "\x89PNG\r\n\x1a\n\0\0\0\rIHDR\0\0\0\x10\0\0\0\x10\x08\x06\0\0\0\x1f\xf3\xff"
      "a";
  std::string bytes(kHeader, sizeof(kHeader) - 1);
  for (int i = 0; i < 64; ++i) bytes.push_back(static_cast<char>(i * 37));
  bytes += "\r\n\n\r end";
  return bytes;
}

// `size_bytes` of deterministic, incompressible-looking bytes, NUL and CR LF among them.
std::string large_bytes(std::size_t size_bytes) {
  std::string bytes(size_bytes, '\0');
  std::uint32_t state = 0x9E3779B9u;
  for (char& b : bytes) {
    state = state * 1664525u + 1013904223u;  // a linear congruential generator: repeatable
    b = static_cast<char>(state >> 24);
  }
  return bytes;
}

constexpr const char* kAttributes =
    "* text=auto eol=crlf\n*.sh text eol=lf\n*.pak filter=lfs diff=lfs merge=lfs -text\n";

constexpr const char* kLfsPointer =
    "version https://git-lfs.github.com/spec/v1\n"
    "oid sha256:4d7a214614ab2935c943f9e0ff69d22eadbb8f32b1258daaa5e2ca24d17e2393\n"
    "size 12345\n";

struct stat lstat_of(const fs::path& path) {
  struct stat info {};
  EXPECT_EQ(::lstat(path.c_str(), &info), 0) << path;
  return info;
}

class CheckoutTreeEntries : public ::testing::Test {
 protected:
  CheckoutTreeEntries() : repo_(dir_.path() / "tracer") {
    // Text is checked out with CRLF, what looks binary is left alone (as `git checkout` does),
    // and LFS files carry the filter git-lfs would install (none here: the pointer stays).
    repo_.write(".gitattributes", kAttributes);
    repo_.write("textures/wood.png", png_like_bytes());
    repo_.write("data/blob.bin", std::string("\0\0\0\0", 4));
    repo_.write("tools/render.sh", "#!/bin/sh\nexec ./tracer \"$@\"\n", true);
    repo_.write_symlink("scenes/current.nff", "../data/teapot.nff");
    repo_.write_symlink("dangling", "does/not/exist");
    repo_.write("notes/readme.txt", "line one\nline two\n");
    repo_.write("assets/model.pak", kLfsPointer);
    repo_.write("empty", "");
    repo_.write("data/large.bin", large_bytes(kLargeBytes));
    sha_ = repo_.commit("every kind of entry");
  }

  Worktree checkout() const {
    return Repository::open(repo_.path().string(), dir_.path() / "cache").checkout(sha_);
  }

  static constexpr std::size_t kLargeBytes = 6u << 20;  // 6 MiB
  TempDir dir_{"raygate-tree-entries"};
  testing::GitFixture repo_;
  std::string sha_;
};

TEST_F(CheckoutTreeEntries, BinaryBlobsAreWrittenByteForByte) {
  const Worktree tree = checkout();
  const std::string png = read_file(tree.path / "textures/wood.png");
  EXPECT_EQ(png.size(), png_like_bytes().size());
  EXPECT_EQ(png, png_like_bytes());
  EXPECT_EQ(read_file(tree.path / "data/blob.bin"), std::string("\0\0\0\0", 4));
}

TEST_F(CheckoutTreeEntries, ALargeFileIsWrittenWhole) {
  const Worktree tree = checkout();
  EXPECT_EQ(fs::file_size(tree.path / "data/large.bin"), kLargeBytes);
  EXPECT_TRUE(read_file(tree.path / "data/large.bin") == large_bytes(kLargeBytes));
}

TEST_F(CheckoutTreeEntries, ExecutablesKeepTheirModeAndOthersDoNotGainIt) {
  const Worktree tree = checkout();
  EXPECT_EQ(lstat_of(tree.path / "tools/render.sh").st_mode & 0111, 0111u);
  EXPECT_EQ(read_file(tree.path / "tools/render.sh"), "#!/bin/sh\nexec ./tracer \"$@\"\n");
  EXPECT_EQ(lstat_of(tree.path / "textures/wood.png").st_mode & 0111, 0u);
  EXPECT_EQ(lstat_of(tree.path / "empty").st_mode & 0111, 0u);
}

TEST_F(CheckoutTreeEntries, SymlinksAreLinksWithTheirTargetEvenDangling) {
  const Worktree tree = checkout();
  ASSERT_TRUE(fs::is_symlink(tree.path / "scenes/current.nff"));
  EXPECT_EQ(fs::read_symlink(tree.path / "scenes/current.nff"), "../data/teapot.nff");
  ASSERT_TRUE(fs::is_symlink(tree.path / "dangling"));
  EXPECT_EQ(fs::read_symlink(tree.path / "dangling"), "does/not/exist");
}

TEST_F(CheckoutTreeEntries, TextFollowsGitattributesEolAndBinaryDoesNot) {
  const Worktree tree = checkout();
  EXPECT_EQ(read_file(tree.path / "notes/readme.txt"), "line one\r\nline two\r\n");
  EXPECT_EQ(read_file(tree.path / ".gitattributes"),
            "* text=auto eol=crlf\r\n*.sh text eol=lf\r\n"
            "*.pak filter=lfs diff=lfs merge=lfs -text\r\n");
  // Under the same "* text=auto eol=crlf" rule, the PNG's LF and CR LF bytes stay as they are.
  EXPECT_EQ(read_file(tree.path / "textures/wood.png"), png_like_bytes());
}

TEST_F(CheckoutTreeEntries, AnLfsPointerIsCheckedOutAsThePointerText) {
  // raygate does not run git-lfs: the tracer's build sees the pointer, as a clone without
  // git-lfs would (docs/checkout.md says to fetch LFS objects another way).
  EXPECT_EQ(read_file(checkout().path / "assets/model.pak"), kLfsPointer);
}

TEST_F(CheckoutTreeEntries, AnEmptyFileIsAnEmptyRegularFile) {
  const Worktree tree = checkout();
  ASSERT_TRUE(fs::is_regular_file(fs::symlink_status(tree.path / "empty")));
  EXPECT_EQ(fs::file_size(tree.path / "empty"), 0u);
}

TEST_F(CheckoutTreeEntries, ATreeCachedByAnOlderCheckoutIsRewrittenNotTrusted) {
  // What a raygate with the empty-binary bug left: the binary file empty, a stamp of layout 1
  // that matches the tree as it is.
  const Worktree first = checkout();
  const fs::path png = first.path / "textures/wood.png";
  fs::remove(png);
  write_file_atomically(png, "");
  std::string stamp = tree_stamp(first.path);
  ASSERT_EQ(stamp.rfind("raygate tree stamp 3\n", 0), 0u);
  stamp.replace(0, std::string("raygate tree stamp 3").size(), "raygate tree stamp 1");
  write_file_atomically(stamp_path_for(first.path), stamp);

  const Worktree again = checkout();
  EXPECT_EQ(again.path, first.path);
  EXPECT_EQ(read_file(again.path / "textures/wood.png"), png_like_bytes());
}

TEST_F(CheckoutTreeEntries, ANoteAboutAFileShowsItsNameNotItsControlBytes) {
  // A file name is the commit's bytes: the note on a changed cached tree must not pass an ESC
  // sequence in it to the terminal.
  repo_.write("evil\x1b[2J.txt", "x\n");
  sha_ = repo_.commit("a hostile file name");
  const Worktree first = checkout();
  write_file_atomically(first.path / "evil\x1b[2J.txt", "edited\n");
  ::testing::internal::CaptureStderr();
  const Worktree again = checkout();
  const std::string said = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(said.find("evil\\x1b[2J.txt was modified"), std::string::npos) << said;
  EXPECT_EQ(said.find('\x1b'), std::string::npos) << said;
  EXPECT_EQ(read_file(again.path / "evil\x1b[2J.txt"), "x\r\n");  // text=auto eol=crlf
}

}  // namespace
}  // namespace raygate
