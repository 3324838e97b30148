// Proof that the baseline traces the SPD scenes the way the SPD intends (`raygate validate`,
// docs/validation.md): the seven classic scenes rendered with the SPD test procedure (512x512,
// corner rays, depth 5), their ray counts compared with the published SPD statistics
// (spd-spec.md Table E), which a correct classical ray tracer matches within about 10%.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace raygate {

struct SpdValidationRequest {
  std::string accel = "bbox";       // none or bbox: the same counts; bbox is faster
  std::vector<std::string> scenes;  // of the seven; empty = all
  std::string work_dir = ".raygate/validate";
  std::string baseline;  // raygate-baseline to use; "" = beside raygate
};

struct SpdValidation {
  std::string table;  // Markdown: one row per scene, "baseline / published (deviation)"
  bool all_within = false;
};

// Renders and compares; `status` hears a line before each render. UsageError for an unknown
// scene or accel; InfraError when the baseline fails.
SpdValidation validate_spd_counts(const SpdValidationRequest& request,
                                  const std::function<void(const std::string&)>& status);

}  // namespace raygate
