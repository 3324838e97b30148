// One way of timing a run (DESIGN.md §6, §11): which number of a finished run the ratio divides,
// the same clock on the tracer's side and on the baseline's, and the names results documents
// carry for it. Each mode is one file in this folder and one line in modes.def; everything that
// used to ask "which mode is this?" asks the mode instead (timing_modes.h finds one by name).
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "adapter/adapter.h"
#include "core/process.h"
#include "runner/cachegrind.h"
#include "runner/run_record.h"
#include "runner/scheduler.h"
#include "runner/suite.h"

namespace raygate {

struct StoppingPolicy;

// What a mode may change in a measurement before anything runs (prepare()): the schedule, the
// stopping budget, the gate's default limit, the simulator it needs, and warnings for the user.
struct TimingPlan {
  const Suite& suite;
  int threads = 1;                            // the adapter's
  const std::filesystem::path& adapter_file;  // for messages
  ScheduleOptions& schedule;
  StoppingPolicy& stopping;
  std::optional<double> default_max_slowdown;  // used when no policy file is given
  std::optional<Cachegrind> cachegrind;        // the simulator, for a mode under cachegrind
  std::vector<std::string> warnings;           // one line each, without "warning: "
};

// A reading a mode adds to its runs beyond the process's own (RunRecord::counters): its name in
// documents, its unit, and what it is. The registry's counters are the only ones a document may
// carry (runner/timing/timing_check.h), so a mode declares every counter it records.
struct CounterSpec {
  std::string_view name;  // the key in a run's "counters": "startup_seconds"
  std::string_view unit;  // "seconds", "cycles", "instructions"
  std::string_view description;
};

class TimingMode {
 public:
  virtual ~TimingMode() = default;

  // The word of `--timing` and of settings.metric: "wall", "cpu", "user", "sim", ...
  virtual std::string_view name() const = 0;
  // What it measures, for --timing's help and `raygate adapter`.
  virtual std::string_view description() const = 0;
  // settings.tracer_clock and baseline.timing in results documents (results/series.h keys
  // history on them, so a mode's names never change once documents carry them).
  virtual std::string_view tracer_clock() const = 0;
  virtual std::string_view baseline_clock() const = 0;
  // The adapter's timing.source this mode belongs to. A process clock chosen with --timing
  // replaces a process-timed adapter's metric; a process-timed adapter names its clock by the
  // mode's name ("metric": "wall").
  virtual TimingSource source() const { return TimingSource::process; }
  // Offered by --timing (a reported time needs the adapter's regex, so it is not).
  virtual bool command_line_choice() const { return true; }
  // Two separate questions the pipeline asks (they were one, "counted", before):
  // Does every run repeat its reading exactly? Then a change can be exact (measure/change.h),
  // warm-ups and held idle CPUs buy nothing, and the baseline runs without --stats (formatting
  // its seconds would make its count unrepeatable).
  virtual bool exact() const { return false; }
  // Do runs execute under cachegrind? Then the mode needs the simulator (prepare() finds it),
  // the baseline's counts can be cached by cachegrind's version, and --explain reads the runs'
  // own cachegrind files.
  virtual bool under_cachegrind() const { return false; }
  // The unit of seconds()'s number, recorded as settings.unit and printed beside every measure.
  virtual std::string_view unit() const { return "seconds"; }
  // The counters collect() adds to a run (CounterSpec); none by default.
  virtual std::vector<CounterSpec> counters() const { return {}; }

  // The number the ratio uses from a finished, successful run of either side; nullopt when the
  // run does not carry it.
  virtual std::optional<double> seconds(const RunRecord& run) const = 0;

  // How a run's process starts under this mode (cachegrind's wraps it in the simulator, its
  // files in `run_dir`); the process itself by default.
  virtual ProcessSpec wrap(ProcessSpec spec, const std::filesystem::path& /*run_dir*/,
                           const std::optional<Cachegrind>& /*simulator*/) const {
    return spec;
  }
  // What a successful run left besides its process times (a counted mode reads its counts, the
  // reported mode records the start-up it leaves out); may fail the run. Both contenders call
  // it after they took their own readings (the process times, a reported time). Nothing by
  // default.
  virtual void collect(RunRecord& /*run*/, const std::filesystem::path& /*run_dir*/) const {}

  // The measurement's adjustments for this mode; none by default.
  virtual void prepare(TimingPlan& /*plan*/) const {}
};

// A mode that is only a clock: its names, its source, and which number of a run it reads. Most
// modes are one (wall, cpu, user, reported); make_clock_mode() makes the TimingMode. A clock may
// also derive counters from a run's readings (`derive`, run after both contenders' own
// readings), declared in `counters`.
struct ClockSpec {
  std::string_view name;
  std::string_view description;
  std::string_view tracer_clock;
  std::string_view baseline_clock;
  std::optional<double> (*seconds)(const RunRecord& run);
  TimingSource source = TimingSource::process;
  std::vector<CounterSpec> counters = {};
  void (*derive)(RunRecord& run) = nullptr;
};

std::unique_ptr<TimingMode> make_clock_mode(const ClockSpec& spec);

}  // namespace raygate
