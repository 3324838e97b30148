// The exit codes raygate promises (DESIGN.md §9). CI scripts branch on them, so they never change.
#pragma once

namespace raygate {

enum class ExitCode : int {
  pass = 0,            // everything measured; warnings allowed
  regression = 1,      // the change made a scene slower or its image wrong
  usage = 2,           // bad command line, adapter, policy or scene file
  infrastructure = 3,  // raygate could not check out, build or measure
  hung_up = 129,       // stopped by SIGHUP (128 + 1): its terminal or ssh session closed
  interrupted = 130,   // stopped by SIGINT (128 + 2), after writing what it had
  quit = 131,          // stopped by SIGQUIT (128 + 3, Ctrl-\), likewise
  terminated = 143,    // stopped by SIGTERM (128 + 15), likewise
};

constexpr int to_int(ExitCode code) { return static_cast<int>(code); }

}  // namespace raygate
