// Errors that travel up to the CLI, which prints what() as one line and exits with code().
// Use UsageError for anything the user can fix in their input, InfraError when raygate could
// not do its work (a tool failed, a file could not be written, a disk is full).
#pragma once

#include <stdexcept>
#include <string>

#include "core/exit_codes.h"

namespace raygate {

class Error : public std::runtime_error {
 public:
  Error(ExitCode code, const std::string& message) : std::runtime_error(message), code_(code) {}
  ExitCode code() const { return code_; }

 private:
  ExitCode code_;
};

class UsageError : public Error {
 public:
  explicit UsageError(const std::string& message) : Error(ExitCode::usage, message) {}
};

class InfraError : public Error {
 public:
  explicit InfraError(const std::string& message) : Error(ExitCode::infrastructure, message) {}
};

}  // namespace raygate
