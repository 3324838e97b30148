// pipeline/document_output: the results document of a measurement is kept whatever happens to
// the file the user named. A requested path that cannot be written sends the document to the
// run folder and says why; a later success removes that stale copy; nowhere to write is
// reported, not thrown.
#include <gtest/gtest.h>

#include "core/fs.h"
#include "pipeline/document_output.h"
#include "results_fixture.h"

namespace raygate::test {
namespace {

namespace fs = std::filesystem;

class DocumentOutputTest : public ::testing::Test {
 protected:
  DocumentOutputTest() {
    DocumentSpec spec;
    spec.sha = fake_sha(2);
    spec.scenes = {{.id = "balls"}};
    document_ = make_document(spec);
    write_file_atomically(blocker_, "a file where a folder should be");
  }

  TempDir dir_;
  ResultsDocument document_;
  fs::path blocker_ = dir_.path() / "not-a-folder";
  fs::path run_folder_copy_ = dir_.path() / "run" / "results.json";
};

TEST_F(DocumentOutputTest, TheRequestedFileWhenItCanBeWritten) {
  const fs::path requested = dir_.path() / "out" / "results.json";
  const KeptDocument kept = keep_document(document_, requested, run_folder_copy_);
  ASSERT_TRUE(kept.path);
  EXPECT_EQ(*kept.path, requested);
  EXPECT_TRUE(kept.failed.empty());
  EXPECT_EQ(describe_kept(kept), "");
  EXPECT_EQ(read_results(requested).scenes.size(), 1u);
  EXPECT_FALSE(fs::exists(run_folder_copy_));
}

TEST_F(DocumentOutputTest, TheRunFolderWhenTheRequestedFileCannotBeWritten) {
  const fs::path requested = blocker_ / "results.json";
  const KeptDocument kept = keep_document(document_, requested, run_folder_copy_);
  ASSERT_TRUE(kept.path);
  EXPECT_EQ(*kept.path, run_folder_copy_);
  ASSERT_EQ(kept.failed.size(), 1u);
  EXPECT_EQ(kept.failed[0].path, requested);
  EXPECT_NE(kept.failed[0].reason.find("cannot create directory"), std::string::npos)
      << kept.failed[0].reason;
  EXPECT_EQ(read_results(run_folder_copy_).scenes.size(), 1u);
  const std::string said = describe_kept(kept);
  EXPECT_NE(said.find("cannot write " + requested.string()), std::string::npos) << said;
  EXPECT_NE(said.find("kept in " + run_folder_copy_.string() + " instead"), std::string::npos)
      << said;
}

TEST_F(DocumentOutputTest, ALaterSuccessRemovesTheStaleRunFolderCopy) {
  const fs::path requested = dir_.path() / "later" / "results.json";
  write_file_atomically(requested.parent_path(), "in the way, for now");
  keep_document(document_, requested, run_folder_copy_);
  ASSERT_TRUE(fs::exists(run_folder_copy_));
  fs::remove(requested.parent_path());  // the disk has room again
  const KeptDocument kept = keep_document(document_, requested, run_folder_copy_);
  EXPECT_EQ(kept.path, requested);
  EXPECT_FALSE(fs::exists(run_folder_copy_));
}

TEST_F(DocumentOutputTest, NowhereToWriteIsReportedNotThrown) {
  const KeptDocument kept =
      keep_document(document_, blocker_ / "a.json", blocker_ / "run" / "results.json");
  EXPECT_FALSE(kept.path);
  EXPECT_EQ(kept.failed.size(), 2u);
  EXPECT_NE(describe_kept(kept).find("the document is kept in no file"), std::string::npos);
}

}  // namespace
}  // namespace raygate::test
