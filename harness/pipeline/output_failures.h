// The outputs a command was asked for (the results document -o, --report files, standard
// output): checked before anything is measured, and those that could not be written at the end.
// A measurement is worth more than any one of its files, so a failed output is said at once
// (which output, its path, the system's reason), the command goes on writing the others, and
// only its exit code changes at the end: 3, "raygate could not finish", unless the gate found a
// regression, which outranks it as it outranks an unmeasured scene (DESIGN.md §11).
#pragma once

#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "core/fs.h"

namespace raygate {

class OutputFailures {
 public:
  // Failures are said on `say` as they happen (standard error; a test passes a file).
  explicit OutputFailures(std::FILE* say = stderr) : say_(say) {}

  // Records that `output` ("--output", "--report html:r.html") could not be written.
  void add(const std::string& output, const FailedWrite& failure);

  // Runs `write`; a WriteError becomes a failure of `output` instead of ending the command.
  // Returns whether the write succeeded. Other errors travel up: they are not about a file.
  bool attempt(const std::string& output, const std::function<void()>& write);

  bool any() const { return !failures_.empty(); }
  // Whether the write of `path` failed (its file, if there is one, is not the one asked for).
  bool failed(const std::filesystem::path& path) const;
  std::size_t count() const { return failures_.size(); }

  // The command's exit code given the gate's: unchanged when every output was written or the
  // gate found a regression (1); otherwise 3.
  int exit_code(int gate_exit_code) const;

  // The closing line: how many outputs failed and that everything else was kept; "" if none.
  std::string summary() const;
  // Says the summary and the command's exit code ("raygate: error: ...; exit 3") when an output
  // failed, so the last line is not the console table's "exit 0"; nothing otherwise.
  void say_summary(int exit_code) const;

 private:
  struct Failure {
    std::string output;
    FailedWrite write;
  };
  std::vector<Failure> failures_;
  std::FILE* say_;
};

// Why a file could not be written at `path` the way documents and reports are (a temporary file
// beside it renamed over it, missing folders created): it is a directory or something else that
// is not a regular file (/dev/full), or the nearest existing folder above it is not a folder or
// is not writable. "" when it can be, and for "" (the default place) and "-" (standard output).
// The text names the path, not the option: a CLI11 check (cli/subcommand.h) puts that before it.
std::string output_file_problem(const std::string& path);

// output_file_problem, and for a document, report or scene: a symbolic link is not replaced by
// one (nor followed), and a file that is there and is an SQLite database (a results store) is not
// replaced by one (the fifth sweep: `run --no-store -o
// results.db` replaced a team's store after the measuring). -o and --report are checked with it.
std::string output_document_problem(const std::string& path);

// Why files could not be written under the folder `path` (--work-dir, --html DIR): it, or the
// nearest folder above it that exists, is not a folder or is not writable. Missing folders are
// fine: they are created. "" when they can be, and for "".
std::string output_folder_problem(const std::string& path);

// The two above as a UsageError naming `option`. Called before measuring, so a typo does not
// cost a whole run.
void check_output_path(const std::filesystem::path& path, const std::string& option);
void check_output_folder(const std::filesystem::path& path, const std::string& option);

// A file a command reads or writes, by the option or argument that named it.
struct NamedFile {
  std::string option;  // "--output", "--report markdown:r.md", "--store", "the results document"
  std::filesystem::path path;
  bool only_read = false;  // an input: two of them the same file are one file given twice
};

// Throws UsageError, naming both options, when two of `files` are the same file (one path spelt
// two ways, or a link to the other): writing one would overwrite the other (a report over its
// results document, -o over the store or over a document read). "" and "-" are skipped. Called
// before measuring, with the outputs' checks.
void check_distinct_files(const std::vector<NamedFile>& files);

// For a command that reads `inputs` and writes one more file beside what it prints (consistency
// --markdown): check_output_path of `output`, and refused when it names one of the inputs
// (each called "`input_role` PATH" in the message). Called before the inputs are read.
void check_output_beside_inputs(const NamedFile& output, const std::vector<std::string>& inputs,
                                const std::string& input_role);

// Flushes standard output after a report went there; a failed write or flush (a full disk
// behind `> file`, /dev/full) is a failure of `output`. `error_number` is errno as the writing
// left it (the stream keeps only that it failed, not why); 0 says "write failed".
void check_standard_output(OutputFailures& failures, const std::string& output, int error_number);

// What a command printed is its result (a report, a verdict, history): when standard output could
// not take it (`> /dev/full`, a full disk), the command did not do its work. Flushes standard
// output; on failure says so in one line and returns 3 where `exit_code` was 0. A regression (1)
// outranks it, and a command that found it already (check_standard_output) exits 3 anyway.
int exit_code_after_standard_output(int exit_code);

// What a filesystem error that reached main says, and its exit code. A name the system refuses as
// too long (ENAMETOOLONG: a name of more than 255 bytes in a path given for reading) is the
// user's to fix, 2; any other refusal (permissions, a full disk) is raygate unable to work, 3.
// Paths over 200 bytes are shortened (a 300,000-byte name once filled the message).
struct FilesystemFailure {
  int exit_code = 3;
  std::string message;
};
FilesystemFailure filesystem_failure(const std::filesystem::filesystem_error& error);

}  // namespace raygate
