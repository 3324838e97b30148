// The world the measuring commands run the pipeline in: real child processes, the steady clock,
// and progress on standard error, rewritten in place on a terminal, plain lines in a CI log, or
// nothing with --quiet (docs/cli.md: standard output carries only results).
#pragma once

#include <cstdio>

#include "cli/console.h"
#include "cli/terminal_progress.h"
#include "pipeline/pipeline_io.h"
#include "runner/executor.h"

namespace raygate::cli {

struct TerminalIo {
  explicit TerminalIo(const Console& console)
      : progress(console.quiet() ? nullptr : stderr, is_terminal(stderr)) {}

  SystemExecutor executor;
  SteadyClock clock;
  Progress progress;
  PipelineIo io{executor, clock, progress};
};

}  // namespace raygate::cli
