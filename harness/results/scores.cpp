#include "results/scores.h"

#include "runner/scheduler.h"

namespace raygate {

std::map<Role, SuiteScore> suite_scores(const std::vector<SceneResult>& scenes,
                                        const std::vector<Role>& roles) {
  std::map<Role, SuiteScore> scores;
  for (const Role role : roles) {
    std::vector<std::vector<RoundSample>> per_scene;
    for (const SceneResult& scene : scenes) {
      if (scene.status == SceneStatus::measured) {
        per_scene.push_back(round_samples(scene.runs.rounds, role));
      }
    }
    if (!per_scene.empty()) scores[role] = suite_score(per_scene);
  }
  return scores;
}

std::vector<Role> scored_roles(const ResultsDocument& document) {
  std::vector<Role> roles;
  for (const RevisionRecord& revision : document.revisions) roles.push_back(revision.role);
  return roles;
}

}  // namespace raygate
