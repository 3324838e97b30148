// The HTML report: one self-contained page a reviewer opens from a CI artifact. From the top:
// the verdict banner, what was compared (repository, base and head commits, machine, policy),
// an overview table with failures first, then one section per scene (html_scene.cpp).
#include <fmt/format.h>

#include "report/counters_line.h"
#include "report/html_parts.h"
#include "report/memory_sections.h"
#include "report/reporters.h"

namespace raygate::report::html {
namespace {

GateOutcome overall_outcome(const GateResult& gate) {
  if (gate.exit_code == 0)
    return gate.count(GateOutcome::warn) > 0 ? GateOutcome::warn : GateOutcome::pass;
  return gate.exit_code == 1 ? GateOutcome::fail : GateOutcome::unmeasured;
}

std::string meta_row(const std::string& key, const std::string& value_html) {
  return fmt::format("<dt>{}</dt><dd>{}</dd>", escape(key), value_html);
}

std::string commit_html(const ResultsDocument& d, Role role) {
  const RevisionRecord* revision = d.revision(role);
  if (revision == nullptr) return "";
  const Worktree& tree = revision->worktree;
  std::string html =
      fmt::format(R"(<code class="sha" title="{}">{}</code> <span class="subject">{}</span>)",
                  escape(tree.sha), escape(tree.short_sha), escape(tree.subject));
  std::vector<std::string> extra;
  if (!tree.revision.empty() && tree.revision != tree.sha) extra.push_back(tree.revision);
  if (!tree.author.empty()) extra.push_back(tree.author);
  if (!tree.commit_time.empty()) extra.push_back(tree.commit_time);
  if (tree.dirty) extra.push_back("uncommitted changes");
  if (!extra.empty()) {
    html += fmt::format(R"( <span class="muted">{}</span>)",
                        escape(fmt::format("{}", fmt::join(extra, " · "))));
  }
  return html;
}

std::string repository_of(const ResultsDocument& d) {
  for (const RevisionRecord& revision : d.revisions) {
    if (!revision.repository.empty()) return revision.repository;
  }
  return "";
}

std::string overrides_html(const GatePolicy& policy) {
  std::string html;
  for (const auto& [id, scene] : policy.scenes) {
    html += fmt::format(R"(<div class="override"><code>{}</code>: max slowdown {} — {}</div>)",
                        escape(id), signed_percent(scene.max_slowdown), escape(scene.reason));
  }
  return html;
}

std::string meta_list(const ReportInput& input) {
  const ResultsDocument& d = input.document;
  std::string rows;
  if (const std::string repo = repository_of(d); !repo.empty()) {
    rows += meta_row("repository", "<code>" + escape(repo) + "</code>");
  }
  for (const Role role : ratio_roles(d)) {
    if (const std::string commit = commit_html(d, role); !commit.empty()) {
      rows += meta_row(role_name(role), commit);
    }
  }
  if (const std::string machine = machine_line(d.machine); !machine.empty()) {
    rows += meta_row("machine", escape(machine));
  }
  if (const std::string clock = clock_line(d); !clock.empty()) {
    rows += meta_row("clock", escape(clock));
  }
  if (const std::string counters = counters_line(d); !counters.empty()) {
    rows += meta_row("counters", escape(counters));
  }
  rows += meta_row("baseline", escape(fmt::format("{} · accel {} · {} timing", d.baseline.version,
                                                  d.baseline.accel, d.baseline.timing)));
  rows += meta_row(
      "policy", escape(policy_line(input.policy, input.document)) + overrides_html(input.policy));
  rows += meta_row("measured", escape(fmt::format("{} → {}{}", d.started_at, d.finished_at,
                                                  d.complete ? "" : " (incomplete)")));
  return R"(<dl class="meta">)" + rows + "</dl>";
}

std::string banner(const ReportInput& input, const std::vector<SceneView>& views) {
  const Headline line = headline(input, views);
  const GateOutcome outcome = overall_outcome(input.gate);
  return fmt::format(
      R"(<div class="banner {}"><span class="big-badge">{}</span><div><div class="headline">{}</div>)"
      R"(<div class="detail">{} · exit code {}</div></div></div>)",
      outcome_class(outcome), escape(verdict_word(input.gate.exit_code)), escape(line.title),
      escape(line.detail), input.exit_code());
}

// What the gate says of the whole document (a problem that keeps it from passing; notes such as
// missing goldens or the runner's noise), under the headline, as the Markdown comment and the
// console list them.
std::string gate_notes_html(const GateResult& gate) {
  std::string html;
  for (const std::string& problem : gate.problems) {
    html += R"(<p class="note"><b>problem</b>: )" + escape(problem) + "</p>";
  }
  for (const std::string& note : gate.notes) {
    html += R"(<p class="note">note: )" + escape(note) + "</p>";
  }
  return html;
}

std::string counts_html(const GateResult& gate) {
  std::string html = R"(<div class="counts">)";
  for (const GateOutcome o :
       {GateOutcome::fail, GateOutcome::unmeasured, GateOutcome::warn, GateOutcome::pass}) {
    html +=
        fmt::format(R"(<span class="count {}"><b>{}</b> {}</span>)", outcome_class(o),
                    gate.count(o), o == GateOutcome::unmeasured ? "not measured" : to_string(o));
  }
  return html + "</div>";
}

// A cell of the overview table; speed and image are tags coloured by their verdict.
std::string overview_cell(const TableColumn& column, const ResultsDocument& d,
                          const SceneView& view) {
  const std::string text = cell_text(column.kind, d, view, "→", "");
  switch (column.kind) {
    case ColumnKind::speed:
      return fmt::format(R"(<td><span class="tag speed-{0}">{0}</span></td>)", escape(text));
    case ColumnKind::image:
      if (!view.gate.image) return "<td>–</td>";
      return fmt::format(R"(<td><span class="verdict v-{}">{}</span></td>)",
                         escape(std::string(to_string(*view.gate.image))), escape(text));
    case ColumnKind::ratio:
    case ColumnKind::change: break;
  }
  return fmt::format(R"(<td class="num">{}</td>)", escape(text));
}

std::string overview(const ReportInput& input, const std::vector<SceneView>& views) {
  const ResultsDocument& d = input.document;
  const std::vector<TableColumn> columns = table_columns(d);
  std::string html = R"(<section class="card overview"><h2>Scenes</h2>)" + counts_html(input.gate);
  html += R"(<table class="scenes"><thead><tr><th>scene</th><th>verdict</th>)";
  for (const TableColumn& column : columns) html += "<th>" + escape(column.heading) + "</th>";
  html += "</tr></thead><tbody>";
  for (const SceneView& view : views) {
    html += fmt::format(R"(<tr class="{}"><td><a href="#{}">{}</a></td><td>{}</td>)",
                        outcome_class(view.gate.outcome), anchor(view.gate.id),
                        escape(view.gate.id), badge(view.gate.outcome));
    for (const TableColumn& column : columns) html += overview_cell(column, d, view);
    html += "</tr>";
  }
  return html + "</tbody></table></section>";
}

std::string title_of(const ResultsDocument& d) {
  if (is_compare(d.kind)) {
    const RevisionRecord* base = d.revision(Role::base);
    const RevisionRecord* head = d.revision(Role::head);
    return fmt::format("raygate compare · {} → {} · suite {}",
                       base ? base->worktree.short_sha : "?", head ? head->worktree.short_sha : "?",
                       d.suite);
  }
  const RevisionRecord* tracer = d.revision(Role::tracer);
  return fmt::format("raygate run · {} · suite {}", tracer ? tracer->worktree.short_sha : "?",
                     d.suite);
}

class HtmlReporter final : public Reporter {
 public:
  void write(const ReportInput& input, std::ostream& out) const override {
    const ResultsDocument& d = input.document;
    const std::vector<SceneView> views = scene_views(input);
    const std::string title = title_of(d);
    out << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
        << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">"
        << "<title>" << escape(title) << "</title><style>" << page_style() << "</style></head>\n"
        << "<body data-js=\"off\"><div class=\"page\">"
        << "<header class=\"top card\"><div class=\"brand\">raygate <span>" << to_string(d.kind)
        << " report</span></div><h1>" << escape(title) << "</h1>" << banner(input, views)
        << gate_notes_html(input.gate) << meta_list(input) << "</header>\n"
        << overview(input, views) << '\n'
        << scaling_section(d) << '\n'
        << memory_html(input) << explanation_html(input) << '\n';  // issue 27
    for (const SceneView& view : views) out << scene_section(input, view) << '\n';
    out << "<footer>raygate " << escape(d.raygate_version)
        << " · normalized ratio = time(tracer) / time(baseline), median of the rounds the "
           "baseline joined, with its 95% CI (head's: base's times the change) · "
           "change = median of per-round head/base, with the interval that decided its verdict or, "
           "for INCONCLUSIVE, would decide it ("
        << escape(kIntervalLegend) << ") · hover an image to see its reference</footer></div>\n"
        << "<script>" << page_script() << "</script></body></html>\n";
  }
};

}  // namespace
}  // namespace raygate::report::html

namespace raygate::report {

std::unique_ptr<Reporter> make_html_reporter(const ReportOptions&) {
  return std::make_unique<html::HtmlReporter>();
}

}  // namespace raygate::report
