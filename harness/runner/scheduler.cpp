#include "runner/scheduler.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string_view>

#include "core/error.h"
#include "core/fs.h"

namespace raygate {

const RunRecord* SceneRuns::first_run(Role role) const { return first_run(role_name(role)); }

const RunRecord* SceneRuns::first_run(const std::string& role) const {
  if (const auto found = warmup.find(role); found != warmup.end()) {
    for (const RunRecord& run : found->second) {
      if (run.ok) return &run;
    }
  }
  for (const Round& round : rounds) {
    if (const auto found = round.runs.find(role); found != round.runs.end() && found->second.ok) {
      return &found->second;
    }
  }
  if (const auto found = partial_round.find(role);
      found != partial_round.end() && found->second.ok) {
    return &found->second;
  }
  return nullptr;
}

namespace {

// A run that succeeded in no measurable time (say a CPU-timed tracer whose work is done by a
// process it does not wait for) cannot be normalized: it fails, for its scene only, instead of
// throwing from the statistics and ending the whole suite.
RunRecord require_positive_time(RunRecord run, const std::string& role) {
  if (run.ok && !(run.seconds > 0.0 && std::isfinite(run.seconds))) {
    run.ok = false;
    run.failure = fmt::format(
        "{} run took {} s by its timing metric; a ratio needs a positive "
        "time",
        role, run.seconds);
  }
  return run;
}

// A run that wrote its scene file changed what every later run is timed on (a sweep's tracer
// appended 3000 spheres a run: the baseline's time grew with it, and the run passed). The run
// fails, so the scene is measured no further (exit 3).
// `during`: "it ran" for one run, "baseline and tracer ran at once" for a duet's pair.
RunRecord with_scene_checked(RunRecord run, const SceneInput& scene, const std::string& during) {
  for (const auto& [file, prepared] : scene.prepared_stamps) {
    const std::optional<FileStamp> now = file_stamp(file);  // gone: changed all the same
    if (now == prepared) continue;
    run.ok = false;
    run.failure = (run.failure.empty() ? "" : run.failure + "; ") +
                  fmt::format(
                      "the scene file {} changed while {} (a run reads its scene, never "
                      "writes it); the scene is measured no further",
                      file.string(), during);
    break;
  }
  return run;
}

// Runs one contender once; `label` names the run directory ("warmup-1", "round-007").
class RunLauncher {
 public:
  RunLauncher(const SceneInput& scene, Executor& executor, const std::filesystem::path& scene_dir)
      : scene_(scene), executor_(executor), scene_dir_(scene_dir) {}

  std::filesystem::path prepare(const Contender& contender, const std::string& label) const {
    const std::filesystem::path dir = scene_dir_ / contender.name() / label;
    std::filesystem::remove_all(dir);  // a re-run of an interrupted measurement starts clean
    std::filesystem::create_directories(dir);
    return dir;
  }

  RunRecord run(const Contender& contender, const std::string& label,
                const std::vector<int>& cpus) const {
    if (std::optional<RunRecord> known = contender.known_run(scene_)) return *known;
    const std::filesystem::path dir = prepare(contender, label);
    ProcessSpec spec = contender.command(scene_, dir);
    spec.metered = true;  // the run's peak memory is the contender's own, not raygate's
    if (!cpus.empty()) spec.cpu_affinity = cpus;
    return with_scene_checked(
        require_positive_time(contender.interpret(scene_, executor_.run(spec), spec, dir),
                              contender.name()),
        scene_, "it ran");
  }

  // Starts all at once, contender i pinned to cpus[i].
  std::vector<RunRecord> run_together(std::span<const Contender* const> contenders,
                                      const std::string& label,
                                      const std::vector<int>& cpus) const {
    std::vector<std::filesystem::path> dirs;
    std::vector<ProcessSpec> specs;
    for (std::size_t i = 0; i < contenders.size(); ++i) {
      dirs.push_back(prepare(*contenders[i], label));
      specs.push_back(contenders[i]->command(scene_, dirs.back()));
      specs.back().cpu_affinity = {cpus[i]};
      specs.back().metered = true;
    }
    const std::vector<ProcessResult> results = executor_.run_together(specs);
    std::vector<RunRecord> records;
    std::string who;  // both ran at once: either may have written it
    for (std::size_t i = 0; i < contenders.size(); ++i) {
      who += (who.empty() ? "" : " and ") + contenders[i]->name();
    }
    for (std::size_t i = 0; i < contenders.size(); ++i) {
      records.push_back(with_scene_checked(
          require_positive_time(contenders[i]->interpret(scene_, results[i], specs[i], dirs[i]),
                                contenders[i]->name()),
          scene_, who + " ran at once"));
    }
    return records;
  }

