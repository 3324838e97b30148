// What the pipeline says while it works, and the processes and time it works with. The pipeline
// prints nothing itself: whoever runs it (the command line, a test) passes a ProgressSink, an
// Executor and a Clock, so the same code runs against a terminal and against fakes.
#pragma once

#include <cstddef>
#include <string>

#include "runner/executor.h"

namespace raygate {

// The scene being measured, after each round (a terminal rewrites one line from it).
struct ProgressState {
  std::size_t scene_index = 0;  // 1-based
  std::size_t scene_count = 0;
  std::string scene_id;
  std::size_t round = 0;
  double ratio = 0.0;                // 0 until known
  double relative_half_width = 0.0;  // of the ratio's 95% CI
  double eta_seconds = -1.0;         // < 0: unknown
};

class ProgressSink {
 public:
  virtual ~ProgressSink() = default;
  // The scene in flight, after each round.
  virtual void update(const ProgressState& state) = 0;
  // A line of the measurement's own account: what is measured, each finished scene, each step
  // of a bisection (the command line prints these on standard output).
  virtual void line(const std::string& text) = 0;
  // What is being done before measuring can start: builds (the command line: standard error).
  virtual void status(const std::string& text) = 0;
};

// Says nothing: for callers that only want the document.
class SilentProgress final : public ProgressSink {
 public:
  void update(const ProgressState&) override {}
  void line(const std::string&) override {}
  void status(const std::string&) override {}
};

// The world a pipeline step runs in.
struct PipelineIo {
  Executor& executor;
  Clock& clock;
  ProgressSink& progress;
};

}  // namespace raygate
