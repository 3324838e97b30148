// The measuring loop of one scene (DESIGN.md §6): warm-up runs, then rounds in which every
// contender runs once, in an order that rotates from round to round (baseline, tracer; then
// tracer, baseline; with three contenders baseline, base, head; base, head, baseline; ...), so a
// slow drift of the machine hits all of them alike. In the duet schedule the contenders of a
// round start together, each pinned to its own CPU, and the CPUs rotate too; with three
// (compare), the first (the baseline) runs alone on the round's first CPU, then the other two
// start together. Rounds continue
// until a stop rule (pipeline/stop_rules.h: the one stopping policy) says enough.
//
// Processes and time come through Executor and Clock, so the loop is tested with fakes.
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "measure/change.h"
#include "measure/ratio.h"
#include "measure/stopping_policy.h"
#include "runner/contender.h"
#include "runner/executor.h"
#include "runner/run_record.h"

namespace raygate {

enum class ScheduleKind { alternate, duet };

struct SceneRuns;

// The runs per contender of a scene's next round, chosen from its runs so far: each side's
// fastest of two where the scene's rounds show it pays (`run`: pipeline/ratio_repeats.h;
// compare: pipeline/visit_plan.h). Only the past may choose, so no round's runs depend on its
// own times, and the verdicts' guarantees hold (docs/statistics.md §6d).
using RepeatChooser = std::function<std::size_t(const SceneRuns& so_far)>;

struct ScheduleOptions {
  ScheduleKind kind = ScheduleKind::alternate;
  int warmup_runs = 1;               // per contender, not counted
  std::vector<int> pin_cpus;         // alternate: every run pinned to these CPUs; empty: no pinning
  std::vector<int> duet_cpus{0, 1};  // duet: one CPU per contender, rotated each round
  // Alternate schedule without pin_cpus: every run of a round pinned to one of these CPUs, the
  // CPU changing every second round (so each CPU sees both orders). The contenders compared
  // within a round then share a CPU: a VM's vCPUs differ in speed, and an unpinned pair that
  // lands on two of them measures the CPUs, not the change. Empty: no pinning.
  std::vector<int> round_cpus;
  // The normalizer (the first contender: the baseline) joins only the first `normalizer_rounds`
  // rounds of a scene; 0 = every round. compare judges ln(head / base) within a round, where
  // the baseline cancels, so it is timed only as often as the normalized ratio needs.
  std::size_t normalizer_rounds = 0;
  // Alternate schedule: each contender of a round runs this many times, interleaved (baseline,
  // base, head, baseline, base, head; the next round rotated), and the round keeps
  // each one's fastest run. A run is only ever slowed by what else the machine does, so the
  // fastest of two is much steadier than one (the identity tracer's per-round spread fell from
  // 1.0-6.9% to 0.2-1.6%); every contender repeats alike, so no ratio is biased by it.
  std::size_t repeats = 1;
  // Alternate schedule: the runs per contender of each round, chosen from the scene's runs
  // before it (RepeatChooser); unset: `repeats` for every round.
  RepeatChooser repeats_from_rounds;
};

// The CPUs the runs of round `index` (0-based) are pinned to: pin_cpus if given, else one of
// round_cpus (see there), else none.
std::vector<int> cpus_of_round(const ScheduleOptions& options, std::size_t index);

// Does the normalizer run in round `index` (0-based)?
bool normalizer_runs_in(const ScheduleOptions& options, std::size_t index);

struct Round {
  // Roles in the order they ran (a role once per run: twice with ScheduleOptions::repeats 2) (the baseline only in the rounds it joined, see
  // ScheduleOptions::normalizer_rounds); in a duet, the pair in CPU order (after the baseline that ran
  // alone before them, with three contenders).
  std::vector<std::string> order;
  std::map<std::string, RunRecord> runs;  // by role; its fastest run when it repeated
};

struct SceneRuns {
  std::map<std::string, std::vector<RunRecord>> warmup;  // by role
  std::vector<Round> rounds;                             // complete rounds only
  std::string stop_reason;                               // to_string(StopDecision), or "failed"
  double seconds_spent = 0.0;
  // When a run failed: whose, and that run (its failure, outcome and log). Measuring the scene
  // stopped there; the rounds before it are kept.
  Role failed_role = Role::tracer;
  std::optional<RunRecord> failed_run;
  // The successful runs of the round that failure cut short, by role. So "base ran before head
  // crashed" reads the same whether the crash came in a warm-up or in the first round.
  std::map<std::string, RunRecord> partial_round;

  bool failed() const { return failed_run.has_value(); }
  // The first successful run of `role` (a warm-up if there was one, else a round's, else one of
  // the round a failure cut short): its image is the one compared with the golden. nullptr if
  // there is none.
  const RunRecord* first_run(Role role) const;
  const RunRecord* first_run(const std::string& role) const;  // by the role's word
};

using StopRule =
    std::function<StopDecision(const std::vector<Round>& rounds, double seconds_spent)>;
// Called after each complete round (progress display).
using RoundObserver = std::function<void(const std::vector<Round>& rounds, double seconds_spent)>;

// Runs the scene's warm-ups and rounds. Run directories: <scene_dir>/<role>/warmup-N and
// <scene_dir>/<role>/round-NNN. Throws UsageError for a duet with other than two or three
// contenders or too few CPUs named; never throws for a contender that fails (see SceneRuns::failed_run).
SceneRuns measure_scene(const SceneInput& scene, std::span<const Contender* const> contenders,
                        const ScheduleOptions& options, const StopRule& stop, Executor& executor,
                        Clock& clock, const std::filesystem::path& scene_dir,
                        const RoundObserver& on_round = {});

// More rounds of a scene measure_scene() stopped without a failure (its time share spent):
// no warm-ups (its programs and files were warmed by the first visit), the round numbering,
// rotation and CPU alternation continued, and seconds_spent the total of both visits, which
// `stop` sees too. The statistics allow it: compare's confidence sequences hold at every round,
// however the rounds are spread over time. Throws std::invalid_argument for `earlier` failed or
// without rounds.
SceneRuns continue_scene(const SceneInput& scene, std::span<const Contender* const> contenders,
                         const ScheduleOptions& options, const StopRule& stop, Executor& executor,
                         Clock& clock, const std::filesystem::path& scene_dir, SceneRuns earlier,
                         const RoundObserver& on_round = {});

// The rounds as (tracer, baseline) pairs of their `seconds`, of the rounds both ran in.
std::vector<RoundSample> round_samples(const std::vector<Round>& rounds, Role tracer_role,
                                       Role baseline_role = Role::baseline);

// The rounds as (baseline, base, head) triples of their `seconds`, for compare; the baseline's
// is empty in rounds it did not join.
std::vector<CompareRound> compare_samples(const std::vector<Round>& rounds);

// How many times each contender ran in this round (ScheduleOptions::repeats when it ran): the
// most times one name appears in its order. 1 for a round whose order is empty (documents
// written before the order was kept).
std::size_t runs_per_contender(const Round& round);

// What the rounds' repeats were, for a scene's line: "6 of them the fastest of 2 runs", "each
// the fastest of 2 runs"; empty when every round ran each contender once.
std::string repeats_note(const std::vector<Round>& rounds);

std::string_view to_string(ScheduleKind kind);

}  // namespace raygate