 private:
  const SceneInput& scene_;
  Executor& executor_;
  std::filesystem::path scene_dir_;
};

template <typename T>
std::vector<T> rotated(const std::vector<T>& items, std::size_t by) {
  std::vector<T> out(items);
  if (!out.empty())
    std::rotate(out.begin(), out.begin() + static_cast<long>(by % out.size()), out.end());
  return out;
}

// The order of a round's runs with each contender `repeats` times: the order over and over
// (A B C A B C), so no two runs of one contender are adjacent. The round keeps each one's
// fastest run, and a slow spell of the machine as long as two runs then slows at most one run of
// each; a mirrored order (A B C C B A) put C's two runs side by side, and one such spell made an
// identity compare's round read +16.9%. Which contender goes first rotates from round to round.
std::vector<const Contender*> interleaved(const std::vector<const Contender*>& order,
                                          std::size_t repeats) {
  std::vector<const Contender*> sequence;
  for (std::size_t k = 0; k < repeats; ++k) {
    sequence.insert(sequence.end(), order.begin(), order.end());
  }
  return sequence;
}

// The runs per contender of the next round: the chooser's, from the scene's runs so far, or the
// schedule's fixed number.
std::size_t repeats_of_round(const ScheduleOptions& options, const SceneRuns& so_far) {
  if (!options.repeats_from_rounds) return options.repeats;
  const std::size_t repeats = options.repeats_from_rounds(so_far);
  if (repeats < 1) throw std::logic_error("a round's repeats must be at least 1");
  return repeats;
}

// A round keeps each role's fastest run (by its timing metric: `seconds`).
void keep_fastest(std::map<std::string, RunRecord>& runs, const std::string& role, RunRecord run) {
  const auto found = runs.find(role);
  if (found == runs.end() || run.seconds < found->second.seconds) runs[role] = std::move(run);
}

void check_options(std::span<const Contender* const> contenders, const ScheduleOptions& options) {
  if (contenders.empty()) throw std::invalid_argument("measure_scene: no contenders");
  if (options.repeats < 1) throw UsageError("--repeats must be at least 1");
  if (options.kind != ScheduleKind::duet) return;
  if (options.repeats != 1 || options.repeats_from_rounds) {
    throw UsageError(
        "--repeats applies to the alternate schedule (a duet round runs each "
        "contender once)");
  }
  if (contenders.size() != 2 && contenders.size() != 3) {
    throw UsageError(
        fmt::format("the duet schedule runs two programs at once (baseline and "
                    "tracer, or base and head after the baseline); this "
                    "measurement has {}",
                    contenders.size()));
  }
  if (options.duet_cpus.size() < 2 || options.duet_cpus[0] == options.duet_cpus[1]) {
    throw UsageError("the duet schedule needs two different CPUs");
  }
}

// Whose run failed, and that run.
struct FailedRun {
  Role role;
  RunRecord run;
};

// A round's runs, or those it had when one failed.
struct RoundOutcome {
  Round round;
  std::optional<FailedRun> failure;
};

// A first visit's warm-ups: each contender `warmup_runs` times, none of them kept in a round.
std::optional<FailedRun> run_warmups(const RunLauncher& launcher,
                                     std::span<const Contender* const> contenders,
                                     const ScheduleOptions& options, SceneRuns& out) {
  for (int w = 1; w <= options.warmup_runs; ++w) {
    for (const Contender* contender : contenders) {
      RunRecord run =
          launcher.run(*contender, fmt::format("warmup-{}", w), cpus_of_round(options, 0));
      out.warmup[contender->name()].push_back(run);
      if (!run.ok) return FailedRun{contender->role(), run};
    }
  }
  return std::nullopt;
}

// A duet round: the pair starts together, each on its CPU of the round. With three contenders
// (compare) the baseline runs alone first on the round's first CPU, when it joins the round, so
// the two whose ratio the gate judges see the same interference; the baseline only normalizes.
RoundOutcome duet_round(const RunLauncher& launcher, const std::vector<const Contender*>& roster,
                        const ScheduleOptions& options, std::size_t index,
                        const std::string& label) {
  RoundOutcome out;
  const std::vector<int> cpus =
      rotated(std::vector<int>(options.duet_cpus.begin(), options.duet_cpus.begin() + 2), index);
  std::span<const Contender* const> pair(roster);
  if (roster.size() == 3) {
    if (normalizer_runs_in(options, index)) {
      const Contender& solo = *roster.front();
      RunRecord run = launcher.run(solo, label, {cpus.front()});
      if (!run.ok) return {std::move(out.round), FailedRun{solo.role(), run}};
      out.round.order.push_back(solo.name());
      out.round.runs[solo.name()] = std::move(run);
    }
    pair = pair.subspan(1);
  }
  const std::vector<RunRecord> runs = launcher.run_together(pair, label, cpus);
  for (std::size_t i = 0; i < pair.size(); ++i) {
    if (runs[i].ok) out.round.runs[pair[i]->name()] = runs[i];
  }
  for (std::size_t i = 0; i < pair.size(); ++i) {
    if (!runs[i].ok) return {std::move(out.round), FailedRun{pair[i]->role(), runs[i]}};
  }
  // Order by CPU, so the document says which contender had which CPU this round.
  for (std::size_t c = 0; c < cpus.size(); ++c) {
    const auto it = std::find(cpus.begin(), cpus.end(), options.duet_cpus[c]);
    out.round.order.push_back(pair[static_cast<std::size_t>(it - cpus.begin())]->name());
  }
  return out;
}

// An alternate round: the contenders one after another in the round's rotated order, each
// `repeats` times interleaved, the round keeping each one's fastest run.
RoundOutcome alternate_round(const RunLauncher& launcher,
                             const std::vector<const Contender*>& roster,
                             const ScheduleOptions& options, std::size_t index,
                             const std::string& label, const SceneRuns& so_far) {
  RoundOutcome out;
  const std::vector<const Contender*> present =
      normalizer_runs_in(options, index)
          ? roster
          : std::vector<const Contender*>(roster.begin() + 1, roster.end());
  const std::vector<int> cpus = cpus_of_round(options, index);
  const std::vector<const Contender*> sequence =
      interleaved(rotated(present, index), repeats_of_round(options, so_far));
  for (std::size_t n = 0; n < sequence.size(); ++n) {
    const Contender& contender = *sequence[n];
    // A repeat's run directory is "<round>-<k>", so no run overwrites another's files.
    const std::size_t runs_before = static_cast<std::size_t>(
        std::count(sequence.begin(), sequence.begin() + static_cast<long>(n), &contender));
    RunRecord run = launcher.run(
        contender, runs_before == 0 ? label : fmt::format("{}-{}", label, runs_before + 1), cpus);
    if (!run.ok) return {std::move(out.round), FailedRun{contender.role(), run}};
    out.round.order.push_back(contender.name());
    keep_fastest(out.round.runs, contender.name(), std::move(run));
  }
  return out;
}

// measure_scene() from `earlier`'s rounds on: a first visit (no rounds yet) starts with the
// warm-ups; a later one continues the round numbering, the rotation and the CPU alternation
// where the first visit left them, and adds its seconds to the earlier ones.
SceneRuns run_scene(const SceneInput& scene, std::span<const Contender* const> contenders,
                    const ScheduleOptions& options, const StopRule& stop, Executor& executor,
                    Clock& clock, const std::filesystem::path& scene_dir,
                    const RoundObserver& on_round, SceneRuns earlier) {
  check_options(contenders, options);
  const RunLauncher launcher(scene, executor, scene_dir);
  const double started = clock.now_seconds();
  SceneRuns out = std::move(earlier);
  const double spent_before = out.seconds_spent;
  out.stop_reason.clear();
  auto fail = [&](FailedRun failure, std::map<std::string, RunRecord> partial_round = {}) {
    out.failed_role = failure.role;
    out.failed_run = std::move(failure.run);
    out.partial_round = std::move(partial_round);
    out.stop_reason = "failed";
    out.seconds_spent = spent_before + clock.now_seconds() - started;
    return out;
  };
  if (out.rounds.empty()) {
    if (std::optional<FailedRun> failure = run_warmups(launcher, contenders, options, out)) {
      return fail(std::move(*failure));
    }
  }
  const std::vector<const Contender*> roster(contenders.begin(), contenders.end());
  for (std::size_t index = out.rounds.size();; ++index) {
    const std::string label = fmt::format("round-{:03}", index + 1);
    RoundOutcome outcome = options.kind == ScheduleKind::duet
                               ? duet_round(launcher, roster, options, index, label)
                               : alternate_round(launcher, roster, options, index, label, out);
    if (outcome.failure) return fail(std::move(*outcome.failure), std::move(outcome.round.runs));
    out.rounds.push_back(std::move(outcome.round));
    out.seconds_spent = spent_before + clock.now_seconds() - started;
    if (on_round) on_round(out.rounds, out.seconds_spent);
    const StopDecision decision = stop(out.rounds, out.seconds_spent);
    if (decision != StopDecision::continue_measuring) {
      out.stop_reason = std::string(to_string(decision));
      return out;
    }
  }
}

}  // namespace

SceneRuns measure_scene(const SceneInput& scene, std::span<const Contender* const> contenders,
                        const ScheduleOptions& options, const StopRule& stop, Executor& executor,
                        Clock& clock, const std::filesystem::path& scene_dir,
                        const RoundObserver& on_round) {
  return run_scene(scene, contenders, options, stop, executor, clock, scene_dir, on_round, {});
}

SceneRuns continue_scene(const SceneInput& scene, std::span<const Contender* const> contenders,
                         const ScheduleOptions& options, const StopRule& stop, Executor& executor,
                         Clock& clock, const std::filesystem::path& scene_dir, SceneRuns earlier,
                         const RoundObserver& on_round) {
  if (earlier.failed() || earlier.rounds.empty()) {
    throw std::invalid_argument("continue_scene: only a scene measured without failure continues");
  }
  return run_scene(scene, contenders, options, stop, executor, clock, scene_dir, on_round,
                   std::move(earlier));
}

std::vector<int> cpus_of_round(const ScheduleOptions& options, std::size_t index) {
  if (!options.pin_cpus.empty()) return options.pin_cpus;
  if (options.round_cpus.empty()) return {};
  // Every second round: rounds 2k and 2k + 1 run in both orders on the same CPU.
  return {options.round_cpus[(index / 2) % options.round_cpus.size()]};
}

bool normalizer_runs_in(const ScheduleOptions& options, std::size_t index) {
  return options.normalizer_rounds == 0 || index < options.normalizer_rounds;
}

std::vector<RoundSample> round_samples(const std::vector<Round>& rounds, Role tracer_role,
                                       Role baseline_role) {
  std::vector<RoundSample> samples;
  samples.reserve(rounds.size());
  for (const Round& round : rounds) {
    const auto baseline = round.runs.find(role_name(baseline_role));
    if (baseline == round.runs.end()) continue;  // a round the normalizer did not join
    samples.push_back({round.runs.at(role_name(tracer_role)).seconds, baseline->second.seconds});
  }
  return samples;
}

std::vector<CompareRound> compare_samples(const std::vector<Round>& rounds) {
  std::vector<CompareRound> samples;
  samples.reserve(rounds.size());
  for (const Round& round : rounds) {
    CompareRound sample{std::nullopt, round.runs.at(role_name(Role::base)).seconds,
                        round.runs.at(role_name(Role::head)).seconds};
    if (const auto baseline = round.runs.find(role_name(Role::baseline));
        baseline != round.runs.end()) {
      sample.baseline_seconds = baseline->second.seconds;
    }
    samples.push_back(sample);
  }
  return samples;
}

std::size_t runs_per_contender(const Round& round) {
  // Counted in one pass: a stored document's order may be as long as its author likes.
  std::map<std::string_view, std::size_t> runs;
  std::size_t most = 1;
  for (const std::string& name : round.order) most = std::max(most, ++runs[name]);
  return most;
}

std::string repeats_note(const std::vector<Round>& rounds) {
  std::size_t repeated = 0;
  std::size_t most = 1;
  for (const Round& round : rounds) {
    const std::size_t runs = runs_per_contender(round);
    if (runs > 1) ++repeated;
    most = std::max(most, runs);
  }
  if (repeated == 0) return {};
  if (repeated == rounds.size()) return fmt::format("each the fastest of {} runs", most);
  return fmt::format("{} of them the fastest of {} runs", repeated, most);
}

std::string_view to_string(ScheduleKind kind) {
  return kind == ScheduleKind::duet ? "duet" : "alternate";
}

}  // namespace raygate
