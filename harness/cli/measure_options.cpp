#include "cli/measure_options.h"

#include <fmt/core.h>

#include "compare/golden.h"
#include "core/error.h"
#include "core/process.h"
#include "core/sha256.h"
#include "runner/timing/timing_modes.h"

namespace raygate::cli {

namespace {

// --timing's help: one clause per mode the registry offers (runner/timing/modes.def).
std::string timing_help() {
  std::string help = "how runs are timed, both sides by the same clock:";
  for (const TimingMode* mode : timing_modes()) {
    if (!mode->command_line_choice()) continue;
    help += fmt::format(" {}: {};", mode->name(), mode->description());
  }
  return help + " (default: the adapter's)";
}

}  // namespace

void add_measure_options(CLI::App& command, MeasureArgs& args) {
  command.add_option("--repo", args.repo, "the tracer's git repository: a path or a URL")
      ->capture_default_str();
  command.add_option("--adapter", args.adapter,
                     "adapter file, or the name of a shipped adapter (raygate-baseline-bbox, ...)")
      ->required();
  command.add_option("--suite", args.suite, "suite name or file")->capture_default_str();
  command.add_option("--scene", args.scenes, "measure only these suite scene ids (repeatable)");
  command.add_option("--cache-dir", args.cache_dir,
                     "worktrees, builds, scenes and run files go here")
      ->capture_default_str();
  command.add_option("--golden-dir", args.golden_dir,
                     "golden images (default: golden/<adapter name>/, or the set whose manifest "
                     "shares it with the adapter; a tracer without goldens is checked against "
                     "none)");
  command.add_option("--baseline", args.baseline, "raygate-baseline executable to use");
  command.add_option("--schedule", args.schedule,
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
  command.add_option("--duet-cpus", args.duet_cpus, "the two CPUs of the duet schedule")
      ->delimiter(',')
      ->capture_default_str();
  command.add_option("--warmup", args.warmup, "untimed runs per program before the rounds")
      ->check(CLI::Range(0, 10))
      ->capture_default_str();
  command.add_option("--target", args.stopping.target_relative_half_width,
                     "stop a scene once the ratio's 95% CI half-width is below this fraction")
      ->check(CLI::Range(0.0001, 1.0))
      ->capture_default_str();
  command.add_option("--min-rounds", args.stopping.min_rounds,
                     "rounds before the stopping rule applies")
      ->check(CLI::Range(2, 1000))
      ->capture_default_str();
  command.add_option("--max-rounds", args.stopping.max_rounds, "round budget per scene")
      ->check(CLI::Range(1, 100000))
      ->capture_default_str();
  command.add_option("--max-seconds", args.stopping.max_seconds,
                     "time budget per scene, in seconds")
      ->check(CLI::Range(0.0, 1e7))
      ->capture_default_str();
  command.add_option("--max-minutes", args.stopping.max_minutes,
                     "time budget of the whole measurement, shared by the scenes still to "
                     "measure; 0 = none")
      ->check(CLI::Range(0.0, 1e6))
      ->capture_default_str();
  command.add_option("--timing", args.metric, timing_help())
      ->check(CLI::IsMember(timing_mode_choices()));
  command.add_option("--jobs", args.jobs, "parallel build jobs (default: all allowed CPUs)");
  command.add_option("--policy", args.policy,
                     "gate policy file: slowdown limit, significance, image thresholds "
                     "(docs/gate.md)");
}

void add_baseline_rounds_option(CLI::App& command, MeasureArgs& args) {
  command.add_option("--baseline-rounds", args.baseline_rounds,
                     "rounds per scene the baseline joins (the change of head against base "
                     "needs none; the normalized ratios need a few); 0 = every round")
      ->check(CLI::Range(0, 100000))
      ->capture_default_str();
}

void add_shard_options(CLI::App& command, MeasureArgs& args) {
  command.add_option("--shard", args.shard,
                     "measure only shard K of N of the selected scenes (1 <= K <= N), split by "
                     "expected cost the same way on every machine; join with raygate merge");
  command.add_option("--shard-costs", args.shard_costs,
                     "results document of the suite whose scene times are the expected costs "
                     "(default: every scene costs the same; docs/shards.md)");
}

namespace {

std::filesystem::path find_adapter(const std::string& name, const std::filesystem::path& data_root) {
  const std::filesystem::path direct(name);
  if (std::filesystem::exists(direct)) return direct;
  const std::filesystem::path shipped = data_root / "adapters" / (name + ".json");
  if (name.find('/') == std::string::npos && std::filesystem::exists(shipped)) return shipped;
  throw UsageError(fmt::format("adapter '{}' not found: not a file, and not a shipped adapter "
                               "(see {}/adapters/)",
                               name, data_root.string()));
}

std::filesystem::path pick_golden_dir(const MeasureArgs& args, const ToolPaths& tools,
                                      const Adapter& adapter) {
  if (!args.golden_dir.empty()) return args.golden_dir;
  // Never the baseline's for another tracer: its shading differs by design (compare/golden.h).
  return adapter_golden_dir(tools.data_root / "golden", adapter.name);
}

// The selection's shard named by --shard, and its record for the document.
void apply_shard(const MeasureArgs& args, MeasureContext& c) {
  if (args.shard.empty()) {
    if (!args.shard_costs.empty()) throw UsageError("--shard-costs needs --shard K/N");
    return;
  }
  ShardRecord record;
  record.spec = parse_shard(args.shard);
  for (const SuiteScene& scene : c.scenes) record.suite_scenes.push_back(scene.id);
  std::map<std::string, double> expected_seconds;
  if (!args.shard_costs.empty()) {
    const ResultsDocument costs = read_results(args.shard_costs);
    if (costs.suite != c.suite.name) {
      throw UsageError(fmt::format("--shard-costs {}: a document of suite '{}', not '{}'; give "
                                   "one measured on the suite being split",
                                   args.shard_costs, costs.suite, c.suite.name));
    }
    expected_seconds = expected_seconds_from(costs);
    // By content, not path: every job of the matrix must name the same costs to split alike.
    record.cost_basis = "seconds_spent of results document sha256:" +
                        sha256_file_hex(args.shard_costs);
  }
  c.scenes = shard_scenes(c.scenes, record.spec, expected_seconds);
  c.shard = std::move(record);
}

// The default pinning (ScheduleOptions::round_cpus): a one-thread tracer on the alternate
// schedule, unless --pin names CPUs or --no-pin asks for none. A tracer with more threads needs
// more CPUs than one, and one that pins itself (adapter pin_cpus) has chosen.
std::vector<int> default_round_cpus(const MeasureArgs& args, const MeasureContext& c) {
  if (args.no_pin && !args.pin_cpus.empty()) {
    throw UsageError("--no-pin and --pin exclude each other");
  }
  if (args.no_pin || c.schedule.kind != ScheduleKind::alternate || !args.pin_cpus.empty()) {
    return {};
  }
  if (c.adapter.threads > 1 || c.adapter.pin_cpus) return {};
  return allowed_cpu_list();
}

}  // namespace

MeasureContext load_measure_context(const MeasureArgs& args) {
  if (args.repo.empty()) {
    throw UsageError("--repo is empty: give the tracer's repository, a path or a URL (default: .)");
  }
  MeasureContext c;
  c.tools = locate_tools(args.baseline);
  c.adapter = load_adapter(find_adapter(args.adapter, c.tools.data_root));
  c.suite = load_suite(args.suite, c.tools.data_root);
  c.scenes = select_scenes(c.suite, args.scenes);
  apply_shard(args, c);
  if (args.cache_dir.empty()) throw UsageError("--cache-dir is empty: give a directory");
  if (std::error_code error; std::filesystem::exists(args.cache_dir, error) &&
                             !std::filesystem::is_directory(args.cache_dir, error)) {
    throw UsageError(fmt::format("--cache-dir {}: exists and is not a directory", args.cache_dir));
  }
  c.cache_dir = std::filesystem::absolute(args.cache_dir);
  c.golden_dir = pick_golden_dir(args, c.tools, c.adapter);
  c.schedule.kind = args.schedule == "duet" ? ScheduleKind::duet : ScheduleKind::alternate;
  c.schedule.warmup_runs = args.warmup;
  c.schedule.pin_cpus = args.pin_cpus;
  c.schedule.duet_cpus = args.duet_cpus;
  c.schedule.round_cpus = default_round_cpus(args, c);
  c.schedule.normalizer_rounds = args.baseline_rounds;
  if (c.schedule.kind == ScheduleKind::duet &&
      (args.duet_cpus.size() != 2 || args.duet_cpus[0] == args.duet_cpus[1])) {
    throw UsageError("--duet-cpus needs two different CPUs, e.g. --duet-cpus 0,1");
  }
  c.stopping = args.stopping;
  c.stopping.max_rounds = std::max(c.stopping.max_rounds, std::size_t{1});
  if (c.stopping.max_rounds < c.stopping.min_rounds) c.stopping.min_rounds = c.stopping.max_rounds;
  if (!args.policy.empty()) c.policy = load_policy(args.policy);
  c.jobs = args.jobs;
  for (const std::string& warning : choose_timing(c, args.metric, !args.policy.empty())) {
    fmt::print(stderr, "warning: {}\n", warning);
  }
  return c;
}

}  // namespace raygate::cli
