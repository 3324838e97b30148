// pipeline/output_failures: an output that cannot be written is said at once with its path and the
// system's reason, the command goes on, and the exit code becomes 3 unless the gate found a
// regression (1), which outranks it.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <stdexcept>

#include "pipeline/output_failures.h"
#include "core/error.h"
#include "core/exit_codes.h"
#include "core/fs.h"

namespace raygate {
namespace {

using ::testing::HasSubstr;

// What the failures said, through a temporary file standing in for standard error.
class SaidLines {
 public:
  SaidLines() : file_(std::tmpfile()) {}
  ~SaidLines() { std::fclose(file_); }
  SaidLines(const SaidLines&) = delete;
  SaidLines& operator=(const SaidLines&) = delete;
  std::FILE* file() { return file_; }
  std::string text() {
    std::fflush(file_);
    std::rewind(file_);
    std::string out;
    for (int c = std::fgetc(file_); c != EOF; c = std::fgetc(file_)) out += static_cast<char>(c);
    return out;
  }

 private:
  std::FILE* file_;
};

TEST(OutputFailures, NothingFailedKeepsTheGatesCode) {
  SaidLines said;
  OutputFailures failures(said.file());
  EXPECT_TRUE(failures.attempt("--report html:r.html", [] {}));
  EXPECT_FALSE(failures.any());
  EXPECT_EQ(failures.exit_code(0), 0);
  EXPECT_EQ(failures.exit_code(1), 1);
  EXPECT_EQ(failures.summary(), "");
  EXPECT_EQ(said.text(), "");
}

TEST(OutputFailures, AFailedWriteIsSaidAndTheCommandGoesOnToExit3) {
  SaidLines said;
  OutputFailures failures(said.file());
  EXPECT_FALSE(failures.attempt("--report junit:/full/j.xml", [] {
    throw WriteError("/full/j.xml", "No space left on device");
  }));
  EXPECT_TRUE(failures.attempt("--report html:r.html", [] {}));  // the next one still runs
  EXPECT_EQ(said.text(),
            "raygate: error: --report junit:/full/j.xml not written: cannot write /full/j.xml: "
            "No space left on device\n");
  EXPECT_TRUE(failures.failed("/full/j.xml"));
  EXPECT_FALSE(failures.failed("r.html"));
  EXPECT_EQ(failures.exit_code(0), to_int(ExitCode::infrastructure));
  EXPECT_EQ(failures.exit_code(3), 3);
  EXPECT_EQ(failures.exit_code(1), 1);  // a found regression outranks a lost file
  EXPECT_EQ(failures.summary(),
            "1 output could not be written (--report junit:/full/j.xml); the other outputs "
            "were written");
  failures.say_summary(3);
  EXPECT_NE(said.text().find("; the other outputs were written; exit 3\n"), std::string::npos);
}

TEST(OutputFailures, OnlyWriteErrorsAreKeptOthersTravelUp) {
  SaidLines said;
  OutputFailures failures(said.file());
  EXPECT_THROW(failures.attempt("x", [] { throw UsageError("bad"); }), UsageError);
  EXPECT_THROW(failures.attempt("x", [] { throw std::logic_error("bug"); }), std::logic_error);
  EXPECT_FALSE(failures.any());
}

// Two outputs, or an output and a file the command reads, that are one file: the second write
// would replace the first (a store overwritten by -o, a report over its own document), so the
// command is refused before it measures, naming both options.
TEST(OutputFailures, TwoNamesForOneFileAreRefused) {
  const TempDir dir;
  const auto store = dir.path() / "results.db";
  write_file_atomically(store, "not yet a store");
  std::filesystem::create_symlink(store, dir.path() / "link.db");
  try {
    check_distinct_files(
        {{"--store", store}, {"--output", dir.path() / "sub" / ".." / "results.db"}});
    ADD_FAILURE() << "one file spelt two ways was taken";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("--store and --output name the same file"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(check_distinct_files({{"--report markdown:link.db", dir.path() / "link.db"},
                                     {"the results document", store}}),
               UsageError);
  // Two inputs that are one file (`merge a.json a.json`) are not one overwriting the other.
  try {
    check_distinct_files(
        {{"the shard a.json", store, true}, {"the shard link.db", dir.path() / "link.db", true}});
    ADD_FAILURE() << "one shard given twice was taken";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("name the same file, " + store.string() +
                                         ": one file given twice"),
              std::string::npos)
        << e.what();
  }
  // Different files, standard output twice and the default place pass.
  check_distinct_files({{"--output", dir.path() / "r.json"},
                        {"--report markdown:-", "-"},
                        {"--report json:-", "-"},
                        {"--store", ""},
                        {"--report html:r.html", dir.path() / "r.html"}});
}

// What cannot be written is found from the path alone, before any work: the same words for a
// file (-o, --markdown) and a folder (--work-dir, --html DIR).
TEST(OutputFailures, PathsThatCannotBeWrittenAreNamedBeforeAnyWork) {
  const TempDir dir;
  const auto file = dir.path() / "a-file";
  write_file_atomically(file, "x");
  EXPECT_THAT(output_file_problem(dir.path().string()), HasSubstr("is a directory"));
  EXPECT_THAT(output_file_problem("/dev/null"), HasSubstr("not a regular file"));
  EXPECT_THAT(output_file_problem((file / "r.md").string()),
              HasSubstr(file.string() + " is not a directory"));
  EXPECT_THAT(output_folder_problem(file.string()), HasSubstr("is not a directory"));
  EXPECT_THAT(output_folder_problem((file / "deeper").string()), HasSubstr("is not a directory"));
  // Folders still to be made, files to replace, standard output and the default place pass.
  EXPECT_EQ(output_file_problem((dir.path() / "new" / "r.md").string()), "");
  EXPECT_EQ(output_file_problem(file.string()), "");
  EXPECT_EQ(output_file_problem("-"), "");
  EXPECT_EQ(output_file_problem(""), "");
  // A document named by a link is refused (written whole, it would replace the link; followed,
  // a link planted in a repository would send it anywhere), loops and links to files alike. A
  // store may be a link: SQLite writes through it.
  std::filesystem::create_symlink("loop-b", dir.path() / "loop-a");
  std::filesystem::create_symlink("loop-a", dir.path() / "loop-b");
  EXPECT_THAT(output_document_problem((dir.path() / "loop-a").string()),
              HasSubstr("loop-a is a symbolic link (to loop-b)"));
  std::filesystem::create_symlink(file, dir.path() / "to-a-file");
  EXPECT_THAT(output_document_problem((dir.path() / "to-a-file").string()),
              HasSubstr("would replace the link; name the file itself"));
  EXPECT_EQ(output_file_problem((dir.path() / "to-a-file").string()), "");
  EXPECT_EQ(output_document_problem(file.string()), "");
  EXPECT_EQ(output_folder_problem((dir.path() / "new" / "work").string()), "");
  EXPECT_EQ(output_folder_problem(dir.path().string()), "");
  EXPECT_THROW(check_output_folder(file, "--work-dir"), UsageError);
  // consistency --markdown over one of its documents.
  EXPECT_THROW(check_output_beside_inputs({"--markdown", file}, {"other.json", file.string()},
                                          "the document"),
               UsageError);
  check_output_beside_inputs({"--markdown", dir.path() / "c.md"}, {file.string()}, "the document");
}

// A name too long is the user's (2) and said in a line; another refusal is raygate's (3).
TEST(OutputFailures, AFilesystemErrorIsSaidShortAndTold) {
  const std::string name(300000, 'a');
  const FilesystemFailure too_long = filesystem_failure(std::filesystem::filesystem_error(
      "status", name, std::make_error_code(std::errc::filename_too_long)));
  EXPECT_EQ(too_long.exit_code, 2);
  EXPECT_THAT(too_long.message, HasSubstr("a path is too long for the file system"));
  EXPECT_THAT(too_long.message, HasSubstr("(300000 bytes)"));
  EXPECT_LT(too_long.message.size(), 400u);
  const FilesystemFailure denied = filesystem_failure(
      std::filesystem::filesystem_error("cannot create directories", "/srv/cache",
                                        std::make_error_code(std::errc::permission_denied)));
  EXPECT_EQ(denied.exit_code, 3);
  EXPECT_THAT(denied.message, HasSubstr("Permission denied [/srv/cache]"));
}

}  // namespace
}  // namespace raygate
