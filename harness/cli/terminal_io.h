// The world the measuring commands run the pipeline in: real child processes, the steady clock,
// and progress on this terminal (or plain lines in a CI log).
#pragma once

#include <cstdio>

#include "cli/progress.h"
#include "pipeline/progress.h"
#include "runner/executor.h"

namespace raygate::cli {

struct TerminalIo {
  SystemExecutor executor;
  SteadyClock clock;
  Progress progress{stdout, is_terminal(stdout)};
  PipelineIo io{executor, clock, progress};
};

}  // namespace raygate::cli
