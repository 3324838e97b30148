// The console report: what a developer reads at a terminal or in a CI log. One header line, a
// table of scenes with failures first and each one's reasons under it, and a summary line.
// ANSI colour only when the caller asks (it knows whether the output is a terminal); text from
// outside never carries its own (render() below).
#include <fmt/format.h>

#include <cctype>
#include <utility>
#include <vector>

#include "core/sanitize.h"
#include "report/memory_sections.h"
#include "report/counters_line.h"
#include "report/report_model.h"
#include "report/reporters.h"

namespace raygate::report {
namespace {

// scene, the data columns of table_columns(), verdict: console, Markdown and HTML share them.
using Row = std::vector<std::string>;

const char* colour_code(GateOutcome outcome) {
  switch (outcome) {
    case GateOutcome::pass: return "\033[32m";
    case GateOutcome::warn: return "\033[33m";
    case GateOutcome::unmeasured: return "\033[35m";
    case GateOutcome::fail: return "\033[1;31m";
  }
  return "";
}

// One piece of the report and how it is drawn: the report is built as spans, then rendered
// in one place, where text from outside (subjects, host names, a tracer's messages) is made
// terminal-safe before the reporter's own colour codes go around it.
enum class Style { plain, dim, outcome };
struct Span {
  std::string text;
  Style style = Style::plain;
  GateOutcome outcome = GateOutcome::pass;  // Style::outcome: its colour
};
using Spans = std::vector<Span>;

class ConsoleReporter final : public Reporter {
 public:
  explicit ConsoleReporter(bool colour) : colour_(colour) {}
  void write(const ReportInput& input, std::ostream& out) const override;

