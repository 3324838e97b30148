// Alerts on a default branch: each history series' ratios over its commits (results/series.h:
// one series per repository, adapter, suite, scene settings, timing and baseline) searched for
// change points (alert/e_divisive.h). A series is in alert when its newest change point made it
// slower by more than the policy allows for its scene: the commit range is named (the last
// commit before the change and the first after it), to be bisected or reverted. The series'
// peak memory (issue 27) is searched the same way: a step up by more than the scene's
// max_memory_increase (and more than 1 MiB, page-level jitter) puts the series in alert too.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "alert/e_divisive.h"
#include "gate/policy.h"
#include "store/history.h"
#include "store/store.h"

namespace raygate {

struct CommitRef {
  std::string sha;
  std::string short_sha;
  std::string subject;
  std::string commit_time;
};

// A change point placed between two commits of the series.
struct SeriesChange {
  CommitRef last_before;          // the newest commit measured before the change
  CommitRef first_after;          // the first commit measured after it: the suspect, or the end of
                                  // the range when commits between them were not measured
  std::size_t commits_after = 0;  // measured commits from first_after to the newest
  ChangePoint change;
};

// The change points of the series' peak memory (its own peaks, KiB, median per commit).
struct MemoryTrack {
  std::size_t points = 0;
  double limit = 0.0;                 // the scene's max_memory_increase
  std::vector<SeriesChange> changes;  // oldest first; means in KiB
  // The newest change, when it is an increase over the limit and over the noise floor.
  std::optional<SeriesChange> alert;
};

struct SeriesJudgement {
  SeriesColumn column;  // the series: id, scene, label and a row with its parts
  std::size_t points = 0;
  double limit = 0.0;                 // the scene's max_slowdown
  std::vector<SeriesChange> changes;  // oldest first
  std::optional<SeriesChange> alert;  // the newest change, when it is a slowdown over the limit
  std::optional<MemoryTrack> memory;  // nullopt when no commit of the series has a peak

  bool in_alert() const { return alert.has_value() || (memory && memory->alert); }
};

enum class AlertAction { fail, annotate };

struct AlertJudgement {
  std::vector<SeriesJudgement> series;
  AlertAction action = AlertAction::fail;
  // Points a series needs before a change can be found in it (two segments of min_segment); the
  // summary counts the series with fewer, so "OK" on one measurement does not read as a verdict.
  std::size_t points_to_find_a_change = 0;
  std::size_t alerts() const;
  int exit_code() const;  // 1 when a series is in alert and the action is fail, else 0
};

// `rows` as ResultsStore::history gives them (one per commit and series, newest first). Series
// with fewer than two segments' worth of points are judged too (no change can be found in them).
// A series is in alert for its time, its memory, or both; alerts() counts series.
AlertJudgement judge_history(const std::vector<HistoryRow>& rows, const GatePolicy& policy,
                             const EDivisiveOptions& detection, AlertAction action);

// "fail" / "annotate", for flags and JSON.
std::string_view to_string(AlertAction action);
AlertAction parse_alert_action(std::string_view text);

nlohmann::json alert_json(const AlertJudgement& judgement, const EDivisiveOptions& detection);
// One line per series in alert, and a summary line: what a CI log shows.
std::string alert_text(const AlertJudgement& judgement);

}  // namespace raygate
