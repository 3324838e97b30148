#include "pipeline/output_failures.h"

#include <fmt/core.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <string_view>

#include "core/error.h"
#include "core/exit_codes.h"
#include "report/terminal.h"

namespace raygate {

void OutputFailures::add(const std::string& output, const FailedWrite& failure) {
  failures_.push_back({output, failure});
  // fputs, not fmt::print: a failed write to `say_` must not throw over the failure it reports.
  std::fputs(fmt::format("raygate: error: {} not written: cannot write {}: {}\n", output,
                         failure.path.string(), failure.reason)
                 .c_str(),
             say_);
  std::fflush(say_);
}

bool OutputFailures::attempt(const std::string& output, const std::function<void()>& write) {
  try {
    write();
    return true;
  } catch (const WriteError& e) {
    add(output, e.failure());
    return false;
  }
}

bool OutputFailures::failed(const std::filesystem::path& path) const {
  for (const Failure& failure : failures_) {
    if (failure.write.path == path) return true;
  }
  return false;
}

int OutputFailures::exit_code(int gate_exit_code) const {
  if (failures_.empty() || gate_exit_code == to_int(ExitCode::regression)) return gate_exit_code;
  return to_int(ExitCode::infrastructure);
}

std::string OutputFailures::summary() const {
  if (failures_.empty()) return {};
  std::string names;
  for (const Failure& failure : failures_) {
    names += (names.empty() ? "" : ", ") + failure.output;
  }
  return fmt::format("{} output{} could not be written ({}); the other outputs were written",
                     failures_.size(), failures_.size() == 1 ? "" : "s", names);
}

void OutputFailures::say_summary(int exit_code) const {
  if (failures_.empty()) return;
  std::fputs(fmt::format("raygate: error: {}; exit {}\n", summary(), exit_code).c_str(), say_);
  std::fflush(say_);
}

void check_standard_output(OutputFailures& failures, const std::string& output, int error_number) {
  std::cout.flush();
  if (std::cout) return;
  const int reason = error_number != 0 ? error_number : errno;
  failures.add(output, {"-", reason != 0 ? std::strerror(reason) : "write failed"});
  std::cout.clear();  // the outputs after this one still get their try
}

int exit_code_after_standard_output(int exit_code) {
  const bool failed = std::fflush(stdout) != 0 || std::ferror(stdout) != 0;
  const int reason = errno;
  if (!failed || exit_code != 0) return exit_code;
  const int code = to_int(ExitCode::infrastructure);
  say_last_words(fmt::format("raygate: error: standard output could not be written: {}; exit {}",
                             reason != 0 ? std::strerror(reason) : "write failed", code));
  return code;
}

namespace {

// Why files could not be written under `folder` on the way to `target`: the nearest folder that
// exists at or above it is not a folder, or not one raygate may write in (the missing ones below
// it are created when `target` is written). "" when they can.
std::string folder_problem(std::filesystem::path folder, const std::filesystem::path& target) {
  for (const auto& part : target) {
    if (part.native().size() > NAME_MAX) {
      return fmt::format(
          "cannot write {}...: a name in it is {} bytes, more than the {} a file "
          "system allows",
          target.string().substr(0, 60), part.native().size(), NAME_MAX);
    }
  }
  std::error_code error;
  while (!std::filesystem::exists(folder, error) && folder.has_relative_path()) {
    if (error) return fmt::format("cannot write {}: {}", target.string(), error.message());
    folder = folder.parent_path();
  }
  if (!std::filesystem::is_directory(folder, error)) {
    return fmt::format("cannot write {}: {} is not a directory", target.string(), folder.string());
  }
  // Tried, not asked: access() says yes to root everywhere, and /proc or a read-only mount
  // refuse the file only when it is made.
  std::string probe = (folder / ".raygate-write-check-XXXXXX").string();
  const int fd = ::mkstemp(probe.data());
  if (fd < 0) {
    return fmt::format("cannot write {}: {}: {}", target.string(), folder.string(),
                       std::strerror(errno));
  }
  ::close(fd);
  ::unlink(probe.c_str());
  return "";
}

}  // namespace

std::string output_file_problem(const std::string& path) {
  if (path.empty() || path == "-") return "";
  std::error_code error;
  const std::filesystem::path target = std::filesystem::absolute(path, error);
  if (std::filesystem::is_directory(target, error)) {
    return fmt::format("{} is a directory; name a file in it", target.string());
  }
  if (std::filesystem::exists(target, error) && !std::filesystem::is_regular_file(target, error)) {
    // Files are replaced whole (a temporary renamed over them): that would replace the node.
    return fmt::format(
        "{} is not a regular file (a device, FIFO or socket); name a file, or - for standard "
        "output",
        target.string());
  }
  return folder_problem(target.parent_path(), target);
}

std::string output_folder_problem(const std::string& path) {
  if (path.empty()) return "";
  std::error_code error;
  const std::filesystem::path target = std::filesystem::absolute(path, error);
  return folder_problem(target, target);
}

std::string output_document_problem(const std::string& path) {
  if (std::string problem = output_file_problem(path); !problem.empty()) return problem;
  if (path.empty() || path == "-") return "";
  // A store may be a link (SQLite writes through it); a document may not.
  if (std::string problem = symbolic_link_problem(path); !problem.empty()) return problem;
  char header[16] = {};
  std::ifstream(path, std::ios::binary).read(header, sizeof header);
  if (std::string_view(header, sizeof header) == std::string_view("SQLite format 3\0", 16)) {
    return path +
           " is an SQLite database (a results store?): a document or report is never "
           "written over one; name another file";
  }
  return "";
}

void check_output_path(const std::filesystem::path& path, const std::string& option) {
  if (const std::string problem = output_document_problem(path.string()); !problem.empty()) {
    throw UsageError(option + ": " + problem);
  }
}

void check_output_folder(const std::filesystem::path& path, const std::string& option) {
  if (const std::string problem = output_folder_problem(path.string()); !problem.empty()) {
    throw UsageError(option + ": " + problem);
  }
}

namespace {

// The file a path names, as far as it can be told before it exists: links and `..` resolved.
std::filesystem::path file_named(const std::filesystem::path& path) {
  std::error_code error;
  const std::filesystem::path canonical = std::filesystem::weakly_canonical(path, error);
  return error ? std::filesystem::absolute(path, error).lexically_normal() : canonical;
}

bool same_file(const std::filesystem::path& a, const std::filesystem::path& b) {
  std::error_code error;
  if (std::filesystem::equivalent(a, b, error)) return true;  // hard links too
  return file_named(a) == file_named(b);
}

}  // namespace

void check_distinct_files(const std::vector<NamedFile>& files) {
  for (std::size_t i = 0; i < files.size(); ++i) {
    if (files[i].path.empty() || files[i].path == "-") continue;
    for (std::size_t j = i + 1; j < files.size(); ++j) {
      if (files[j].path.empty() || files[j].path == "-") continue;
      if (!same_file(files[i].path, files[j].path)) continue;
      const bool both_read = files[i].only_read && files[j].only_read;
      throw UsageError(
          fmt::format("{} and {} name the same file, {}: {}; give each its own file",
                      files[i].option, files[j].option, file_named(files[i].path).string(),
                      both_read ? "one file given twice" : "one would overwrite the other"));
    }
  }
}

void check_output_beside_inputs(const NamedFile& output, const std::vector<std::string>& inputs,
                                const std::string& input_role) {
  check_output_path(output.path, output.option);
  // The output against each input, not the inputs against each other: reading one twice is the
  // command's own question (consistency calls it one measurement).
  for (const std::string& input : inputs) {
    check_distinct_files({output, {input_role + " " + input, input}});
  }
}

namespace {

// "/tmp/aaaa…aaaa/x.json (300012 bytes)" for a path too long to echo whole.
std::string shortened(const std::filesystem::path& path) {
  const std::string text = path.string();
  if (text.size() <= 200) return text;
  return fmt::format("{}…{} ({} bytes)", text.substr(0, 120), text.substr(text.size() - 60),
                     text.size());
}

}  // namespace

FilesystemFailure filesystem_failure(const std::filesystem::filesystem_error& error) {
  // A working directory deleted under the shell: every relative path fails in the library's words
  // ("cannot make absolute path"), and exit 3 read as raygate's failure (a sweep).
  if (char* cwd = ::getcwd(nullptr, 0); cwd != nullptr) {
    std::free(cwd);
  } else if (errno == ENOENT) {
    return {to_int(ExitCode::usage),
            "the working directory no longer exists (it was deleted after the shell entered "
            "it): cd to a folder that exists and run raygate again"};
  }
  if (error.code() == std::errc::filename_too_long) {
    return {to_int(ExitCode::usage),
            "a path is too long for the file system (a name has at most 255 bytes): " +
                shortened(error.path1())};
  }
  const bool long_paths =
      error.path1().native().size() > 200 || error.path2().native().size() > 200;
  return {to_int(ExitCode::infrastructure),
          long_paths ? fmt::format("{} [{}]", error.code().message(), shortened(error.path1()))
                     : std::string(error.what())};
}

}  // namespace raygate
