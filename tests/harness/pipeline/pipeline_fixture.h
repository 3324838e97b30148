// The pipeline in-process, as ninja tests its Builder with a fake command runner: a throwaway git
// repository of a "tracer" whose speed is a file it commits (cost: seconds per render), an
// adapter whose build copies that file (a real build through the builder, a few milliseconds),
// and a fake executor that never starts the tracer or the baseline: it answers each run with the
// committed cost (the baseline: one second), advances a fake clock by it, and leaves the image
// and stats files a real run would. So run, compare and bisect are exact, and take no time.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "adapter/adapter.h"
#include "checkout/git_fixture.h"
#include "checkout/repository.h"
#include "core/error.h"
#include "core/fs.h"
#include "pipeline/measure_context.h"
#include "pipeline/pipeline_io.h"
#include "runner/baseline_tool.h"
#include "runner/fake_executor.h"
#include "runner/suite.h"

namespace raygate::testing {

// Everything the pipeline said, by channel.
class RecordingProgress final : public ProgressSink {
 public:
  void update(const ProgressState& state) override { updates.push_back(state); }
  void line(const std::string& text) override {
    lines.push_back(text);
    if (on_line) on_line(text);
  }
  void status(const std::string& text) override { statuses.push_back(text); }

  // The lines that contain `part`.
  std::vector<std::string> lines_with(const std::string& part) const;

  std::vector<ProgressState> updates;
  std::vector<std::string> lines;
  std::vector<std::string> statuses;
  // Called after each line is recorded: a test's way to act at a point of the pipeline (send a
  // signal after a given scene).
  std::function<void(const std::string&)> on_line;
};

class PipelineTest : public ::testing::Test {
 protected:
  PipelineTest();

  // Commits the tracer at `cost` seconds per render ("" for a commit that does not build: no
  // cost file, so the build's copy fails); returns the sha.
  std::string commit_tracer(const std::string& cost, const std::string& message);

  // The fake tracer's seconds per render in each run from now on are multiplied by this
  // factor, cycled over its runs (noise for the budget tests).
  void set_tracer_noise(std::vector<double> factors) { noise_ = std::move(factors); }

  TempDir dir_;
  GitFixture repo_;
  FakeClock clock_;
  FakeExecutor executor_{clock_};
  RecordingProgress progress_;
  PipelineIo io_{executor_, clock_, progress_};
  MeasureContext context_;
  BaselineTool baseline_;

 private:
  std::optional<double> seconds_of(const ProcessSpec& spec);
  std::vector<double> noise_;
  std::size_t tracer_runs_ = 0;
};

}  // namespace raygate::testing
