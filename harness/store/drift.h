// Machine drift (DESIGN.md §6): when the baseline's own seconds moved against this machine's
// history while the normalized ratios held, the machine changed (governor, turbo, a neighbour,
// new hardware under the same name), not the code. The rule (docs/store.md): compare the latest
// document with earlier documents of the same machine (hostname + CPU model), series by series
// (results/series.h: same repository, adapter, suite, scene settings, timing and baseline),
// against the median of the earlier values.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "store/store.h"

namespace raygate {

inline constexpr double kDriftBaselineFraction = 0.05;   // baseline seconds moved by more than this
inline constexpr double kDriftRatioHeldFraction = 0.03;  // ratio within this (or its own CI)

struct SceneDrift {
  std::string scene_id;
  double baseline_change = 0.0;  // latest / earlier median - 1; -0.1 is 10% less time
  double ratio_change = 0.0;
  bool baseline_moved = false;
  bool ratio_held = false;
};

struct MachineDrift {
  std::string hostname;
  std::string cpu_model;
  std::int64_t document_id = 0;  // the latest document
  std::string short_sha;
  std::size_t scenes_compared = 0;      // scenes of the latest document with earlier history
  std::size_t scenes_drifted = 0;       // moved one way with the ratio held
  double median_baseline_change = 0.0;  // over the drifted scenes
  std::vector<SceneDrift> scenes;

  bool faster() const { return median_baseline_change < 0.0; }
};

// `measurements` as ResultsStore::measurements gives them (every document, not one per commit).
// A result when more than half the compared scenes drifted the same way; otherwise nullopt.
std::optional<MachineDrift> detect_machine_drift(const std::vector<HistoryRow>& measurements);

// The note for people: which machine, which way, how much, on how many scenes.
std::string describe_drift(const MachineDrift& drift);

}  // namespace raygate
