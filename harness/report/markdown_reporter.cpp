// The Markdown report: a pull-request comment and $GITHUB_STEP_SUMMARY. A bold headline a
// reviewer reads in the notification, a table with failures first, the reasons, and the setup
// folded away in <details>. GitHub refuses comments over 65536 characters, so when the report
// would be longer, passing scenes are left out from the end with a note saying how many.
#include <fmt/format.h>

#include <cctype>

#include "core/sanitize.h"
#include "report/memory_sections.h"
#include "report/counters_line.h"
#include "report/report_model.h"
#include "report/reporters.h"
#include "results/settings_json.h"
#include "scaling/scaling_text.h"

namespace raygate::report {
namespace {

// Text in a table cell or list item: nothing in it may end the cell or open HTML, emphasis or
// a link. A lone '>' opens nothing inside a line, so "ratio 0.731 -> 0.789" stays as written. A "]" right before "(" or "[" is escaped, which unmakes "[x](javascript:...)" and
// "![x](url)" from a commit subject while "[+6.1%, +9.8%]" stays as written. Control
// characters become visible escapes (core/sanitize.h).
std::string md(const std::string& raw) {
  const std::string text = markup_text(raw);  // controls shown as "\x1b", then escaped below
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == ']' && i + 1 < text.size() && (text[i + 1] == '(' || text[i + 1] == '[')) {
      out += "\\]";
      continue;
    }
    switch (c) {
      case '|': out += "\\|"; break;
      case '<': out += "&lt;"; break;
      case '&': out += "&amp;"; break;
      case '*':
      case '_':
      case '`':
      case '\\':
        out += '\\';
        out += c;
        break;
      case '\n':
      case '\r': out += ' '; break;
      default: out += c;
    }
  }
  return out;
}

