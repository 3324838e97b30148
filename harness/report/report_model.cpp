#include "report/report_model.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "core/format.h"
#include "core/utf8.h"
#include "gate/memory_gate.h"
#include "report/ratio_interval_text.h"

namespace raygate::report {
namespace {

int reading_rank(GateOutcome outcome) {
  switch (outcome) {
    case GateOutcome::fail: return 0;
    case GateOutcome::unmeasured: return 1;
    case GateOutcome::warn: return 2;
    case GateOutcome::pass: return 3;
  }
  return 3;
}

SceneGate gate_of(const GateResult& gate, const std::string& id) {
  for (const SceneGate& scene : gate.scenes) {
    if (scene.id == id) return scene;
  }
  SceneGate unjudged;
  unjudged.id = id;
  unjudged.outcome = GateOutcome::unmeasured;
  unjudged.reasons.push_back("not judged by the gate");
  return unjudged;
}

// The gate judges the speed and image parts apart (gate/verdict.h); JUnit and the tables show
// them apart, as the gate said them.
SceneView make_view(const ReportInput& input, const SceneResult& scene) {
  SceneView view;
  view.result = &scene;
  view.gate = gate_of(input.gate, scene.entry.id);
  view.speed_outcome = view.gate.speed_outcome;
  view.image_outcome = view.gate.image_outcome;
  for (const std::string& reason : view.gate.reasons) {
    (reason.starts_with("image ") ? view.image_reasons : view.speed_reasons).push_back(reason);
  }
  return view;
}

std::string plural(std::size_t n, const char* one, const char* many) {
  return fmt::format("{} {}", n, n == 1 ? one : many);
}

// What went wrong with a failing scene, in a few words: "mount +7.9%", "gears image".
std::string failure_words(const SceneView& view) {
  std::vector<std::string> what;
  if (view.speed_outcome == GateOutcome::fail) {
    if (view.result->change && view.gate.speed != SpeedVerdict::failed) {
      what.push_back(signed_percent(view.result->change->change));
    } else {
      what.push_back(view.result->runs.failed() ? "crashed"
                                                : std::string(to_string(view.gate.speed)));
    }
  }
  if (view.image_outcome == GateOutcome::fail) what.push_back("image");
  // Said as speed is: "balls failed" for a scene as fast with three times the memory (a sweep).
  if (view.gate.memory == ChangeVerdict::regressed) {
    const std::optional<MemorySummary> memory = scene_memory(*view.result);
    what.push_back(memory ? "memory " + signed_percent(memory->change) : "memory");
  }
  if (what.empty()) what.push_back("failed");
  return fmt::format("{} {}", view.gate.id, fmt::join(what, ", "));
}

std::string ids_of(const std::vector<SceneView>& views, GateOutcome outcome, bool words) {
  std::vector<std::string> parts;
  for (const SceneView& view : views) {
    if (view.gate.outcome == outcome) parts.push_back(words ? failure_words(view) : view.gate.id);
  }
  return fmt::format("{}", fmt::join(parts, ", "));
}

std::string json_text(const nlohmann::json& machine, const char* key) {
  const auto found = machine.find(key);
  if (found == machine.end() || found->is_null()) return "";
  return value_text(*found);
}

}  // namespace

std::vector<SceneView> scene_views(const ReportInput& input) {
  std::vector<SceneView> views;
  for (const SceneResult& scene : input.document.scenes) views.push_back(make_view(input, scene));
  std::stable_sort(views.begin(), views.end(), [](const SceneView& a, const SceneView& b) {
    return reading_rank(a.gate.outcome) < reading_rank(b.gate.outcome);
  });
  return views;
}

std::vector<Role> ratio_roles(const ResultsDocument& document) {
  return revision_roles(document.kind);
}

Role primary_role(const ResultsDocument& document) { return primary_role(document.kind); }

namespace {

// Growth exponents that failed the gate (gate/growth_gate.h): a regression with no scene failed.
std::size_t failed_families(const GateResult& gate) {
  return static_cast<std::size_t>(
      std::count_if(gate.families.begin(), gate.families.end(),
                    [](const SceneGate& g) { return g.outcome == GateOutcome::fail; }));
}

// Scenes whose speed change the gate could not decide (INCONCLUSIVE, a warning).
std::size_t undecided_speed(const std::vector<SceneView>& views) {
  return static_cast<std::size_t>(std::count_if(views.begin(), views.end(), [](const SceneView& v) {
    return v.gate.speed == SpeedVerdict::inconclusive && v.speed_outcome == GateOutcome::warn;
  }));
}

}  // namespace

Headline headline(const ReportInput& input, const std::vector<SceneView>& views) {
  const GateResult& gate = input.gate;
  const std::size_t failed = gate.count(GateOutcome::fail);
  const std::size_t unmeasured = gate.count(GateOutcome::unmeasured);
  const std::size_t warned = gate.count(GateOutcome::warn);
  Headline line;
  if (failed > 0) {
    line.title = "raygate: " + plural(failed, "regression", "regressions");
    line.detail = ids_of(views, GateOutcome::fail, true);
    if (unmeasured > 0)
      line.detail += "; not measured: " + ids_of(views, GateOutcome::unmeasured, false);
  } else if (unmeasured > 0) {
    line.title = "raygate: could not measure " + plural(unmeasured, "scene", "scenes");
    line.detail = ids_of(views, GateOutcome::unmeasured, false);
  } else if (const std::size_t growth = failed_families(gate); growth > 0) {
    line.title = "raygate: growth regressed in " + plural(growth, "scene family", "scene families");
    line.detail = "the exponent of time against scene size rose beyond the policy's limit";
  } else if (views.empty() && gate.exit_code != 0) {
    line.title = "raygate: no scenes";
    line.detail = "nothing was measured";
  } else if (gate.exit_code != 0) {
    line.title = "raygate: incomplete";
    line.detail = "only " + plural(views.size(), "scene", "scenes") + " measured";
  } else {
    // An undecided speed change is named as such: "pass (1 scene, 1 warning; suite +1418.9%)"
    // read as a clean result with a huge change (the seventh sweep).
    const std::size_t undecided = undecided_speed(views);
    line.title = "raygate: pass";
    line.detail = plural(views.size(), "scene", "scenes");
    if (undecided > 0) line.detail += ", " + std::to_string(undecided) + " undecided";
    if (warned > undecided) line.detail += ", " + plural(warned - undecided, "warning", "warnings");
  }
  if (const auto change = suite_change(input.document)) {
    const bool decided = undecided_speed(views) == 0;
    line.detail +=
        fmt::format("; suite {}{}", signed_percent(*change), decided ? "" : ", undecided");
  } else if (const auto score = input.document.scores.find(Role::tracer);
             score != input.document.scores.end() && score->second.score > 0.0) {
    line.detail += fmt::format("; suite score {:.3f}", score->second.score);
  }
  return line;
}

std::string verdict_word(int exit_code) {
  if (exit_code == 0) return "pass";
  if (exit_code == 1) return "fail";
  return "could not measure";
}

std::string image_verdict_text(ImageVerdict verdict) {
  // "missing" read as "the image is missing"; what it means is that nobody blessed one yet.
  if (verdict == ImageVerdict::missing) return "no golden";
  return std::string(to_string(verdict));
}

std::string image_text(const SceneGate& gate, const std::string& none) {
  return gate.image ? image_verdict_text(*gate.image) : none;
}

namespace {

// How many runs decided a scene: " (8 fastest of 2)" when that many of its rounds kept each
// program's fastest of two runs (chosen per scene, or --repeats); empty when every round ran
// each once.
std::string fastest_of_text(const std::vector<Round>& rounds) {
  std::size_t repeated = 0;
  std::size_t most = 1;
  for (const Round& round : rounds) {
    const std::size_t runs = runs_per_contender(round);
    repeated += runs > 1 ? 1 : 0;
    most = std::max(most, runs);
  }
  return repeated > 0 ? fmt::format(" ({} fastest of {})", repeated, most) : "";
}

}  // namespace

std::optional<ChangeCell> change_cell(const SceneResult& scene, const SceneGate& gate) {
  if (!scene.change || scene.runs.failed()) return std::nullopt;
  const ChangeSummary& c = *scene.change;
  ChangeCell cell;
  cell.change = c.change;
  cell.rounds = c.rounds;
  cell.exact = c.exact;
  // The gate's verdict, so a report judged under another policy prints that policy's interval.
  cell.verdict = change_verdict_of(gate.speed).value_or(scene.change_verdict);
  if (c.exact) {
    cell.interval_name = "exact";
    if (c.change_interval.lower != c.change_interval.upper) {  // counts within the tolerance
      cell.interval = c.change_interval;
      cell.interval_name = "counted";
    }
    cell.text = change_with_interval(c, cell.verdict, gate.speed_limit);
    return cell;
  }
  const DecidingInterval decided = deciding_interval(c, cell.verdict, gate.speed_limit);
  cell.rounds_needed = rounds_to_bound(c, decided);
  if (c.rounds >= cell.rounds_needed) {
    cell.interval = decided.interval;
    cell.interval_name = interval_name(decided);
    cell.interval_confidence = decided.confidence;
  }
  cell.text = fmt::format("{}, {}{}", change_with_interval(c, cell.verdict, gate.speed_limit),
                          count_text(c.rounds, "round"), fastest_of_text(scene.runs.rounds));
  return cell;
}

std::string change_text(const SceneView& view) {
  const auto cell = change_cell(*view.result, view.gate);
  return cell ? cell->text : "";
}

std::string cost_text(const ResultsDocument& document, double value) {
  const std::string unit = document.settings.measure_unit();
  if (unit == "seconds") return fmt::format("{:.3f} s", value);
  return fmt::format("{:.4g} {}", value, unit);
}

std::vector<TableColumn> table_columns(const ResultsDocument& document) {
  if (is_compare(document.kind)) {
    return {{ColumnKind::ratio, "ratio base->head"},
            {ColumnKind::change, kChangeHeading},
            {ColumnKind::speed, "speed"},
            {ColumnKind::image, "image"}};
  }
  return {{ColumnKind::ratio, "ratio [95% CI]"},
          {ColumnKind::speed, "speed"},
          {ColumnKind::image, "image"}};
}

std::string columns_line(const ResultsDocument& document) {
  const std::string ratio = "ratio = time(tracer) / time(baseline), the median over rounds";
  if (!is_compare(document.kind)) return ratio + ", [its 95% CI]";
  return ratio +
         " the baseline joined; head's = base's x (1 + change), so both move with the "
         "change; change = median of per-round time(head) / time(base) - 1, [the "
         "interval its verdict was drawn from; INCONCLUSIVE: the one that would decide "
         "it]";
}

std::string cell_text(ColumnKind kind, const ResultsDocument& document, const SceneView& view,
                      const std::string& arrow, const std::string& none) {
  switch (kind) {
    case ColumnKind::ratio: return ratio_text(document, *view.result, arrow);
    case ColumnKind::change: return change_text(view);
    case ColumnKind::speed: return std::string(to_string(view.gate.speed));
    case ColumnKind::image: return image_text(view.gate, none);
  }
  return "";
}

namespace {

// Where the runs were pinned: an adapter's pin_cpus pins its tracer, --pin every run, and by
// default each round of a one-thread tracer runs on one CPU.
std::string pinning_text(const MeasurementSettings& s) {
  if (s.pin_cpus && !s.pin_cpus->empty()) {
    const std::vector<int>& cpus = *s.pin_cpus;
    const std::string where =
        fmt::format("CPU{} {}", cpus.size() == 1 ? "" : "s", fmt::join(cpus, ","));
    switch (s.pinned_by.value_or(PinnedBy::none)) {
      case PinnedBy::adapter:
        return "; the tracer pinned to " + where + " (its adapter's pin_cpus)";
      case PinnedBy::option: return "; every run pinned to " + where + " (--pin)";
      case PinnedBy::none: return "; pinned to " + where;
    }
  }
  if (s.round_cpus && !s.round_cpus->empty()) return "; each round pinned to one CPU";
  return "";
}

}  // namespace

std::string clock_line(const ResultsDocument& document) {
  const MeasurementSettings& s = document.settings;
  const std::string tracer = s.tracer_clock.value_or("");
  if (tracer.empty()) return "";
  std::string line = tracer;
  if (s.metric_by_threads.value_or(false)) {
    line += s.threads.value_or(1) > 1 ? " (auto: threads > 1)" : " (auto: one thread)";
  }
  if (const std::string baseline = s.baseline_clock.value_or(""); !baseline.empty()) {
    line += ", baseline " + baseline;
  }
  line += " (measures in " + s.measure_unit() + ")";
  line += pinning_text(s);
  if (s.cpu_idle == CpuIdle::poll) line += "; idle CPUs held polling";
  if (s.cpu_idle_refused) line += "; idle CPUs not held polling (" + *s.cpu_idle_refused + ")";
  return line;
}

std::string ratio_text(const ResultsDocument& document, const SceneResult& scene,
                       const std::string& arrow) {
  if (is_compare(document.kind)) {
    const RatioSummary* base = scene.ratio(Role::base);
    const RatioSummary* head = scene.ratio(Role::head);
    if (base == nullptr || head == nullptr) return "";
    return fmt::format("{:.3f} {} {:.3f}", base->ratio, arrow, head->ratio);
  }
  const RatioSummary* tracer = scene.ratio(Role::tracer);
  if (tracer == nullptr) return "";
  return fmt::format("{}, {}{}", ratio_interval_text(*tracer), count_text(tracer->rounds, "round"),
                     fastest_of_text(scene.runs.rounds));
}

std::optional<double> suite_change(const ResultsDocument& document) {
  // The geometric mean of the scenes' own changes, so the suite figure agrees in sign and size
  // with the rows above it (the ratio scores come from the rounds the baseline joined).
  double log_sum = 0.0;
  std::size_t scenes = 0;
  for (const SceneResult& scene : document.scenes) {
    if (!scene.change || scene.runs.failed() || !(scene.change->change > -1.0)) continue;
    log_sum += std::log1p(scene.change->change);
    ++scenes;
  }
  if (scenes == 0) return std::nullopt;
  return std::expm1(log_sum / static_cast<double>(scenes));
}

std::string value_text(const nlohmann::json& value) {
  if (value.is_string()) return value.get<std::string>();
  return value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string machine_line(const nlohmann::json& machine) {
  if (!machine.is_object()) return "";
  std::vector<std::string> parts;
  std::string cpu = json_text(machine, "cpu_model");
  if (const std::string cores = json_text(machine, "logical_cores"); !cores.empty()) {
    cpu += fmt::format(" ({} cores)", cores);
  }
  for (std::string part : {cpu, json_text(machine, "kernel")}) {
    if (!part.empty()) parts.push_back(part);
  }
  if (const std::string host = json_text(machine, "hostname"); !host.empty()) {
    parts.push_back("host " + host);
  }
  return fmt::format("{}", fmt::join(parts, ", "));
}

namespace {

// A commit's text as a report line shows it: its first line, at most `max_bytes` (cut at a
// character, marked "…"). A pull request's author writes it: a 70,000-character subject filled
// GitHub's comment limit before the scene table (a sweep).
std::string shown_commit_text(std::string_view text, std::size_t max_bytes) {
  text = text.substr(0, text.find('\n'));
  if (text.size() <= max_bytes) return std::string(text);
  std::size_t end = 0;
  while (end < max_bytes) {
    const std::size_t length = std::max<std::size_t>(1, utf8_sequence_length(text.substr(end)));
    if (end + length > max_bytes) break;
    end += length;
  }
  return std::string(text.substr(0, end)) + "…";
}

}  // namespace

std::string revision_line(const ResultsDocument& document, Role role) {
  const RevisionRecord* revision = document.revision(role);
  if (revision == nullptr) return "";
  const Worktree& tree = revision->worktree;
  constexpr std::size_t kSubjectBytes = 200;
  std::string line =
      fmt::format("{} {}", tree.short_sha, shown_commit_text(tree.subject, kSubjectBytes));
  if (!tree.revision.empty() && tree.revision != tree.sha)
    line += fmt::format(" ({})", shown_commit_text(tree.revision, kSubjectBytes));
  if (tree.dirty) line += " [dirty]";
  return line;
}

namespace {

// The scenes whose decision sequence is at 1 - 2 x family/K, by K: each scene's share of the
// compare's false alarms (measure/family.h). Read back from the levels the scenes carry; empty
// when some level is not such a share (a document from another raygate), so nothing is claimed.
std::map<long, std::vector<std::string>> scenes_by_share(const ResultsDocument& d, double family) {
  std::map<long, std::vector<std::string>> by_share;
  for (const SceneResult& scene : d.scenes) {
    const std::optional<ChangeSummary>& c = scene.change;
    if (!c || c->exact || c->interval_kind != ChangeIntervalKind::confidence_sequence) continue;
    const double share = (1.0 - c->confidence) / 2.0;
    const double scenes = family / share;
    if (!(share > 0.0) || !(std::abs(scenes - std::round(scenes)) < 1e-6 * scenes)) return {};
    by_share[std::lround(scenes)].push_back(scene.entry.id);
  }
  return by_share;
}

// Why each sequence has the level it has (pipeline/stop_rules.h scene_levels): UNCHANGED's is
// 1 - 2 x the significance; a decision sequence's 1 - 2 x family/K, its share of the compare's
// false alarms over K scenes, or Holm's larger family/(K - r) for a scene judged after r others
// were REGRESSED. "levels: 90% CS = 1 − 2 × the 5% significance; 99.5% = 1 - 2 x 1%/4 ...".
std::string levels_text(const GatePolicy& policy, const ResultsDocument& d) {
  const double significance = policy.defaults.significance;
  const auto level = [](double confidence) {
    return interval_name({{}, confidence, ChangeIntervalKind::confidence_sequence});
  };
  std::string text = fmt::format("levels: {} = 1 − 2 × the {:.4g}% significance",
                                 level(1.0 - 2.0 * significance), 100.0 * significance);
  const double family = d.settings.family_significance.value_or(policy.family_significance);
  const auto by_share = scenes_by_share(d, family);
  if (by_share.empty()) return text;
  const long most = by_share.rbegin()->first;
  for (auto it = by_share.rbegin(); it != by_share.rend(); ++it) {
    const auto& [scenes, ids] = *it;
    const std::string confidence = level(1.0 - 2.0 * family / static_cast<double>(scenes));
    if (scenes == most) {
      text += fmt::format("; {} = 1 − 2 × {:.4g}%/{} (each scene's share of the {:.4g}% over {})",
                          confidence, 100.0 * family, scenes, 100.0 * family,
                          count_text(static_cast<std::size_t>(scenes), "scene"));
    } else {
      // No verdict word (see policy_line): "found slower".
      const long slower = most - scenes;
      text += fmt::format(
          "; {} for {} = 1 − 2 × {:.4g}%/{} (Holm: a larger share once {} {} found "
          "slower)",
          confidence, fmt::join(ids, ", "), 100.0 * family, scenes, slower,
          slower == 1 ? "other scene was" : "others were");
    }
  }
  return text;
}

// The rule the document's images were judged by: a Monte Carlo tracer's runs within the image
// tolerance (its per-pixel thresholds were never used), else the per-pixel thresholds.
std::string image_rule_text(const ScenePolicy& d, const ResultsDocument& document) {
  if (document.settings.images == ImageKind::monte_carlo) {
    return fmt::format("images (Monte Carlo) pass within the ±{:.4g}% image tolerance",
                       100.0 * document.settings.image_tolerance.value_or(d.image_tolerance));
  }
  // One threshold for both by default: the line says what each verdict takes, not the same
  // number twice ("fail over 0.004 ..., warn over 0.004" read as a contradiction).
  std::string text =
      fmt::format("images fail when more than {:.4g}% of pixels differ by over {:.4g} in a channel",
                  d.image.fail_percent, d.image.fail_threshold);
  text += d.image.warn_threshold == d.image.fail_threshold
              ? std::string(" and warn when fewer do")
              : fmt::format(" and warn when any differs by over {:.4g}", d.image.warn_threshold);
  if (d.image.hard_fail < 1e29) {
    text += fmt::format("; any channel over {:.4g} off fails", d.image.hard_fail);
  }
  return text;
}

}  // namespace

std::string policy_line(const GatePolicy& policy, const ResultsDocument& document) {
  const ScenePolicy& d = policy.defaults;
  const DocumentKind kind = document.kind;
  std::string line;
  if (is_compare(kind)) {
    // The equivalence sequence's level, the one UNCHANGED rows name (measure/change.h).
    const DecidingInterval equivalence{
        {}, 1.0 - 2.0 * d.significance, ChangeIntervalKind::confidence_sequence};
    // No verdict words here: a report of a passing compare must not contain them (CI templates
    // search a comment for REGRESSED).
    line = fmt::format(
        "max slowdown {} (within the limit when the {} lies within ±{:.4g}%, slower when the "
        "decision CS lies above 0, at most {:.4g}% false alarms per compare; {}; {}); ",
        signed_percent(d.max_slowdown), interval_name(equivalence), 100.0 * d.max_slowdown,
        100.0 * policy.family_significance, kIntervalLegend, levels_text(policy, document));
  }
  line += image_rule_text(d, document);
  if (policy.fail_on_inconclusive && is_compare(kind)) line += "; inconclusive fails";
  if (!policy.scenes.empty()) {
    line += fmt::format("; {}", plural(policy.scenes.size(), "scene override", "scene overrides"));
  }
  return line;
}

std::filesystem::path role_image(const SceneResult& scene, Role role) {
  for (const ImageCheck& check : scene.images) {
    if (check.role == role && !check.actual.empty()) return check.actual;
  }
  if (const RunRecord* run = scene.runs.first_run(role)) return run->image;
  return {};
}

std::filesystem::path golden_image(const SceneResult& scene) {
  for (const ImageCheck& check : scene.images) {
    if (check.reference == ImageReference::golden && check.verdict != ImageVerdict::missing &&
        !check.expected.empty()) {
      return check.expected;
    }
  }
  return {};
}

std::filesystem::path resolve(const ReportInput& input, const std::filesystem::path& path) {
  if (path.empty() || path.is_absolute() || input.base_dir.empty()) return path;
  return input.base_dir / path;
}

}  // namespace raygate::report
