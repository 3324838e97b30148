// The gate's policy (DESIGN.md §6-§7): how much slowdown a scene may show, at which confidence,
// and how far its image may drift, in idiff's terms. Defaults apply to every scene; a scene may
// override any of them, and every override must say why (`reason`), because a loosened gate
// nobody can explain is how regressions get waved through.
#pragma once

#include <filesystem>
#include <map>

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "compare/image_compare.h"
#include "compare/noisy_image_compare.h"
#include "measure/family.h"
#include "measure/memory_change.h"
#include "results/measurement_settings.h"

namespace raygate {

struct ScenePolicy {
  double max_slowdown = 0.03;  // REGRESSED beyond +3% (and significant)
  // Peak resident memory may grow this much from base to head (measure/memory_change.h).
  double max_memory_increase = kDefaultMaxMemoryIncrease;
  // The reported ratios' CIs are at 1 - significance; in a compare it is also the chance per
  // scene that a change beyond max_slowdown is called UNCHANGED (docs/statistics.md §6).
  double significance = 0.05;
  ImageThresholds image;  // against the golden and against the base revision's image
  // A Monte Carlo image's tolerance (compare/noisy_image_compare.h): the whole image's change,
  // per channel, within which it passes and beyond which it fails (docs/monte-carlo-images.md).
  double image_tolerance = kDefaultImageTolerance;
  std::string reason;  // why this scene differs from the defaults (overrides only)
};

struct GatePolicy {
  ScenePolicy defaults;
  std::map<std::string, ScenePolicy> scenes;  // by suite scene id, defaults already applied
  bool fail_on_inconclusive = false;
  // A scene family's growth exponent may rise this much from base to head (docs/scaling.md).
  double max_exponent_increase = 0.1;
  // The chance that a compare of an unchanged commit calls any scene REGRESSED (docs/statistics.md §6c).
  double family_significance = kDefaultFamilySignificance;
  std::filesystem::path file;  // where it came from; empty for the built-in defaults

  const ScenePolicy& for_scene(const std::string& id) const;
};

// Parses a policy document. Unknown keys (with "did you mean"), wrong types and out-of-range
// values are UsageErrors naming origin and JSON path; an override without a reason too.
GatePolicy parse_policy(std::string_view text, const std::string& origin);
GatePolicy load_policy(const std::filesystem::path& path);

// The policy a results document was measured under, for judging it again (gate, merge) when no
// --policy is given: its policy file when that file is still there, else the defaults it
// recorded (settings.max_slowdown, settings.significance); `note` says which was used.
GatePolicy recorded_policy(const MeasurementSettings& settings, std::string& note);

}  // namespace raygate
