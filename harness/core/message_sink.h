// What a library step says to the person running it besides its result: chatter, warnings, and
// problems in their own words. Libraries print nothing themselves; the command line's Console
// (report/terminal.h) says these on standard error, and a test records them.
#pragma once

#include <string>

namespace raygate {

class MessageSink {
 public:
  virtual ~MessageSink() = default;
  // A line of chatter: where a file went, what was stored (dropped with --quiet).
  virtual void info(const std::string& text) const = 0;
  // One line, said as "raygate: warning: TEXT" whatever --quiet says.
  virtual void warning(const std::string& text) const = 0;
  // Lines said exactly as given (their own "raygate: warning: " and indented continuation).
  virtual void problem(const std::string& text) const = 0;
};

}  // namespace raygate
