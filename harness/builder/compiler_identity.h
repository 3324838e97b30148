// Which compilers a build would use, as text that goes into the build cache key: the same commit
// built by another compiler (a CI image upgrade, CXX=clang++) is a different build, because its
// speed is what raygate measures.
#pragma once

#include <string>

namespace raygate {

// One compiler: the command a build tool would run, where PATH finds it, and the first line of
// its `--version` output.
struct CompilerInfo {
  std::string variable;  // "CXX" or "CC"
  std::string command;   // $CXX / $CC if set, else "c++" / "cc"
  std::string path;      // resolved through PATH (symlinks followed); "" if not found
  std::string version;   // first line of `command --version`; "" if it could not be run

  bool operator==(const CompilerInfo&) const = default;
};

// CXX or CC as this process's environment and PATH see them (runs `--version`, a few ms).
CompilerInfo detect_compiler(const std::string& variable, const std::string& default_command);

// "CXX=c++ (/usr/bin/x86_64-linux-gnu-g++-12): c++ (Debian 12.2.0-14) 12.2.0"; "not found" or
// "version unknown" in place of the missing parts.
std::string describe(const CompilerInfo& compiler);

// Both compilers, one line each: the text hashed into the cache key and kept in BuildRecord.
std::string detect_compiler_identity();

}  // namespace raygate
