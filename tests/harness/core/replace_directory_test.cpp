// core/replace_directory: a directory replaced whole or not at all. A fill that fails midway
// leaves the old directory exactly as it was and no temporary beside it; a completed one swaps
// in and the old contents are gone; links start a new version without writing through them.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <stdexcept>

#include "core/fs.h"
#include "core/replace_directory.h"

namespace raygate {
namespace {

namespace fs = std::filesystem;

std::size_t entries_in(const fs::path& folder) {
  std::size_t count = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(folder)) ++count;
  return count;
}

TEST(ReplaceDirectory, AFillThatFailsMidwayLeavesTheOldDirectoryAsItWas) {
  TempDir dir;
  const fs::path target = dir.path() / "set";
  write_file_atomically(target / "a.txt", "old a");
  write_file_atomically(target / "b.txt", "old b");
  EXPECT_THROW(replace_directory(target,
                                 [&](const fs::path& fresh) {
                                   link_tree(target, fresh);
                                   write_file_atomically(fresh / "a.txt", "new a");
                                   throw WriteError(fresh / "b.txt", "No space left on device");
                                 }),
               WriteError);
  EXPECT_EQ(read_file(target / "a.txt"), "old a");
  EXPECT_EQ(read_file(target / "b.txt"), "old b");
  EXPECT_EQ(entries_in(dir.path()), 1u);  // no temporary left beside it
}

TEST(ReplaceDirectory, ACompletedFillIsSwappedInAndTheOldIsRemoved) {
  TempDir dir;
  const fs::path target = dir.path() / "set";
  write_file_atomically(target / "a.txt", "old a");
  write_file_atomically(target / "gone.txt", "only in the old set");
  ::chmod(target.c_str(), 0750);
  replace_directory(target,
                    [](const fs::path& fresh) { write_file_atomically(fresh / "a.txt", "new a"); });
  EXPECT_EQ(read_file(target / "a.txt"), "new a");
  EXPECT_FALSE(fs::exists(target / "gone.txt"));
  EXPECT_EQ(fs::status(target).permissions(), fs::perms(0750));  // the old folder's
  EXPECT_EQ(entries_in(dir.path()), 1u);
}

TEST(ReplaceDirectory, AMissingTargetIsCreatedAndALinkedTargetIsReplacedWhereItPoints) {
  TempDir dir;
  replace_directory(dir.path() / "deep" / "new",
                    [](const fs::path& fresh) { write_file_atomically(fresh / "x", "x"); });
  EXPECT_EQ(read_file(dir.path() / "deep" / "new" / "x"), "x");

  fs::create_directory_symlink(dir.path() / "deep" / "new", dir.path() / "alias");
  replace_directory(dir.path() / "alias",
                    [](const fs::path& fresh) { write_file_atomically(fresh / "x", "y"); });
  EXPECT_TRUE(fs::is_symlink(dir.path() / "alias"));  // still a link, to the new contents
  EXPECT_EQ(read_file(dir.path() / "alias" / "x"), "y");
}

TEST(ReplaceDirectory, LinkTreeStartsANewVersionWithoutWritingThroughTheLinks) {
  TempDir dir;
  const fs::path target = dir.path() / "set";
  write_file_atomically(target / "keep.png", "kept bytes");
  write_file_atomically(target / "sub" / "deep.txt", "deep");
  fs::create_symlink("keep.png", target / "alias.png");
  replace_directory(target, [&](const fs::path& fresh) {
    link_tree(target, fresh);
    EXPECT_EQ(fs::hard_link_count(fresh / "keep.png"), 2u);   // a link, not a copy
    write_file_atomically(fresh / "keep.png", "changed");     // replaces the link's name
    EXPECT_EQ(read_file(target / "keep.png"), "kept bytes");  // the old one is untouched
  });
  EXPECT_EQ(read_file(target / "keep.png"), "changed");
  EXPECT_EQ(read_file(target / "sub" / "deep.txt"), "deep");
  EXPECT_EQ(fs::read_symlink(target / "alias.png"), "keep.png");
}

TEST(ReplaceDirectory, TemporariesAreRecognizedByName) {
  EXPECT_TRUE(is_replacement_temporary("/g/.raygate-baseline.new-a1B2c3"));
  EXPECT_TRUE(is_replacement_temporary("/g/.raygate-baseline.new-a1B2c3.old"));
  EXPECT_FALSE(is_replacement_temporary("/g/raygate-baseline"));
  EXPECT_FALSE(is_replacement_temporary("/g/.hidden"));
}

}  // namespace
}  // namespace raygate
