// The JSON report, for bots: the gate's verdict and the numbers that decided it, per scene, in
// a small stable shape (docs/reports.md), without the raw samples of the results document.
// Numbers that have no JSON form (an infinite PSNR) are written as null.
#include <cmath>

#include "report/memory_sections.h"
#include "report/report_model.h"
#include "report/reporters.h"
#include "results/json_number.h"
#include "results/summary_json.h"

namespace raygate::report {
namespace {

using nlohmann::json;

json interval(const Interval& i) {
  return json{{"lower", finite_number(i.lower)}, {"upper", finite_number(i.upper)}};
}

json revisions(const ResultsDocument& d) {
  json out = json::object();
  for (const RevisionRecord& r : d.revisions) {
    out[role_name(r.role)] = {{"sha", r.worktree.sha},         {"short_sha", r.worktree.short_sha},
                              {"subject", r.worktree.subject}, {"revision", r.worktree.revision},
                              {"dirty", r.worktree.dirty},     {"repository", r.repository}};
  }
  return out;
}

json ratios(const SceneResult& scene) {
  json out = json::object();
  for (const auto& [key, r] : scene.ratios) {
    const std::string role(to_string(key));
    out[role] = {{"ratio", finite_number(r.ratio)},
                 {"interval", interval(r.ratio_interval)},
                 {"relative_half_width", finite_number(r.relative_half_width)},
                 {"rounds", r.rounds}};
  }
  return out;
}

// The change with the interval its verdict was drawn from, named as every format names it.
json change(const SceneView& view) {
  const std::optional<ChangeCell> cell = change_cell(*view.result, view.gate);
  if (!cell) return nullptr;
  return {{"change", finite_number(cell->change)},
          {"interval", cell->interval ? interval(*cell->interval) : json(nullptr)},
          {"interval_name", cell->interval_name},
          {"interval_confidence", finite_number(cell->interval_confidence)},
          {"rounds", cell->rounds},
          {"rounds_needed", cell->rounds_needed},
          {"exact", cell->exact},
          {"verdict", std::string(to_string(cell->verdict))},
          {"text", cell->text}};
}

json images(const SceneResult& scene) {
  json out = json::array();
  for (const ImageCheck& check : scene.images) {
    json item = {{"role", to_string(check.role)},
                 {"reference", to_string(check.reference)},
                 {"verdict", to_string(check.verdict)}};
    if (check.metrics) {
      const ImageMetrics& m = *check.metrics;
      item["max_error"] = finite_number(m.max_error);
      item["percent_over_fail"] = finite_number(m.percent_over_fail);
      item["rms_error"] = finite_number(m.rms_error);
      item["psnr_db"] = finite_number(m.psnr_db);
      item["summary"] = summarize(m);
    }
    if (check.noisy) {
      item["monte_carlo"] = *check.noisy;
      item["summary"] = summarize(*check.noisy);
    }
    if (!check.error.empty()) item["error"] = check.error;
    out.push_back(item);
  }
  return out;
}

json scene_json(const SceneView& view) {
  return {{"id", view.gate.id},
          {"outcome", to_string(view.gate.outcome)},
          {"speed", to_string(view.gate.speed)},
          {"speed_outcome", to_string(view.speed_outcome)},
          // Bots read the stable word ("missing"), not the reader's ("no golden").
          {"image", view.gate.image ? std::string(to_string(*view.gate.image)) : ""},
          {"image_outcome", to_string(view.image_outcome)},
          {"reasons", view.gate.reasons},
          {"ratios", ratios(*view.result)},
          {"change", change(view)},
          {"images", images(*view.result)}};
}

json counts(const GateResult& gate) {
  json out = json::object();
  for (GateOutcome o :
       {GateOutcome::pass, GateOutcome::warn, GateOutcome::unmeasured, GateOutcome::fail}) {
    out[std::string(to_string(o))] = gate.count(o);
  }
  return out;
}

json policy_json(const GatePolicy& policy) {
  const ScenePolicy& d = policy.defaults;
  return {{"file", policy.file.string()},
          {"max_slowdown", d.max_slowdown},
          {"significance", d.significance},
          {"max_memory_increase", d.max_memory_increase},
          {"fail_on_inconclusive", policy.fail_on_inconclusive},
          {"image",
           {{"fail_threshold", d.image.fail_threshold},
            {"fail_percent", d.image.fail_percent},
            {"warn_threshold", d.image.warn_threshold},
            {"hard_fail", finite_number(d.image.hard_fail)}}}};
}

class JsonReporter final : public Reporter {
 public:
  void write(const ReportInput& input, std::ostream& out) const override {
    const ResultsDocument& d = input.document;
    const std::vector<SceneView> views = scene_views(input);
    const Headline line = headline(input, views);
    json scenes = json::array();
    for (const SceneView& view : views) {
      scenes.push_back(scene_json(view));
      // Issue 27: peak memory, and where a regressed scene's time went.
      scenes.back()["memory"] = memory_json(input, *view.result);
      if (view.result->explanation) scenes.back()["explanation"] = *view.result->explanation;
    }
    const auto suite = suite_change(d);
    json report = {{"raygate_report", 1},
                   {"kind", to_string(d.kind)},
                   {"suite", d.suite},
                   {"verdict", verdict_word(input.gate.exit_code)},
                   {"exit_code", input.exit_code()},
                   {"headline", line.title + " (" + line.detail + ")"},
                   {"counts", counts(input.gate)},
                   {"complete", d.complete},
                   {"revisions", revisions(d)},
                   {"suite_change", suite ? finite_number(*suite) : json(nullptr)},
                   {"policy", policy_json(input.policy)},
                   {"scenes", scenes}};
    out << report.dump(2, ' ', false, json::error_handler_t::replace) << '\n';
  }
};

}  // namespace

std::unique_ptr<Reporter> make_json_reporter(const ReportOptions&) {
  return std::make_unique<JsonReporter>();
}

}  // namespace raygate::report
