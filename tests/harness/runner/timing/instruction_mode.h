// A timing mode raygate does not ship, written as a user would add one (one file): an
// instruction counter in the manner of `perf stat -x, -e instructions:u`. It wraps the process,
// reads perf's output into a counter with its own unit, and is exact (a count repeats) without
// running under cachegrind. The tests register it beside the shipped modes to show that nothing
// else in raygate needs an edit for it (new_mode_test.cpp), and that the baseline contender goes
// through it as the tracer's does (contender_test.cpp).
#pragma once

#include <charconv>
#include <string>
#include <vector>

#include "core/fs.h"
#include "runner/timing/timing_mode.h"

namespace raygate::test {

inline constexpr CounterSpec kInstructions{"instructions", "instructions",
                                           "user-space instructions retired (perf stat)"};

class InstructionMode final : public TimingMode {
 public:
  std::string_view name() const override { return "instructions"; }
  std::string_view description() const override { return "instructions retired (perf stat)"; }
  std::string_view tracer_clock() const override { return "instructions"; }
  std::string_view baseline_clock() const override { return "instructions"; }
  bool exact() const override { return true; }
  std::string_view unit() const override { return "instructions"; }
  std::vector<CounterSpec> counters() const override { return {kInstructions}; }

  std::optional<double> seconds(const RunRecord& run) const override {
    const auto found = run.counters.find(std::string(kInstructions.name));
    if (found == run.counters.end()) return std::nullopt;
    return found->second.value;
  }

  ProcessSpec wrap(ProcessSpec spec, const std::filesystem::path& run_dir,
                   const std::optional<Cachegrind>& /*simulator*/) const override {
    std::vector<std::string> argv{
        "perf", "stat", "-x,", "-e", "instructions:u", "-o", (run_dir / "perf.txt").string(), "--"};
    argv.insert(argv.end(), spec.argv.begin(), spec.argv.end());
    spec.argv = std::move(argv);
    return spec;
  }

  // perf's CSV line: "<count>,,instructions:u,..."; "<not counted>" fails the run.
  void collect(RunRecord& run, const std::filesystem::path& run_dir) const override {
    const std::string text = read_file(run_dir / "perf.txt");
    const std::size_t at = text.find(",,instructions");
    const std::size_t line = at == std::string::npos ? at : text.rfind('\n', at);
    const std::size_t begin = line == std::string::npos ? 0 : line + 1;
    double count = 0;
    const char* const last = text.data() + (at == std::string::npos ? 0 : at);
    const auto [end, ec] = std::from_chars(text.data() + begin, last, count);
    if (at == std::string::npos || ec != std::errc() || end != last) {
      run.ok = false;
      run.failure = "perf counted no instructions";
      return;
    }
    run.counters[std::string(kInstructions.name)] = {count, std::string(kInstructions.unit)};
  }
};

}  // namespace raygate::test
