#include "builder/compiler_identity.h"

#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <vector>

#include "core/fs.h"
#include "core/process.h"

namespace fs = std::filesystem;

namespace raygate {
namespace {

// $CXX may hold a launcher and its compiler ("ccache g++"); the words are run as argv.
std::vector<std::string> split_words(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> words;
  for (std::string word; in >> word;) words.push_back(word);
  return words;
}

// Where execvp would find `program`; symlinks followed, because /usr/bin/c++ is an alternatives
// link and its target names the real compiler.
std::string find_on_path(const std::string& program) {
  if (program.find('/') != std::string::npos) {
    std::error_code ec;
    const fs::path resolved = fs::canonical(program, ec);
    return ec ? "" : resolved.string();
  }
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path != nullptr ? path : "/usr/bin:/bin");
  for (std::string dir; std::getline(dirs, dir, ':');) {
    const fs::path candidate = fs::path(dir.empty() ? "." : dir) / program;
    if (::access(candidate.c_str(), X_OK) != 0) continue;
    std::error_code ec;
    const fs::path resolved = fs::canonical(candidate, ec);
    if (!ec && fs::is_regular_file(resolved, ec)) return resolved.string();
  }
  return "";
}

std::string first_line_of_version(const std::vector<std::string>& command) {
  const TempDir scratch("raygate-cc");
  ProcessSpec spec;
  spec.argv = command;
  spec.argv.push_back("--version");
  spec.stdout_path = scratch.path() / "version.txt";
  spec.stderr_path = spec.stdout_path;
  spec.timeout = std::chrono::seconds(20);
  if (!run_process(spec).succeeded()) return "";
  std::ifstream in(spec.stdout_path);
  std::string line;
  std::getline(in, line);
  return line;
}

}  // namespace

CompilerInfo detect_compiler(const std::string& variable, const std::string& default_command) {
  CompilerInfo info;
  info.variable = variable;
  const char* value = std::getenv(variable.c_str());
  info.command = value != nullptr && *value != '\0' ? value : default_command;
  const std::vector<std::string> words = split_words(info.command);
  if (words.empty()) return info;
  // With a launcher, the compiler is the last word; the version line is the launcher's, so
  // the path of the compiler itself is what tells two set-ups apart.
  info.path = find_on_path(words.back());
  if (!info.path.empty() || words.size() > 1) info.version = first_line_of_version(words);
  return info;
}

std::string describe(const CompilerInfo& compiler) {
  std::string text = compiler.variable + "=" + compiler.command + " (";
  text += compiler.path.empty() ? "not found" : compiler.path;
  text += "): ";
  text += compiler.version.empty() ? "version unknown" : compiler.version;
  return text;
}

std::string detect_compiler_identity() {
  return describe(detect_compiler("CXX", "c++")) + "\n" + describe(detect_compiler("CC", "cc"));
}

}  // namespace raygate
