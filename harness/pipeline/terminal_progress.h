// What a long measurement says while it runs: the measuring commands' ProgressSink. On a
// terminal: one line, rewritten in place ("[3/13] mount  round 7  ratio 0.512 ±0.8%  ETA 1m40s").
// Elsewhere (CI logs): one plain line per finished scene, nothing rewritten, so logs stay
// readable. All of it is chatter: the command line passes standard error (docs/cli.md), or no
// stream with --quiet. Every text passes core/sanitize.h's terminal_text here, the one place
// progress reaches the terminal: a commit subject's ESC or BEL is shown as "\x1b", not obeyed.
#pragma once

#include <cstdio>
#include <string>

#include "pipeline/pipeline_io.h"
#include "runner/executor.h"

namespace raygate {

class TerminalProgress final : public ProgressSink {
 public:
  // interactive: rewrite one line (use is_terminal(stream) to decide). A null stream says
  // nothing (--quiet).
  TerminalProgress(std::FILE* stream, bool interactive)
      : stream_(stream), interactive_(interactive) {}
  ~TerminalProgress() override;

  void update(const ProgressState& state) override;
  // A finished scene's line; on a terminal it replaces the progress line.
  void line(const std::string& text) override;
  // Build steps and the like: a line like any other.
  void status(const std::string& text) override;

 private:
  void clear();
  std::FILE* stream_;
  bool interactive_;
  bool dirty_ = false;  // a progress line is on screen
};

// "1m40s", "12s", "2h03m".
std::string format_duration(double seconds);

// The world the measuring commands run the pipeline in: real child processes, the steady clock,
// and progress on standard error, rewritten in place on a terminal, plain lines in a CI log, or
// nothing with --quiet (docs/cli.md: standard output carries only results).
struct TerminalIo {
  TerminalIo(bool quiet, bool terminal) : progress(quiet ? nullptr : stderr, terminal) {}

  SystemExecutor executor;
  SteadyClock clock;
  TerminalProgress progress;
  PipelineIo io{executor, clock, progress};
};

}  // namespace raygate
