// Hand-made results documents for the store and history tests: a few commits, scenes with a
// chosen ratio, baseline seconds and image error, on a chosen machine. Every document also has
// a round of runs, so the JSON round trip covers the nested records.
#pragma once

#include <string>
#include <vector>

#include "results/results.h"

namespace raygate::test {

struct SceneSpec {
  std::string id;
  double ratio = 1.0;
  double half_width = 0.01;  // relative half-width of the ratio's CI
  double baseline_seconds = 1.0;
  double max_error = 0.0;
  ImageVerdict verdict = ImageVerdict::pass;
  SceneStatus status = SceneStatus::measured;
  // The runs' own peak memory (raygate-meter's): 0 none, as in documents from before it.
  long peak_kib = 0;
  long head_peak_kib = 0;  // compare: head's, when not peak_kib
};

struct DocumentSpec {
  std::string sha;  // 40 hex digits (fake_sha)
  std::string subject = "a commit";
  std::string commit_time = "2026-01-01T12:00:00+00:00";
  std::string ref_name = "refs/heads/main";
  std::string started_at = "2026-01-02T00:00:00Z";
  std::string hostname = "ci-runner-1";
  std::string cpu_model = "Test CPU 3000";
  std::string baseline_sha256 = std::string(64, 'b');
  DocumentKind kind = DocumentKind::run;
  std::string shard;                      // "K/N"
  std::vector<Role> roles{Role::tracer};  // compare: {base, head}
  bool dirty = false;
  bool complete = true;
  std::string repository_id;  // "" as in documents written before it was recorded
  std::string adapter = "cmake-nff";
  std::string suite = "ci";
  std::vector<SceneSpec> scenes;
  // compare documents: each scene also carries a change of head against base (+1%, UNCHANGED,
  // from a confidence sequence), as compare writes it.
  bool with_change = false;
};

// A sha that looks real and differs per `seed`.
std::string fake_sha(int seed);

ResultsDocument make_document(const DocumentSpec& spec);

// A commit of a March 2026 history: "commit SEED", committed on `day` ("10") at 10:00+02:00 and
// measured at noon UTC, with balls at `ratio` and gears at twice it.
DocumentSpec march_commit(int seed, const std::string& day, double ratio);

}  // namespace raygate::test
