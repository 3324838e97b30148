#include "report_fixture.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "compare/image_check.h"

namespace raygate::test {
namespace {

namespace OIIO = OIIO_NAMESPACE;
const std::filesystem::path kGolden =
    std::filesystem::path(RAYGATE_SOURCE_DIR) / "golden" / "raygate-baseline";

RevisionRecord revision(Role role, const std::string& sha, const std::string& subject) {
  RevisionRecord r;
  r.role = role;
  r.repository = "https://example.org/tracer.git";
  r.worktree.sha = sha + std::string(40 - sha.size(), '0');
  r.worktree.short_sha = sha.substr(0, 7);
  r.worktree.subject = subject;
  r.worktree.revision = role == Role::base ? "main" : "feature/bvh";
  r.worktree.author = "A. Tracer";
  r.worktree.commit_time = "2024-05-01T12:00:00+02:00";
  r.adapter_name = "cmake-nff";
  return r;
}

RatioSummary ratio(double value, double half_width_fraction, std::size_t rounds = 12) {
  RatioSummary r;
  r.rounds = rounds;
  r.ratio = value;
  r.ratio_interval = {value * (1 - half_width_fraction), value * (1 + half_width_fraction)};
  r.relative_half_width = half_width_fraction;
  r.tracer_median_seconds = value * 1.5;
  r.baseline_median_seconds = 1.5;
  return r;
}

SceneResult scene(const std::string& id, double seconds_spent = 20.0) {
  SceneResult s;
  s.entry = {id, id, 1, 128, 128};
  s.status = SceneStatus::measured;
  s.runs.stop_reason = "stop_converged";
  s.runs.seconds_spent = seconds_spent;
  return s;
}

void set_change(SceneResult& s, double base, double head, double change, double lo, double hi,
                ChangeVerdict verdict) {
  s.ratios[Role::base] = ratio(base, 0.006);
  s.ratios[Role::head] = ratio(head, 0.006);
  ChangeSummary c;
  c.rounds = 12;
  c.change = change;
  c.change_interval = {lo, hi};
  c.base = s.ratios[Role::base];
  c.head = s.ratios[Role::head];
  s.change = c;
  s.change_verdict = verdict;
}

ImageCheck check(Role role, ImageReference reference, const std::filesystem::path& actual,
                 const std::filesystem::path& expected, const std::filesystem::path& dir,
                 const std::string& stem) {
  return check_image(role, reference, actual, expected, ImageThresholds{}, dir / "evidence", stem);
}

// gears as a wrong tracer would draw it: a bright square, written as PPM (browsers cannot
// show PPM, so the HTML report must convert it).
std::filesystem::path wrong_gears(const std::filesystem::path& dir) {
  OIIO::ImageBuf buf((kGolden / "gears.png").string());
  if (!buf.read(0, 0, true, OIIO::TypeDesc::FLOAT)) throw std::runtime_error(buf.geterror());
  const float bright[3] = {1.0f, 0.9f, 0.2f};
  OIIO::ImageBufAlgo::fill(buf, bright, OIIO::ROI(40, 72, 40, 72, 0, 1, 0, 3));
  const std::filesystem::path out = dir / "head-gears.ppm";
  if (!buf.write(out.string(), OIIO::TypeDesc::UINT8)) throw std::runtime_error(buf.geterror());
  return out;
}

SceneResult passing(const std::filesystem::path& dir) {
  SceneResult s = scene("balls");
  set_change(s, 0.512, 0.514, 0.004, -0.006, 0.013, ChangeVerdict::unchanged);
  const auto golden = kGolden / "balls.png";
  s.images.push_back(
      check(Role::head, ImageReference::golden, golden, golden, dir, "balls-head-golden"));
  s.images.push_back(
      check(Role::base, ImageReference::golden, golden, golden, dir, "balls-base-golden"));
  return s;
}

SceneResult regression(const std::filesystem::path& dir) {
  SceneResult s = scene("mount", 41.5);
  set_change(s, 0.731, 0.789, 0.079, 0.061, 0.098, ChangeVerdict::regressed);
  const auto golden = kGolden / "mount.png";
  s.images.push_back(
      check(Role::head, ImageReference::golden, golden, golden, dir, "mount-head-golden"));
  return s;
}

SceneResult image_failure(const std::filesystem::path& dir) {
  SceneResult s = scene("gears");
  set_change(s, 1.204, 1.207, 0.002, -0.008, 0.011, ChangeVerdict::unchanged);
  const auto golden = kGolden / "gears.png";
  const auto head = wrong_gears(dir);
  s.images.push_back(
      check(Role::head, ImageReference::golden, head, golden, dir, "gears-head-golden"));
  s.images.push_back(
      check(Role::base, ImageReference::golden, golden, golden, dir, "gears-base-golden"));
  s.images.push_back(check(Role::head, ImageReference::base, head, golden, dir, "gears-head-base"));
  return s;
}

SceneResult unmeasured() {
  SceneResult s = scene("tetra", 3.0);
  s.status = SceneStatus::failed;
  s.runs.stop_reason = "failed";
  s.runs.failed_role = Role::baseline;
  RunRecord run;
  run.outcome = "killed by SIGSEGV";
  run.failure = "the baseline crashed";
  run.log = "/tmp/raygate/tetra/baseline/round-001/log.txt";
  s.runs.failed_run = run;
  return s;
}

ResultsDocument header(DocumentKind kind) {
  ResultsDocument d;
  d.kind = kind;
  d.raygate_version = "0.1.0";
  d.started_at = "2024-05-01T10:00:00Z";
  d.finished_at = "2024-05-01T10:12:00Z";
  d.complete = true;
  d.machine = {{"cpu_model", "Test CPU @ 3.0GHz"},
               {"logical_cores", 2},
               {"kernel", "Linux 6.1.0 x86_64"},
               {"hostname", "ci-runner-3"}};
  d.baseline.version = "raygate-baseline 0.1.0";
  d.suite = "ci";
  d.settings.schedule = ScheduleKind::alternate;
  d.settings.max_rounds = 40;
  d.settings.threads = 1;
  return d;
}

}  // namespace

ResultsDocument make_run_document(const std::filesystem::path& dir) {
  ResultsDocument d = header(DocumentKind::run);
  d.revisions.push_back(revision(Role::tracer, "1111111abcdef", "Tracer at main"));
  for (const std::string id : {"balls", "tetra"}) {
    SceneResult s = scene(id);
    s.ratios[Role::tracer] = ratio(id == "balls" ? 0.512 : 0.377, 0.008);
    const auto golden = kGolden / (id + ".png");
    s.images.push_back(
        check(Role::tracer, ImageReference::golden, golden, golden, dir, id + "-tracer-golden"));
    d.scenes.push_back(s);
  }
  d.scores[Role::tracer] = {2, 0.439, {0.435, 0.443}};
  return d;
}

ResultsDocument make_compare_document(const std::filesystem::path& dir) {
  ResultsDocument d = header(DocumentKind::compare);
  d.revisions.push_back(revision(Role::base, "2222222abcdef", "Merge pull request #41"));
  d.revisions.push_back(revision(Role::head, "3333333abcdef", kNastySubject));
  d.scenes = {passing(dir), regression(dir), image_failure(dir), unmeasured()};
  d.scores[Role::base] = {3, 0.77, {0.76, 0.78}};
  d.scores[Role::head] = {3, 0.79, {0.78, 0.80}};
  return d;
}

Fixture::Fixture(bool compare) {
  document = compare ? make_compare_document(dir.path()) : make_run_document(dir.path());
  gate = evaluate_gate(document, policy);
  input = std::make_unique<ReportInput>(ReportInput{document, gate, policy, {}, dir.path(), {}, 0});
}

std::string Fixture::render(std::string_view format, const ReportOptions& options) const {
  std::ostringstream out;
  make_reporter(format, options)->write(*input, out);
  return out.str();
}

TrendSeries make_trend(const std::string& scene, int n) {
  TrendSeries series{scene, {}};
  for (int i = 0; i < n; ++i) {
    const double r = 0.73 + 0.004 * std::sin(i * 1.3) + (i == n - 1 ? 0.058 : 0.0);
    series.points.push_back({"c0ffee" + std::to_string(i), "commit " + std::to_string(i), "", r,
                             r * 0.994, r * 1.006, "", false, ""});
  }
  return series;
}

}  // namespace raygate::test
