#include "results_fixture.h"

#include <cmath>

#include "core/sha256.h"

namespace raygate::test {

namespace {

RevisionRecord revision(const DocumentSpec& spec, Role role) {
  RevisionRecord r;
  r.role = role;
  r.repository = "/tmp/tracer-repo";
  r.repository_id = spec.repository_id;
  r.worktree.path = "/tmp/worktrees/" + spec.sha;
  r.worktree.revision = "main";
  r.worktree.ref_name = spec.ref_name;
  r.worktree.sha = spec.sha;
  r.worktree.short_sha = spec.sha.substr(0, 7);
  r.worktree.subject = spec.subject;
  r.worktree.author = "Test Author";
  r.worktree.commit_time = spec.commit_time;
  r.worktree.dirty = spec.dirty;
  r.adapter_name = spec.adapter;
  r.adapter_hash = std::string(64, 'a');
  r.adapter_file = "adapters/cmake-nff.json";
  r.build.sha = spec.sha;
  r.build.success = true;
  return r;
}

RatioSummary ratio_summary(const SceneSpec& s) {
  RatioSummary r;
  r.rounds = 5;
  r.ratio = s.ratio;
  r.ratio_interval = {s.ratio * (1.0 - s.half_width), s.ratio * (1.0 + s.half_width)};
  r.relative_half_width = s.half_width;
  r.log_ratio_median = std::log(s.ratio);
  r.log_ratio_mad_scaled = s.half_width;
  r.tracer_median_seconds = s.ratio * s.baseline_seconds;
  r.baseline_median_seconds = s.baseline_seconds;
  return r;
}

RunRecord run(double seconds) {
  RunRecord r;
  r.ok = true;
  r.outcome = "exited with status 0";
  r.seconds = seconds;
  r.wall_seconds = seconds + 0.2;
  r.user_seconds = seconds;
  r.max_rss_kib = 20480;
  r.reported_seconds = seconds;
  return r;
}

ImageCheck image(const SceneSpec& s, Role role) {
  ImageCheck c;
  c.role = role;
  c.reference = ImageReference::golden;
  c.actual = "/tmp/run/" + s.id + ".png";
  c.expected = "golden/" + s.id + ".png";
  c.verdict = s.verdict;
  ImageMetrics m;
  m.width = m.height = m.expected_width = m.expected_height = 64;
  m.max_error = s.max_error;
  m.rms_error = s.max_error / 4.0;
  m.mean_error = s.max_error / 8.0;
  m.psnr_db = s.max_error == 0.0 ? INFINITY : 40.0;
  c.metrics = m;
  return c;
}

SceneResult scene(const SceneSpec& s, const std::vector<Role>& roles) {
  SceneResult r;
  r.entry = {s.id, s.id, 1, 64, 64};
  r.scene_sha256 = sha256_hex(s.id);
  r.status = s.status;
  r.runs.stop_reason = "stop_converged";
  r.runs.seconds_spent = 12.5;
  Round round;
  round.order = {"baseline"};
  round.runs["baseline"] = run(s.baseline_seconds);
  for (const Role role : roles) {
    const std::string word = role_name(role);
    round.order.push_back(word);
    round.runs[word] = run(s.ratio * s.baseline_seconds);
    if (s.peak_kib > 0) {
      round.runs[word].max_rss_own = true;
      round.runs[word].max_rss_kib =
          role == Role::head && s.head_peak_kib > 0 ? s.head_peak_kib : s.peak_kib;
    }
    r.ratios[role] = ratio_summary(s);
    r.images.push_back(image(s, role));
  }
  // As many rounds as the ratios and the change say (5): a change of more rounds than the scene
  // lists is refused on reading.
  r.runs.rounds = std::vector<Round>(5, round);
  return r;
}

ChangeSummary change_summary(const SceneSpec& s) {
  ChangeSummary c;
  c.rounds = 5;
  c.change = 0.01;
  c.change_interval = {-0.01, 0.03};
  c.interval_kind = ChangeIntervalKind::confidence_sequence;
  c.equivalence_interval = {-0.02, 0.04};
  c.equivalence_confidence = 0.99;
  c.one_look_interval = {0.0, 0.02};
  c.one_look_confidence = 0.9;
  c.log_change_median = std::log(1.01);
  c.log_change_mad_scaled = 0.01;
  c.base = ratio_summary(s);
  c.head = ratio_summary(s);
  c.mann_whitney = {12.0, 0.5, 0.6};
  return c;
}

}  // namespace

std::string fake_sha(int seed) {
  return sha256_hex("commit " + std::to_string(seed)).substr(0, 40);
}

ResultsDocument make_document(const DocumentSpec& spec) {
  ResultsDocument d;
  d.kind = spec.kind;
  d.raygate_version = "0.1.0";
  d.started_at = spec.started_at;
  d.finished_at = spec.started_at;
  d.complete = spec.complete;
  d.machine = {{"hostname", spec.hostname}, {"cpu_model", spec.cpu_model}, {"logical_cores", 2}};
  d.baseline.version = "raygate-baseline 0.1.0";
  d.baseline.source_sha256 = spec.baseline_sha256;
  d.suite = spec.suite;
  d.shard = spec.shard;
  d.settings.schedule = ScheduleKind::alternate;
  d.settings.unknown = {{"target", 0.01}};  // a key this raygate does not know
  for (const Role role : spec.roles) d.revisions.push_back(revision(spec, role));
  double log_sum = 0.0;
  for (const SceneSpec& s : spec.scenes) {
    d.scenes.push_back(scene(s, spec.roles));
    if (spec.with_change) {
      d.scenes.back().change = change_summary(s);
      d.scenes.back().change_verdict = ChangeVerdict::unchanged;
    }
    log_sum += std::log(s.ratio);
  }
  for (const Role role : spec.roles) {
    const double n = static_cast<double>(spec.scenes.size());
    const double score = spec.scenes.empty() ? 0.0 : std::exp(log_sum / n);
    d.scores[role] = {spec.scenes.size(), score, {score * 0.99, score * 1.01}};
  }
  return d;
}

DocumentSpec march_commit(int seed, const std::string& day, double ratio) {
  DocumentSpec spec;
  spec.sha = fake_sha(seed);
  spec.subject = "commit " + std::to_string(seed);
  spec.commit_time = "2026-03-" + day + "T10:00:00+02:00";
  spec.started_at = "2026-03-" + day + "T12:00:00Z";
  spec.scenes = {{"balls", ratio}, {"gears", ratio * 2}};
  return spec;
}

}  // namespace raygate::test
