#include "pipeline/measure_options.h"

#include <fmt/core.h>

#include <algorithm>
#include <map>

#include "compare/golden.h"
#include "core/error.h"
#include "core/process.h"
#include "core/sha256.h"
#include "pipeline/adapter_check.h"
#include "pipeline/adapter_summary.h"

namespace raygate {

namespace {

// A folder option (--cache-dir, --golden-dir): refused when given empty (it would silently
// mean the current directory or the default) or when it names a file.
void check_folder_option(const std::string& option, const std::filesystem::path& folder) {
  if (folder.empty()) throw UsageError(fmt::format("{} is empty: give a directory", option));
  std::error_code error;
  const bool exists = std::filesystem::exists(folder, error);
  // Found only after the build before, when the first golden was read.
  if (error == std::errc::filename_too_long) {
    throw UsageError(fmt::format(
        "{}: the path is too long for the file system (a name has at most 255 bytes)", option));
  }
  if (exists && !std::filesystem::is_directory(folder, error)) {
    throw UsageError(fmt::format("{} {}: exists and is not a directory", option, folder.string()));
  }
}

// The cache and the folders raygate keeps in it: a file where one of them goes would fail
// only after building, in the file system's words.
void check_cache_dir(const std::string& cache_dir) {
  check_folder_option("--cache-dir", cache_dir);
  for (const char* kept : {"builds", "repos", "runs", "scenes", "simulated-baseline"}) {
    const std::filesystem::path folder = std::filesystem::path(cache_dir) / kept;
    if (std::error_code error;
        std::filesystem::exists(folder, error) && !std::filesystem::is_directory(folder, error)) {
      throw UsageError(fmt::format(
          "--cache-dir {}: {} is a file, not a folder (raygate keeps its {} there); move it "
          "away or give another --cache-dir",
          cache_dir, folder.string(), kept));
    }
  }
}

std::filesystem::path pick_golden_dir(const MeasureOptions& args, const ToolPaths& tools,
                                      const Adapter& adapter) {
  if (args.golden_dir) {
    check_folder_option("--golden-dir", *args.golden_dir);
    // Absolute: the document records each golden's path, and a report is read from the run's
    // folder, where "my-tracer/golden/tetra.png" named nothing ("image not found").
    return std::filesystem::absolute(*args.golden_dir);
  }
  // Never the baseline's for another tracer: its shading differs by design (compare/golden.h).
  return adapter_golden_dir(tools.data_root / "golden", adapter.name);
}

// The selection's shard named by --shard, and its record for the document.
void apply_shard(const MeasureOptions& args, MeasureContext& c) {
  if (args.shard.empty()) {
    if (!args.shard_costs.empty()) throw UsageError("--shard-costs needs --shard K/N");
    return;
  }
  ShardRecord record;
  record.spec = parse_shard(args.shard);
  std::string contents = c.suite.sampling + "\n";
  for (const SuiteScene& scene : c.scenes) {
    record.suite_scenes.push_back(scene.id);
    contents += fmt::format("{}\t{}\t{}\t{}x{}\n", scene.id, scene.scene, scene.size, scene.width,
                            scene.height);
  }
  record.suite_sha256 = sha256_hex(contents);
  std::map<std::string, double> expected_seconds;
  if (!args.shard_costs.empty()) {
    ResultsDocument costs;
    try {
      costs = read_results(args.shard_costs);
    } catch (const UsageError& e) {  // the path alone did not say which option named it
      throw UsageError(std::string("--shard-costs: ") + e.what());
    }
    if (costs.suite != c.suite.name) {
      throw UsageError(
          fmt::format("--shard-costs {}: a document of suite '{}', not '{}'; give "
                      "one measured on the suite being split",
                      args.shard_costs, costs.suite, c.suite.name));
    }
    expected_seconds = expected_seconds_from(costs);
    // By content, not path: every job of the matrix must name the same costs to split alike.
    record.cost_basis =
        "seconds_spent of results document sha256:" + sha256_file_hex(args.shard_costs);
  }
  c.scenes = shard_scenes(c.scenes, record.spec, expected_seconds);
  c.shard = std::move(record);
}

// The default pinning (ScheduleOptions::round_cpus): a one-thread tracer on the alternate
// schedule, unless --pin names CPUs or --no-pin asks for none. A tracer with more threads needs
// more CPUs than one, and one that pins itself (adapter pin_cpus) has chosen.
std::vector<int> default_round_cpus(const MeasureOptions& args, const MeasureContext& c) {
  if (args.no_pin && !args.pin_cpus.empty()) {
    throw UsageError("--no-pin and --pin exclude each other");
  }
  if (args.no_pin || c.schedule.kind != ScheduleKind::alternate || !args.pin_cpus.empty()) {
    return {};
  }
  if (c.adapter.threads > 1 || c.adapter.pin_cpus) return {};
  return allowed_cpu_list();
}

// The duet's two CPUs, 0 and 1 unless given. Given to the alternate schedule, they would go unused
// while the user believed the programs ran there.
std::vector<int> duet_cpus(const MeasureOptions& args, ScheduleKind kind) {
  if (kind != ScheduleKind::duet) {
    if (!args.duet_cpus.empty()) {
      throw UsageError(
          "--duet-cpus applies to the duet schedule; add --schedule duet, or leave it out");
    }
    return {0, 1};  // recorded in settings as before; no run uses them
  }
  if (args.duet_cpus.empty()) return {0, 1};
  for (const int cpu : args.duet_cpus) {
    if (cpu < 0) throw UsageError(fmt::format("--duet-cpus {}: CPUs are numbered from 0", cpu));
  }
  if (args.duet_cpus.size() != 2 || args.duet_cpus[0] == args.duet_cpus[1]) {
    throw UsageError("--duet-cpus needs two different CPUs, e.g. --duet-cpus 0,1");
  }
  return args.duet_cpus;
}

// CPUs named on the command line must be ones raygate may run on: another number fails every
// run's sched_setaffinity, which would read as the tracer not running (exit 3), not as the
// option's mistake.
void check_named_cpus(const MeasureOptions& args, ScheduleKind kind) {
  const std::vector<int> allowed = allowed_cpu_list();
  if (allowed.empty()) return;  // not known here: the runs say
  const auto check = [&](const char* option, const std::vector<int>& cpus) {
    for (const int cpu : cpus) {
      if (std::find(allowed.begin(), allowed.end(), cpu) != allowed.end()) continue;
      std::string list;
      for (const int a : allowed) {
        if (!list.empty()) list += ',';
        list += std::to_string(a);
      }
      throw UsageError(
          fmt::format("{} {}: not a CPU raygate may run on (allowed: {})", option, cpu, list));
    }
  };
  check("--pin", args.pin_cpus);
  if (kind == ScheduleKind::duet) check("--duet-cpus", duet_cpus(args, kind));
  // A duet places its programs on --duet-cpus: a --pin beside it would be silently not used.
  if (kind == ScheduleKind::duet && !args.pin_cpus.empty()) {
    throw UsageError("--pin applies to the alternate schedule; a duet runs on --duet-cpus");
  }
  for (std::size_t i = 0; i < args.pin_cpus.size(); ++i) {
    if (std::count(args.pin_cpus.begin(), args.pin_cpus.begin() + i, args.pin_cpus[i]) > 0) {
      throw UsageError(fmt::format("--pin names CPU {} twice", args.pin_cpus[i]));
    }
  }
}

}  // namespace

MeasureContext load_measure_context(const MeasureOptions& args,
                                    std::vector<std::string>& warnings) {
  if (args.repo.empty()) {
    throw UsageError("--repo is empty: give the tracer's repository, a path or a URL (default: .)");
  }
  MeasureContext c;
  c.tools = locate_tools(args.baseline);
  c.adapter = load_adapter(find_adapter(args.adapter, c.tools.data_root));
  c.suite = load_suite(args.suite, c.tools.data_root);
  c.scenes = select_scenes(c.suite, args.scenes);
  apply_shard(args, c);
  check_cache_dir(args.cache_dir);
  c.cache_dir = std::filesystem::absolute(args.cache_dir);
  c.golden_dir = pick_golden_dir(args, c.tools, c.adapter);
  c.schedule.kind = args.schedule == "duet" ? ScheduleKind::duet : ScheduleKind::alternate;
  c.schedule.warmup_runs = args.warmup;
  c.schedule.pin_cpus = args.pin_cpus;
  c.schedule.duet_cpus = duet_cpus(args, c.schedule.kind);
  c.schedule.round_cpus = default_round_cpus(args, c);
  c.schedule.normalizer_rounds = args.baseline_rounds;
  c.schedule.repeats = std::max<std::size_t>(args.repeats, 1);
  if (args.no_idle_poll) c.idle_poll_device.clear();
  c.repeat_where_it_pays = args.repeats == 0 && c.schedule.kind == ScheduleKind::alternate;
  if (c.schedule.kind == ScheduleKind::duet && args.repeats > 1) {
    throw UsageError(
        "--repeats applies to the alternate schedule (a duet round runs each "
        "program once)");
  }
  check_named_cpus(args, c.schedule.kind);
  // Sweep 12: a 2-thread adapter with pin_cpus ran on both duet CPUs while the other side ran.
  if (c.schedule.kind == ScheduleKind::duet && c.adapter.threads > 1) {
    throw UsageError(fmt::format(
        "--schedule duet runs two programs at once, one CPU each, but {}'s tracer runs {} "
        "threads (its adapter's threads); measure it with the alternate schedule",
        c.adapter.name, c.adapter.threads));
  }
  c.stopping = args.stopping;
  c.stopping.max_rounds = std::max(c.stopping.max_rounds, std::size_t{1});
  if (c.stopping.max_rounds < c.stopping.min_rounds) c.stopping.min_rounds = c.stopping.max_rounds;
  if (!args.policy.empty()) c.policy = load_policy(args.policy);
  c.jobs = args.jobs;
  c.input_files = {{"--adapter", c.adapter.file, true},
                   {"--suite", c.suite.path, true},
                   {"--policy", args.policy, true},
                   {"--shard-costs", args.shard_costs, true}};
  warnings = choose_timing(c, args.metric, !args.policy.empty());
  if (const std::string note = repository_unused_note(c.adapter); !note.empty()) {
    warnings.push_back(note);
  }
  return c;
}

}  // namespace raygate
