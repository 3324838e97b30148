// store/document_files: documents into the store from files and back out. Other JSON is refused
// by name; an export writes stored documents byte for byte, and a stored sha that would make a
// path ("../x") leaves the directory untouched.
#include <gtest/gtest.h>

#include <functional>

#include "core/error.h"
#include "core/fs.h"
#include "results_fixture.h"
#include "store/document_files.h"

namespace raygate::test {
namespace {

namespace fs = std::filesystem;

std::string error_of(const std::function<void()>& action) {
  try {
    action();
  } catch (const UsageError& e) {
    return e.what();
  }
  return "no error";
}

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

DocumentSpec spec(int seed) {
  DocumentSpec s;
  s.sha = fake_sha(seed);
  s.scenes = {{"balls", 0.5}};
  return s;
}

TEST(LoadResultsFile, ReadsADocumentAndRefusesOtherJsonByName) {
  TempDir dir;
  const fs::path good = dir.path() / "results.json";
  write_results(make_document(spec(1)), good);
  EXPECT_EQ(load_results_file(good).scenes.at(0).entry.id, "balls");

  write_file_atomically(dir.path() / "adapter.json", R"({"name": "make-nff", "run": ["x"]})");
  const std::string other = error_of([&] { load_results_file(dir.path() / "adapter.json"); });
  EXPECT_TRUE(has(other, "adapter.json: not a raygate results document")) << other;
  write_file_atomically(dir.path() / "torn.json", R"({"schema_version": )");
  const std::string torn = error_of([&] { load_results_file(dir.path() / "torn.json"); });
  EXPECT_TRUE(has(torn, "torn.json:1:")) << torn;
  EXPECT_TRUE(has(torn, ": not JSON")) << torn;
}

// import takes files from anywhere: a key given twice or a number past a double's range is
// refused with where it is, before anything is stored.
TEST(LoadResultsFile, RefusesDuplicateKeysAndOutOfRangeNumbers) {
  TempDir dir;
  write_file_atomically(dir.path() / "twice.json",
                        "{\"schema_version\": 1,\n \"schema_version\": 2}");
  const std::string twice = error_of([&] { load_results_file(dir.path() / "twice.json"); });
  EXPECT_TRUE(has(twice, "twice.json:2:2: $: duplicate key 'schema_version'")) << twice;
  write_file_atomically(dir.path() / "huge.json", R"({"schema_version": 1e400})");
  const std::string huge = error_of([&] { load_results_file(dir.path() / "huge.json"); });
  EXPECT_TRUE(has(huge, "huge.json:1:20: $.schema_version: number 1e400 is out of range")) << huge;
}

TEST(CheckedShaPrefix, LowerCasesHexAndRefusesTheRest) {
  EXPECT_EQ(checked_sha_prefix("AbC123"), "abc123");
  EXPECT_EQ(checked_sha_prefix(""), "");
  EXPECT_THROW(checked_sha_prefix("abc; rm -rf"), UsageError);
  EXPECT_THROW(checked_sha_prefix(std::string(41, 'a')), UsageError);
}

class ExportDocuments : public ::testing::Test {
 protected:
  ExportDocuments() {
    const auto store = open_store((dir.path() / "results.db").string());
    store->add(make_document(spec(1)), "main");
    store->add(make_document(spec(2)), "main");
    documents = store->documents({});
  }
  TempDir dir;
  std::vector<StoredDocument> documents;
};

TEST_F(ExportDocuments, OneFilePerDocumentAsItWasStored) {
  const ExportedFiles out = export_documents(documents, dir.path() / "out");
  ASSERT_EQ(out.files.size(), 2u);
  EXPECT_FALSE(out.single_file);
  const std::string name = out.files[0].filename().string();
  EXPECT_EQ(name,
            std::to_string(documents[0].id) + "-" +
                documents[0].document["revisions"][0]["worktree"]["short_sha"].get<std::string>() +
                ".json");
  EXPECT_EQ(read_file(out.files[0]), documents[0].document.dump(1) + "\n");
}

TEST_F(ExportDocuments, OneFileTakesExactlyOneDocument) {
  const std::string many = error_of([&] { export_documents(documents, dir.path() / "x.json"); });
  EXPECT_TRUE(has(many, "2 documents match but -o")) << many;
  EXPECT_FALSE(fs::exists(dir.path() / "x.json"));
  const ExportedFiles one = export_documents({documents[0]}, dir.path() / "x.json");
  EXPECT_TRUE(one.single_file);
  EXPECT_EQ(read_file(dir.path() / "x.json"), documents[0].document.dump(1) + "\n");
}

TEST_F(ExportDocuments, AStoredShaThatMakesAPathWritesNothing) {
  documents[1].document["revisions"][0]["worktree"]["short_sha"] = "../../escape";
  const std::string bad = error_of([&] { export_documents(documents, dir.path() / "out"); });
  EXPECT_TRUE(has(bad, "revisions[].worktree.short_sha")) << bad;
  EXPECT_FALSE(fs::exists(dir.path() / "out"));
  EXPECT_FALSE(fs::exists(dir.path() / "escape.json"));
}

}  // namespace
}  // namespace raygate::test
