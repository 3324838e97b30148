#include "cli/measure_options.h"

#include <fmt/core.h>

#include "cli/subcommand.h"
#include "runner/timing/timing_modes.h"

namespace raygate::cli {

void add_tracer_options(CLI::App& command, MeasureArgs& args) {
  command.add_option("--repo", args.repo, "the tracer's git repository: a path or a URL")
      ->capture_default_str();
  command
      .add_option("--adapter", args.adapter,
                  "adapter file, or the name of a shipped adapter (raygate-baseline-bbox, ...)")
      ->required();
  command.add_option("--suite", args.suite, "suite name or file")->capture_default_str();
  command.add_option("--scene", args.scenes, "only these suite scene ids (repeatable)");
  command
      .add_option("--cache-dir", args.cache_dir, "worktrees, builds, scenes and run files go here")
      ->capture_default_str()
      ->check(writable_folder());
  command.add_option("--baseline", args.baseline, "raygate-baseline executable to use");
  add_bounded_option(command, "--jobs", args.jobs, 0, 4096,
                     "parallel build jobs; 0 = all allowed CPUs");
}

namespace {

// Where and how the programs run: the schedule, CPUs, idle CPUs, warm-up, repeats and the clock.
void add_schedule_options(CLI::App& command, MeasureArgs& args) {
  command
      .add_option("--schedule", args.schedule,
                  "alternate: one program at a time, order alternating per round; duet: "
                  "baseline and tracer at once, each on its own CPU (compare: the baseline "
                  "alone, then base and head at once)")
      ->check(CLI::IsMember({"alternate", "duet"}))
      ->capture_default_str();
  command.add_option("--pin", args.pin_cpus, "pin every run to these CPUs (alternate schedule)")
      ->delimiter(',');
  command.add_flag("--no-pin", args.no_pin,
                   "do not pin: by default each round of a one-thread tracer runs on one CPU, "
                   "changing every second round");
  command.add_flag("--no-idle-poll", args.no_idle_poll,
                   "let idle CPUs sleep (by default they poll while raygate measures, "
                   "/dev/cpu_dma_latency: a CPU woken from sleep runs slow)");
  command.add_option("--duet-cpus", args.duet_cpus, "the two CPUs of the duet schedule (0,1)")
      ->delimiter(',');
  add_bounded_option(command, "--warmup", args.warmup, 0, 10,
                     "untimed runs per program before the rounds");
  command.add_option("--timing", args.metric, timing_choices_help())
      ->check(CLI::IsMember(timing_mode_choices()));
  // No default shown: not given, it is one run, and each scene chooses (see the help).
  command
      .add_option("--repeats", args.repeats,
                  "runs of each program per round, interleaved; the round keeps each one's "
                  "fastest (steadier on a busy machine, at that many times the runs). Default: "
                  "one, and a scene whose rounds show that the fastest of two gets there sooner "
                  "takes it (from the scene's 11th round on, in run and in compare)")
      ->check(CLI::Validator([](const std::string& t) { return number_problem(t, true, 1, 10); },
                             "", ""))
      ->check(CLI::Range(1, 10));
}

// When a scene, and the whole measurement, stops (measure/stopping_policy.h).
void add_stopping_options(CLI::App& command, MeasureArgs& args) {
  add_bounded_option(command, "--target", args.stopping.target_relative_half_width, 0.0001, 1.0,
                     "stop a scene once the ratio's 95% CI half-width is below this fraction");
  const CLI::Option* min_rounds =
      add_bounded_option(command, "--min-rounds", args.stopping.min_rounds, 2, 1000,
                         "rounds before the stopping rule applies");
  add_bounded_option(command, "--max-rounds", args.stopping.max_rounds, 1, 100000,
                     "round budget per scene");
  // Given, it cannot hold; a default minimum gives way (pipeline/measure_options.cpp).
  command.parse_complete_callback([min_rounds, &s = args.stopping] {
    if (min_rounds->count() == 0 || s.min_rounds <= s.max_rounds) return;
    throw UsageError(
        fmt::format("--min-rounds {} is above --max-rounds {}: a scene cannot need "
                    "more rounds than it may take; lower one or raise the other",
                    s.min_rounds, s.max_rounds));
  });
  add_bounded_option(command, "--max-seconds", args.stopping.max_seconds, 1.0, 1e7,
                     "time budget per scene, in seconds (a run is given at least 1 s)");
  add_bounded_option(command, "--max-minutes", args.stopping.max_minutes, 0.0, 1e6,
                     "time budget of the whole measurement, shared by the scenes still to "
                     "measure; 0 = none");
}

}  // namespace

void add_measure_options(CLI::App& command, MeasureArgs& args) {
  add_tracer_options(command, args);
  command.add_option("--golden-dir", args.golden_dir,
                     "golden images (default: golden/<adapter name>/, or the set whose manifest "
                     "shares it with the adapter; a tracer without goldens is checked against "
                     "none)");
  add_schedule_options(command, args);
  add_stopping_options(command, args);
  command
      .add_option("--policy", args.policy,
                  "gate policy file: slowdown limit, significance, image thresholds (docs/gate.md)")
      ->check(CLI::ExistingFile);  // raygate.toml's policy is then named with its line
}

void add_change_measure_options(CLI::App& command, MeasureArgs& args) {
  args.stopping = change_stopping_policy();
  args.baseline_rounds = kChangeBaselineRounds;
  add_measure_options(command, args);
  add_bounded_option(command, "--baseline-rounds", args.baseline_rounds, 0, 100000,
                     "rounds per scene the baseline joins (the change of head against base "
                     "needs none; the normalized ratios need a few); 0 = every round");
}

void add_shard_options(CLI::App& command, MeasureArgs& args) {
  command.add_option("--shard", args.shard,
                     "measure only shard K of N of the selected scenes (1 <= K <= N), split by "
                     "expected cost the same way on every machine; join with raygate merge");
  command.add_option("--shard-costs", args.shard_costs,
                     "results document of the suite whose scene times are the expected costs "
                     "(default: every scene costs the same; docs/shards.md)");
}

MeasureContext load_measure_context(const MeasureArgs& args) {
  std::vector<std::string> warnings;
  MeasureContext context = raygate::load_measure_context(args, warnings);
  for (const std::string& warning : warnings) fmt::print(stderr, "warning: {}\n", warning);
  return context;
}

}  // namespace raygate::cli
