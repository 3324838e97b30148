// One scene's section of the HTML report: verdict badge and reasons, the ratio and change with
// their confidence intervals, the trend over commits, the images (golden, base, head; hovering
// one shows what it was compared with) with the |Δ|×16 evidence, and the image metrics.
#include <fmt/format.h>

#include <cmath>
#include <optional>

#include "core/format.h"
#include "measure/descriptive.h"
#include "measure/stop_words.h"
#include "report/html_parts.h"

namespace raygate::report::html {
namespace {

struct Shot {
  std::string id;
  std::string label;
  std::filesystem::path path;
  std::string swap_id;  // hovering shows this shot's image instead
  std::string swap_label;
  bool evidence = false;
  std::optional<Role> role;  // whose image; nullopt for the golden and the evidence
};

// Whether `shot` is the image `reference` names: the golden, or base's.
bool shows(const Shot& shot, ImageReference reference) {
  if (shot.evidence) return false;
  if (reference == ImageReference::golden) return !shot.role;
  return shot.role == Role::base;
}

std::string shot_id(const SceneView& view, const std::string& what) {
  return anchor(view.gate.id) + "-" + what;
}

// The reference a role's image is best compared with: that of its worst check.
ImageReference reference_of(const SceneResult& scene, Role role) {
  ImageReference reference = ImageReference::golden;
  int worst = -1;
  for (const ImageCheck& check : scene.images) {
    if (check.role != role) continue;
    const int rank =
        check.verdict == ImageVerdict::fail                                                  ? 2
        : check.verdict == ImageVerdict::warn || check.verdict == ImageVerdict::inconclusive ? 1
                                                                                             : 0;
    if (rank > worst) {
      worst = rank;
      reference = check.reference;
    }
  }
  return reference;
}

std::filesystem::path diff_of(const ImageCheck& check) {
  for (const std::filesystem::path& path : check.evidence) {
    if (path.string().ends_with(".diff.png")) return path;
  }
  return check.evidence.size() >= 3 ? check.evidence[2] : std::filesystem::path();
}

std::vector<Shot> shots_of(const ReportInput& input, const SceneView& view) {
  const SceneResult& scene = *view.result;
  std::vector<Shot> shots;
  if (const auto golden = golden_image(scene); !golden.empty()) {
    const std::string golden_word(to_string(ImageReference::golden));
    shots.push_back({shot_id(view, golden_word), golden_word, golden, "", "", false, {}});
  }
  for (const Role role : ratio_roles(input.document)) {
    const std::filesystem::path image = role_image(scene, role);
    if (image.empty()) continue;
    shots.push_back({shot_id(view, role_name(role)), role_name(role), image, "", "", false, role});
  }
  for (Shot& shot : shots) {
    if (!shot.role) continue;  // the golden: what the others are compared with
    const ImageReference reference = reference_of(scene, *shot.role);
    for (const Shot& other : shots) {
      if (shows(other, reference) && other.id != shot.id) {
        shot.swap_id = other.id;
        shot.swap_label = other.label;
      }
    }
  }
  for (const ImageCheck& check : scene.images) {
    if (const auto diff = diff_of(check); !diff.empty()) {
      const std::string role = role_name(check.role);
      const std::string reference(to_string(check.reference));
      shots.push_back({shot_id(view, "diff-" + role + "-" + reference),
                       fmt::format("|Δ|×16 {} vs {}", role, reference),
                       diff,
                       "",
                       "",
                       true,
                       {}});
    }
  }
  return shots;
}

std::string figure(const ReportInput& input, const Shot& shot) {
  const auto uri = image_data_uri(resolve(input, shot.path));
  std::string picture;
  if (uri) {
    picture = fmt::format(R"(<img id="{}" src="{}" alt="{}")", shot.id, *uri, escape(shot.label));
    if (!shot.swap_id.empty()) {
      picture += fmt::format(R"( data-swap="{}" data-swap-label="{}")", shot.swap_id,
                             escape(shot.swap_label));
    }
    picture += ">";
  } else {
    picture = fmt::format(R"(<div class="no-image">image not found<br><code>{}</code></div>)",
                          escape(shot.path.string()));
  }
  std::string caption = fmt::format(R"(<span class="who">{}</span>)", escape(shot.label));
  if (!shot.swap_id.empty() && uri) {
    caption += fmt::format(R"(<span class="hint">hover: {}</span>)", escape(shot.swap_label));
  }
  return fmt::format(
      R"(<figure class="shot{}"><div class="frame">{}</div><figcaption>{}</figcaption></figure>)",
      shot.evidence ? " evidence" : "", picture, caption);
}

std::string gallery(const ReportInput& input, const SceneView& view) {
  const std::vector<Shot> shots = shots_of(input, view);
  if (shots.empty()) return R"(<p class="muted">No images were recorded for this scene.</p>)";
  std::string out = R"(<div class="gallery">)";
  for (const Shot& shot : shots) out += figure(input, shot);
  return out + "</div>";
}

std::string metric_row(const ImageCheck& check) {
  const std::string who = fmt::format("{} vs {}", escape(role_name(check.role)),
                                      escape(std::string(to_string(check.reference))));
  const std::string verdict = fmt::format(R"(<span class="verdict v-{}">{}</span>)",
                                          escape(std::string(to_string(check.verdict))),
                                          escape(image_verdict_text(check.verdict)));
  if (!check.metrics) {
    return fmt::format(R"(<tr><td>{}</td><td>{}</td><td colspan="5" class="muted">{}</td></tr>)",
                       who, verdict, escape(check_detail(check)));
  }
  const ImageMetrics& m = *check.metrics;
  if (m.size_mismatch) {
    return fmt::format(R"(<tr><td>{}</td><td>{}</td><td colspan="5">{}</td></tr>)", who, verdict,
                       escape(summarize(m)));
  }
  if (m.identical()) {
    return fmt::format(
        R"(<tr><td>{}</td><td>{}</td><td colspan="5" class="muted">identical pixels</td></tr>)",
        who, verdict);
  }
  const std::string psnr = std::isfinite(m.psnr_db) ? fmt::format("{:.1f} dB", m.psnr_db) : "∞";
  return fmt::format(
      "<tr><td>{}</td><td>{}</td><td class=\"num\">{:.4g} <span class=\"muted\">at ({},{}) ch {}"
      "</span></td><td class=\"num\">{:.3g}%</td><td class=\"num\">{:.3g}</td>"
      "<td class=\"num\">{}</td><td class=\"num\">{:+.4f}</td></tr>",
      who, verdict, m.max_error, m.max_x, m.max_y, m.max_channel, m.percent_over_fail, m.rms_error,
      psnr, m.luminance_bias());
}

std::string metrics_table(const SceneResult& scene) {
  if (scene.images.empty()) return "";
  std::string out =
      R"(<table class="metrics"><thead><tr><th>image check</th><th>verdict</th><th>max error</th>)"
      R"(<th>pixels over fail</th><th>RMS</th><th>PSNR</th><th>luminance bias</th></tr></thead><tbody>)";
  for (const ImageCheck& check : scene.images) out += metric_row(check);
  return out + "</tbody></table>";
}

std::string mark_class(Role role, const SceneView& view) {
  if (role == Role::base) return "role-base";
  if (role == Role::head) return outcome_class(view.speed_outcome);
  return "role-tracer";
}

std::string speed_plots(const ReportInput& input, const SceneView& view) {
  const SceneResult& scene = *view.result;
  std::vector<IntervalRow> rows;
  for (const Role role : ratio_roles(input.document)) {
    if (const RatioSummary* r = scene.ratio(role)) {
      rows.push_back({role_name(role), r->ratio, r->ratio_interval.lower, r->ratio_interval.upper,
                      mark_class(role, view)});
    }
  }
  std::string out = ratio_bars_svg(rows);
  if (const std::optional<ChangeCell> cell = change_cell(scene, view.gate)) {
    const double limit = input.policy.for_scene(scene.entry.id).max_slowdown;
    out += change_bar_svg(*cell, limit, outcome_class(view.speed_outcome));
  }
  return out;
}

// Base's and head's times in the rounds that ran both (a document from disk may lack a side).
std::pair<std::vector<double>, std::vector<double>> compare_sides(const SceneResult& scene) {
  std::pair<std::vector<double>, std::vector<double>> sides;
  for (const Round& round : scene.runs.rounds) {
    const auto base = round.runs.find(role_name(Role::base));
    const auto head = round.runs.find(role_name(Role::head));
    if (base == round.runs.end() || head == round.runs.end()) continue;
    sides.first.push_back(base->second.seconds);
    sides.second.push_back(head->second.seconds);
  }
  return sides;
}

// Each program's median cost, in the document's unit, and over which rounds. In a compare the
// change is the median of the per-round head/base, and the baseline ran in only a few rounds:
// base's and head's medians over those few could read +16% beside a change of +0.8%. So base and
// head are given over every round, the baseline over its own, and the line says which number
// the change is.
std::string medians_fact(const ResultsDocument& d, const SceneResult& scene,
                         const RatioSummary& primary) {
  const std::string baseline = cost_text(d, primary.baseline_median_seconds);
  const auto [base, head] = compare_sides(scene);
  if (is_compare(d.kind) && scene.change && !base.empty()) {
    return fmt::format(
        "medians over the {}: base {}, head {} (the change, {}, is the median of each round's "
        "head/base, not the ratio of these two); the baseline {} over the {} it joined",
        count_text(base.size(), "round"), cost_text(d, median(base)), cost_text(d, median(head)),
        signed_percent(scene.change->change), baseline, count_text(primary.rounds, "round"));
  }
  std::string medians = "medians: baseline " + baseline;
  for (const Role role : ratio_roles(d)) {
    if (const RatioSummary* r = scene.ratio(role)) {
      medians += fmt::format(", {} {}", to_string(role), cost_text(d, r->tracer_median_seconds));
    }
  }
  return medians;
}

// "15 rounds (the baseline in 3)", then each program's median cost (medians_fact).
std::vector<std::string> round_facts(const ResultsDocument& d, const SceneResult& scene) {
  std::vector<std::string> facts;
  const RatioSummary* primary = scene.ratio(primary_role(d));
  if (primary == nullptr) return facts;
  const std::size_t all_rounds = scene.runs.rounds.size();
  if (scene.change && all_rounds > scene.change->rounds) {
    // Rounds for the stored ratio after the change was decided (pipeline/stored_ratio.h).
    facts.push_back(fmt::format("{} decided the change, {} in all (the baseline in {})",
                                count_text(scene.change->rounds, "round"), all_rounds,
                                primary->rounds));
  } else if (scene.change && scene.change->rounds != primary->rounds) {
    facts.push_back(fmt::format("{} (the baseline in {})",
                                count_text(scene.change->rounds, "round"), primary->rounds));
  } else {
    facts.push_back(count_text(primary->rounds, "round"));
  }
  facts.push_back(medians_fact(d, scene, *primary));
  return facts;
}

std::string run_facts(const ReportInput& input, const SceneResult& scene) {
  const ResultsDocument& d = input.document;
  std::vector<std::string> facts = round_facts(d, scene);
  if (!scene.runs.stop_reason.empty()) facts.push_back(stop_reason_text(scene.runs.stop_reason));
  // The pairing-free second opinion (docs/statistics.md §5) on the rounds the baseline joined;
  // the verdict does not use it. Not beside a counted change (no sampling error to test), nor
  // with fewer than 6 rounds a side, where no p can fall below 0.05 whatever the change.
  const RatioSummary* base = scene.ratio(Role::base);
  if (scene.change && !scene.runs.failed() && !scene.change->exact && base != nullptr &&
      base->rounds >= 6) {
    facts.push_back(fmt::format(
        "Mann–Whitney U {:.1f}, p {:.3g} over the {} rounds with the "
        "baseline (not used by the verdict)",
        scene.change->mann_whitney.u, scene.change->mann_whitney.p_value, base->rounds));
  }
  facts.push_back(fmt::format("{:.1f} s spent", scene.runs.seconds_spent));
  return fmt::format(R"(<p class="facts">{}</p>)",
                     escape(fmt::format("{}", fmt::join(facts, " · "))));
}

// The reasons above already say what failed and where its log is; this says what it costs.
std::string failure_note(const SceneResult& scene) {
  if (!scene.runs.failed_run) return "";
  return fmt::format(R"(<div class="failure">No ratio: the {} run {}.</div>)",
                     escape(role_name(scene.runs.failed_role)),
                     escape(scene.runs.failed_run->outcome));
}

std::string head_line(const SceneView& view) {
  const SuiteScene& entry = view.result->entry;
  std::string spec = entry.scene;
  if (entry.size > 0) spec += fmt::format(" · size {}", entry.size);
  if (entry.width > 0) spec += fmt::format(" · {}×{}", entry.width, entry.height);
  std::string tags = fmt::format(R"(<span class="tag speed-{0}">{0}</span>)",
                                 escape(std::string(to_string(view.gate.speed))));
  if (view.gate.image) {
    tags += fmt::format(R"(<span class="tag v-{}">image: {}</span>)",
                        escape(std::string(to_string(*view.gate.image))),
                        escape(image_text(view.gate, "")));
  }
  return fmt::format(
      R"(<header class="scene-head"><h2><a href="#{}">{}</a></h2>{}{}<span class="spec">{}</span></header>)",
      anchor(view.gate.id), escape(view.gate.id), badge(view.gate.outcome), tags, escape(spec));
}

std::string reasons_list(const SceneView& view) {
  if (view.gate.reasons.empty()) return "";
  std::string out = R"(<ul class="reasons">)";
  for (const std::string& reason : view.gate.reasons) out += "<li>" + escape(reason) + "</li>";
  return out + "</ul>";
}

}  // namespace

std::string scene_section(const ReportInput& input, const SceneView& view) {
  const SceneResult& scene = *view.result;
  std::string numbers =
      "<h3>Speed</h3>" + failure_note(scene) + speed_plots(input, view) + run_facts(input, scene);
  if (const TrendSeries* trend = input.trend(scene.entry.id)) {
    std::vector<TrendMark> marks;
    for (const RevisionRecord& revision : input.document.revisions) {
      marks.push_back({revision.worktree.sha,
                       revision.role == Role::tracer ? "this run" : role_name(revision.role)});
    }
    numbers += fmt::format("<h3>Trend over {} commits</h3>", trend->points.size()) +
               trend_svg(*trend, marks) +
               R"(<p class="facts">normalized ratio per commit, oldest first; the band is its )"
               R"(95% CI; this report's commits are marked; point at a commit for its )"
               R"(subject</p>)";
  }
  return fmt::format(
      R"(<section class="scene card {}" id="{}">{}{}<div class="scene-body">)"
      R"(<div class="scene-numbers">{}</div><div class="scene-images"><h3>Images</h3>{}</div>)"
      R"(</div>{}</section>)",
      outcome_class(view.gate.outcome), anchor(view.gate.id), head_line(view), reasons_list(view),
      numbers, gallery(input, view), metrics_table(scene));
}

}  // namespace raygate::report::html