std::string upper(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

std::string intro(const ResultsDocument& d) {
  if (is_compare(d.kind)) {
    return fmt::format("Compare on suite `{}`: base {} → head {}.\n", md(d.suite),
                       md(revision_line(d, Role::base)), md(revision_line(d, Role::head)));
  }
  return fmt::format("Run on suite `{}`: {}.\n", md(d.suite), md(revision_line(d, Role::tracer)));
}

std::string table_head(const ResultsDocument& d) {
  std::string names = "| verdict | scene |", rule = "|---|---|";
  for (const TableColumn& column : table_columns(d)) {
    names += fmt::format(" {} |", md(column.heading));
    rule += "---|";
  }
  return names + "\n" + rule + "\n";
}

std::string table_row(const ResultsDocument& d, const SceneView& view) {
  std::string row =
      fmt::format("| **{}** | {} |", upper(to_string(view.gate.outcome)), md(view.gate.id));
  for (const TableColumn& column : table_columns(d)) {
    row += fmt::format(" {} |", md(cell_text(column.kind, d, view, "→", "–")));
  }
  return row + "\n";
}

std::string reasons_of(const SceneView& view) {
  std::string text;
  for (const std::string& reason : view.gate.reasons) {
    text += fmt::format("- **{}** ({}): {}\n", md(view.gate.id), to_string(view.gate.outcome),
                        md(reason));
  }
  return text;
}

std::string key_values(const nlohmann::json& object) {
  std::string text;
  if (!object.is_object()) return text;
  for (const auto& [key, value] : object.items()) {
    const std::string shown = value_text(value);
    if (value.is_null() || shown.empty()) continue;
    // A backtick would end the code span and let the rest be read as Markdown.
    // Inside a code span nothing is Markdown, but control characters are still shown escaped.
    const bool plain = shown.find('`') != std::string::npos;
    text += plain ? fmt::format("- {}: {}\n", md(key), md(shown))
                  : fmt::format("- {}: `{}`\n", md(key), markup_text(shown));
  }
  return text;
}

std::string details(const ReportInput& input) {
  const ResultsDocument& d = input.document;
  std::string text = "<details><summary>Settings, machine and policy</summary>\n\n";
  text += fmt::format("- raygate {}, baseline {} (accel {}, {} timing)\n", md(d.raygate_version),
                      md(d.baseline.version), md(d.baseline.accel), md(d.baseline.timing));
  text += fmt::format("- started {}, finished {}\n", md(d.started_at), md(d.finished_at));
  if (const std::string clock = clock_line(d); !clock.empty()) {
    text += fmt::format("- clock: {}\n", md(clock));
  }
  if (const std::string counters = counters_line(d); !counters.empty()) {
    text += fmt::format("- counters: {}\n", md(counters));
  }
  text += fmt::format("- policy: {}\n", md(policy_line(input.policy, input.document)));
  for (const auto& [id, scene] : input.policy.scenes) {
    text += fmt::format("  - override {}: {}\n", md(id), md(scene.reason));
  }
  text.append("\n**Machine**\n\n").append(key_values(d.machine));
  text.append("\n**Settings**\n\n").append(key_values(to_json(d.settings)));
  return text + "\n</details>\n";
}

class MarkdownReporter final : public Reporter {
 public:
  explicit MarkdownReporter(std::size_t limit) : limit_(limit) {}
  void write(const ReportInput& input, std::ostream& out) const override;

 private:
  std::string compose(const ReportInput& input, const std::vector<SceneView>& views,
                      std::size_t shown, bool with_details) const;
  std::size_t limit_;
};

std::string MarkdownReporter::compose(const ReportInput& input, const std::vector<SceneView>& views,
                                      std::size_t shown, bool with_details) const {
  const ResultsDocument& d = input.document;
  const Headline line = headline(input, views);
  std::string text = fmt::format("**{}** ({})\n\n", md(line.title), md(line.detail));
  // Said once for the document, however many scenes share them (a tracer without goldens), and
  // under the headline, as in the HTML report: the runner-noise note says why scenes stayed
  // INCONCLUSIVE, which a reviewer needs before the table, not after the memory section.
  std::string notes;
  for (const std::string& problem : input.gate.problems) {
    notes += "- **problem**: " + md(problem) + "\n";
  }
  for (const std::string& note : input.gate.notes) notes += "- note: " + md(note) + "\n";
  if (!notes.empty()) text.append(notes).append("\n");
  text += intro(d) + "\n" + table_head(d);
  std::string reasons;
  for (std::size_t i = 0; i < shown; ++i) {
    text += table_row(d, views[i]);
    reasons += reasons_of(views[i]);
  }
  text += fmt::format("\n<sub>{}</sub>\n", md(columns_line(d)));
  if (shown < views.size()) {
    text += fmt::format(
        "\n_{} more scenes not shown: the full report would exceed GitHub's "
        "comment limit. See the HTML or JSON report._\n",
        views.size() - shown);
  }
  if (!reasons.empty()) text.append("\n").append(reasons);
  text += memory_markdown(input) + explanation_markdown(input);  // issue 27
  if (d.scaling) {
    text += "\n**Growth with scene size** (exponent k of t ≈ c·n^k, 95% CI)\n\n```\n";
    for (const std::string& fit : scaling_lines(*d.scaling)) {
      text += fit + "\n";
    }
    text += "```\n";
  }
  if (with_details) text.append("\n").append(details(input));
  return text;
}

// The last resort, when even the headline, the notes and the table head are over the limit
// (text no report shortens: a note of 70,000 characters): cut at the end of a line, with a line
// saying so, never inside a line (a table row or a link cut in half).
std::string cut(std::string text, std::size_t limit) {
  if (text.size() <= limit) return text;
  static constexpr std::string_view kSaid =
      "\n_The report was cut here: it would exceed GitHub's comment limit. See the HTML or JSON "
      "report._\n";
  const std::size_t room = limit > kSaid.size() ? limit - kSaid.size() : 0;
  std::size_t end = room == 0 ? 0 : text.rfind('\n', room - 1);
  if (end == std::string::npos) {  // one long first line: cut at a character
    end = room;
    while (end > 0 && (static_cast<unsigned char>(text[end]) & 0xC0) == 0x80) --end;
  }
  text.resize(end);
  return text.append(kSaid.substr(0, std::min(kSaid.size(), limit - end)));
}

void MarkdownReporter::write(const ReportInput& input, std::ostream& out) const {
  const std::vector<SceneView> views = scene_views(input);
  std::string text = compose(input, views, views.size(), true);
  if (text.size() > limit_) text = compose(input, views, views.size(), false);
  for (std::size_t shown = views.size(); text.size() > limit_ && shown > 0;) {
    text = compose(input, views, --shown, false);
  }
  out << cut(std::move(text), limit_);
}

}  // namespace

std::unique_ptr<Reporter> make_markdown_reporter(const ReportOptions& options) {
  return std::make_unique<MarkdownReporter>(options.markdown_limit);
}

}  // namespace raygate::report