 private:
  void render(const Spans& spans, std::ostream& out) const;
  bool colour_;
};

Span dim(std::string text) { return {std::move(text), Style::dim, GateOutcome::pass}; }
Span painted(std::string text, GateOutcome outcome) {
  return {std::move(text), Style::outcome, outcome};
}
Span plain(std::string text) { return {std::move(text), Style::plain, GateOutcome::pass}; }

Row heading(const ResultsDocument& document) {
  Row row{"scene"};
  for (const TableColumn& column : table_columns(document)) row.push_back(column.heading);
  row.push_back("verdict");
  return row;
}

Row row_of(const ResultsDocument& document, const SceneView& view) {
  std::string verdict(to_string(view.gate.outcome));
  for (char& c : verdict) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  Row row{view.gate.id};
  for (const TableColumn& column : table_columns(document)) {
    row.push_back(cell_text(column.kind, document, view));
  }
  row.push_back(verdict);
  return row;
}

// Column widths as rendered: a cell's control characters are shown escaped, so wider.
std::vector<std::size_t> widths_of(const std::vector<Row>& rows) {
  std::vector<std::size_t> widths(rows.front().size(), 0);
  for (const Row& row : rows) {
    for (std::size_t i = 0; i < row.size(); ++i) {
      widths[i] = std::max(widths[i], terminal_line(row[i]).size());
    }
  }
  return widths;
}

std::string padded(const Row& row, const std::vector<std::size_t>& widths, std::size_t columns) {
  std::string line;
  for (std::size_t i = 0; i < columns; ++i) {
    if (widths[i] == 0) continue;
    line += fmt::format("{:<{}}  ", terminal_line(row[i]), widths[i]);
  }
  return line;
}

void add_header(const ReportInput& input, Spans& spans) {
  const ResultsDocument& d = input.document;
  std::string line = fmt::format("raygate {} on suite {}", to_string(d.kind), d.suite);
  if (is_compare(d.kind)) {
    line += fmt::format(": base {} -> head {}", revision_line(d, Role::base),
                        revision_line(d, Role::head));
  } else if (const std::string tracer = revision_line(d, Role::tracer); !tracer.empty()) {
    line += ": " + tracer;
  }
  spans.push_back(plain(terminal_line(line) + "\n"));
  if (const std::string machine = machine_line(d.machine); !machine.empty()) {
    spans.push_back(dim("machine: " + machine));
    spans.push_back(plain("\n"));
  }
  if (const std::string clock = clock_line(d); !clock.empty()) {
    spans.push_back(dim("clock: " + clock));
    spans.push_back(plain("\n"));
  }
  if (const std::string counters = counters_line(d); !counters.empty()) {
    spans.push_back(dim("counters: " + counters));
    spans.push_back(plain("\n"));
  }
  spans.push_back(dim("policy: " + policy_line(input.policy, input.document)));
  spans.push_back(plain("\n"));
  spans.push_back(dim("columns: " + columns_line(d)));
  spans.push_back(plain("\n\n"));
}

void add_table(const ReportInput& input, const std::vector<SceneView>& views, Spans& spans) {
  std::vector<Row> rows{heading(input.document)};
  for (const SceneView& view : views) rows.push_back(row_of(input.document, view));
  const auto widths = widths_of(rows);
  const std::size_t columns = widths.size();
  std::string head = padded(rows[0], widths, columns);
  head.erase(head.find_last_not_of(' ') + 1);
  spans.push_back(dim(head));
  spans.push_back(plain("\n"));
  for (std::size_t i = 0; i < views.size(); ++i) {
    const GateOutcome outcome = views[i].gate.outcome;
    spans.push_back(plain(padded(rows[i + 1], widths, columns - 1)));
    spans.push_back(painted(rows[i + 1].back(), outcome));
    spans.push_back(plain("\n"));
    for (const std::string& reason : views[i].gate.reasons) {
      spans.push_back(plain("    "));
      spans.push_back(painted("- " + reason, outcome));
      spans.push_back(plain("\n"));
    }
  }
}

void add_footer(const ReportInput& input, const std::vector<SceneView>& views, Spans& spans) {
  // Said once for the document, however many scenes share them (a tracer without goldens).
  std::vector<std::string> problems = input.gate.problems;
  if (!input.outputs_failed.empty()) problems.push_back(input.outputs_failed);
  if (!input.gate.notes.empty() || !problems.empty()) spans.push_back(plain("\n"));
  for (const std::string& problem : problems) {
    spans.push_back(painted("problem: " + problem, GateOutcome::unmeasured));
    spans.push_back(plain("\n"));
  }
  for (const std::string& note : input.gate.notes) {
    spans.push_back(plain("note: " + terminal_line(note) + "\n"));
  }
  const Headline line = headline(input, views);
  const int exit_code = input.exit_code();
  const GateOutcome overall = exit_code == 0   ? GateOutcome::pass
                              : exit_code == 1 ? GateOutcome::fail
                                               : GateOutcome::unmeasured;
  spans.push_back(plain("\n"));
  spans.push_back(
      painted(fmt::format("{} ({}), exit {}", line.title, line.detail, exit_code), overall));
  spans.push_back(plain("\n"));
}

void ConsoleReporter::render(const Spans& spans, std::ostream& out) const {
  for (const Span& span : spans) {
    // A styled span is one line (a reason, a machine line); plain ones carry the line ends.
    const std::string text =
        span.style == Style::plain ? terminal_text(span.text) : terminal_line(span.text);
    if (!colour_ || span.style == Style::plain) {
      out << text;
    } else if (span.style == Style::dim) {
      out << "\033[2m" << text << "\033[0m";
    } else {
      out << colour_code(span.outcome) << text << "\033[0m";
    }
  }
}

void ConsoleReporter::write(const ReportInput& input, std::ostream& out) const {
  const std::vector<SceneView> views = scene_views(input);
  Spans spans;
  add_header(input, spans);
  add_table(input, views, spans);
  spans.push_back(plain(memory_console(input) + explanation_console(input)));  // issue 27
  add_footer(input, views, spans);
  render(spans, out);
}

}  // namespace

std::unique_ptr<Reporter> make_console_reporter(const ReportOptions& options) {
  return std::make_unique<ConsoleReporter>(options.colour);
}

}  // namespace raygate::report
