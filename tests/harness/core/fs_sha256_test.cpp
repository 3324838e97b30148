// Atomic writes and SHA-256 (FIPS 180-4 test vectors).
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>

#include <cerrno>
#include <csignal>
#include <cstring>

#include "core/error.h"
#include "core/fs.h"
#include "core/sha256.h"

namespace raygate {
namespace {

TEST(Sha256, KnownVectors) {
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(sha256_hex(std::string(1000000, 'a')),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(Fs, AtomicWriteCreatesParentsAndReplaces) {
  TempDir dir;
  const auto path = dir.path() / "a" / "b" / "result.json";
  write_file_atomically(path, "first");
  write_file_atomically(path, "second");
  EXPECT_EQ(read_file(path), "second");
  // No temp files are left behind.
  int entries = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(path.parent_path())) {
    ++entries;
  }
  EXPECT_EQ(entries, 1);
}

TEST(Fs, FailedWriteKeepsTheOldFileAndNamesThePath) {
  TempDir dir;
  const auto path = dir.path() / "keep.txt";
  write_file_atomically(path, "precious");
  // A regular file where the parent directory should be: nothing can be written there.
  const auto blocked = dir.path() / "keep.txt" / "child.txt";
  try {
    write_file_atomically(blocked, "x");
    FAIL() << "expected InfraError";
  } catch (const InfraError& e) {
    EXPECT_NE(std::string(e.what()).find("keep.txt"), std::string::npos) << e.what();
  }
  EXPECT_EQ(read_file(path), "precious");
}

// The seventh sweep: a TMPDIR that is no folder was "filesystem error: temp_directory_path: No
// such file or directory" from run and doctor alike.
TEST(Fs, ATmpdirThatIsNoFolderIsNamed) {
  const TempDir dir;
  const std::string saved = std::getenv("TMPDIR") ? std::getenv("TMPDIR") : "";
  const std::string missing = (dir.path() / "gone").string();
  setenv("TMPDIR", missing.c_str(), 1);
  try {
    TempDir unusable;
    ADD_FAILURE() << "a TempDir was made in " << unusable.path();
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("TMPDIR=" + missing + " is not a folder that can be used"),
              std::string::npos)
        << e.what();
  }
  saved.empty() ? unsetenv("TMPDIR") : setenv("TMPDIR", saved.c_str(), 1);
}

TEST(Fs, WriteFailingMidwayKeepsTheOldFile) {
  // A file-size limit makes write() fail part way (EFBIG), as a full disk does (ENOSPC): the
  // old content must survive and no temp file may be left.
  TempDir dir;
  const auto path = dir.path() / "history.json";
  write_file_atomically(path, "old");
  rlimit saved{};
  ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &saved), 0);
  signal(SIGXFSZ, SIG_IGN);
  rlimit small = saved;
  small.rlim_cur = 4096;
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &small), 0);
  try {
    write_file_atomically(path, std::string(100000, 'x'));
    ADD_FAILURE() << "expected WriteError";
  } catch (const WriteError& e) {  // which file and the system's own reason, for the message
    EXPECT_EQ(e.path(), path);
    EXPECT_EQ(e.reason(), std::strerror(EFBIG));
  }
  setrlimit(RLIMIT_FSIZE, &saved);
  EXPECT_EQ(read_file(path), "old");
  int entries = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir.path())) ++entries;
  EXPECT_EQ(entries, 1);
}

TEST(Fs, ANodeThatIsNotARegularFileIsNeverReplaced) {
  // Renaming a temp file over a FIFO (or, as root, over /dev/full) would replace the node
  // itself; the writer refuses instead, and the node stays what it was.
  TempDir dir;
  const auto fifo = dir.path() / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_THROW(write_file_atomically(fifo, "x"), WriteError);
  EXPECT_TRUE(std::filesystem::is_fifo(fifo));
  EXPECT_THROW(write_file_atomically(dir.path(), "x"), WriteError);  // a directory
}

TEST(Fs, ASymlinkIsReplacedNeverFollowed) {
  // A link planted where raygate writes (a repository's `results.json -> ~/.bashrc`) must not
  // send the write to its target: the link is replaced by the file, and the target stays as it
  // was. (Outputs a user names are refused up front when they are links.)
  TempDir dir;
  write_file_atomically(dir.path() / "target.txt", "kept");
  std::filesystem::create_symlink(dir.path() / "target.txt", dir.path() / "results.json");
  write_file_atomically(dir.path() / "results.json", "new");
  EXPECT_FALSE(std::filesystem::is_symlink(dir.path() / "results.json"));
  EXPECT_EQ(read_file(dir.path() / "results.json"), "new");
  EXPECT_EQ(read_file(dir.path() / "target.txt"), "kept");
}

// The fifth sweep: names of 244 to 255 bytes passed the up-front check and failed at the write,
// the temporary's name ("." + name + ".tmp-XXXXXX") being too long.
TEST(Fs, ANameUpToTheFileSystemsLimitIsWritten) {
  TempDir dir;
  for (const std::size_t length : {240u, 244u, 250u, 255u}) {
    const auto path = dir.path() / std::string(length, 'm');
    write_file_atomically(path, "whole");
    EXPECT_EQ(read_file(path), "whole") << length;
  }
}

TEST(Fs, SyncDirectoryNamesAFolderThatCannotBeOpened) {
  TempDir dir;
  sync_directory(dir.path());
  try {
    sync_directory(dir.path() / "gone");
    ADD_FAILURE() << "expected WriteError";
  } catch (const WriteError& e) {
    EXPECT_EQ(e.path(), dir.path() / "gone");
  }
}

TEST(Fs, ReadingADirectoryOrMissingFileIsAUsageError) {
  TempDir dir;
  EXPECT_THROW(read_file(dir.path()), UsageError);
  EXPECT_THROW(read_file(dir.path() / "missing"), UsageError);
}

// A FIFO with no writer would block the open forever, /dev/zero would never end: every input
// raygate reads (adapters, suites, policies, documents, raygate.toml, cached scenes) goes
// through read_file, which refuses them at once (issue 25, class 12).
TEST(Fs, ReadingAFifoOrADeviceIsAUsageErrorNotAHang) {
  TempDir dir;
  const std::filesystem::path fifo = dir.path() / "scene.nff";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0) << std::strerror(errno);
  try {
    read_file(fifo);
    ADD_FAILURE() << "a FIFO was read";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find(fifo.string() + ": is a FIFO (named pipe), expected a "
                                                         "regular file"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(read_file("/dev/zero"), UsageError);
  // A symlink to a regular file is read as the file.
  write_file_atomically(dir.path() / "real.nff", "s 0 0 0 1\n");
  std::filesystem::create_symlink(dir.path() / "real.nff", dir.path() / "link.nff");
  EXPECT_EQ(read_file(dir.path() / "link.nff"), "s 0 0 0 1\n");
}

}  // namespace
}  // namespace raygate
