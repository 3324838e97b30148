#include "pipeline/run_images.h"

#include <algorithm>

namespace raygate {

std::vector<std::filesystem::path> run_images(const SceneRuns& runs, Role role) {
  const std::string word = role_name(role);
  std::vector<std::filesystem::path> images;
  auto take = [&](const RunRecord& run) {
    if (!run.ok || run.image.empty()) return;
    if (std::find(images.begin(), images.end(), run.image) == images.end()) {
      images.push_back(run.image);
    }
  };
  if (const auto found = runs.warmup.find(word); found != runs.warmup.end()) {
    for (const RunRecord& run : found->second) take(run);
  }
  for (const Round& round : runs.rounds) {
    if (const auto found = round.runs.find(word); found != round.runs.end()) take(found->second);
  }
  if (const auto found = runs.partial_round.find(word); found != runs.partial_round.end()) {
    take(found->second);
  }
  return images;
}

}  // namespace raygate
