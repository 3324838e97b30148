// The console report: what a developer reads at a terminal or in a CI log. One header line, a
// table of scenes with failures first and each one's reasons under it, and a summary line.
// ANSI colour only when the caller asks (it knows whether the output is a terminal).
#include <fmt/format.h>

#include <array>
#include <cctype>

#include "report/report_model.h"
#include "report/reporters.h"

namespace raygate::report {
namespace {

constexpr std::size_t kColumns = 6;
using Row = std::array<std::string, kColumns>;

const char* colour_code(GateOutcome outcome) {
  switch (outcome) {
    case GateOutcome::pass: return "\033[32m";
    case GateOutcome::warn: return "\033[33m";
    case GateOutcome::unmeasured: return "\033[35m";
    case GateOutcome::fail: return "\033[1;31m";
  }
  return "";
}

class ConsoleReporter final : public Reporter {
 public:
  explicit ConsoleReporter(bool colour) : colour_(colour) {}
  void write(const ReportInput& input, std::ostream& out) const override;

 private:
  std::string paint(const std::string& text, GateOutcome outcome) const {
    return colour_ ? fmt::format("{}{}\033[0m", colour_code(outcome), text) : text;
  }
  std::string dim(const std::string& text) const {
    return colour_ ? fmt::format("\033[2m{}\033[0m", text) : text;
  }
  void write_header(const ReportInput& input, std::ostream& out) const;
  void write_table(const ReportInput& input, const std::vector<SceneView>& views,
                   std::ostream& out) const;
  bool colour_;
};

Row heading(const ResultsDocument& document) {
  const bool compare = document.kind == "compare";
  return {"scene", compare ? "ratio base->head" : "ratio [95% CI]",
          compare ? kChangeHeading : "", "speed", "image", "verdict"};
}

Row row_of(const ResultsDocument& document, const SceneView& view) {
  std::string verdict(to_string(view.gate.outcome));
  for (char& c : verdict) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return {view.gate.id, ratio_text(document, *view.result), change_text(*view.result),
          view.gate.speed, image_text(view.gate, "-"), verdict};
}

std::array<std::size_t, kColumns> widths_of(const std::vector<Row>& rows) {
  std::array<std::size_t, kColumns> widths{};
  for (const Row& row : rows) {
    for (std::size_t i = 0; i < kColumns; ++i) widths[i] = std::max(widths[i], row[i].size());
  }
  return widths;
}

std::string padded(const Row& row, const std::array<std::size_t, kColumns>& widths,
                   std::size_t columns) {
  std::string line;
  for (std::size_t i = 0; i < columns; ++i) {
    if (widths[i] == 0) continue;
    line += fmt::format("{:<{}}  ", row[i], widths[i]);
  }
  return line;
}

void ConsoleReporter::write_header(const ReportInput& input, std::ostream& out) const {
  const ResultsDocument& d = input.document;
  std::string line = fmt::format("raygate {} on suite {}", d.kind, d.suite);
  if (d.kind == "compare") {
    line += fmt::format(": base {} -> head {}", revision_line(d, "base"), revision_line(d, "head"));
  } else if (const std::string tracer = revision_line(d, "tracer"); !tracer.empty()) {
    line += ": " + tracer;
  }
  out << line << '\n';
  if (const std::string machine = machine_line(d.machine); !machine.empty()) {
    out << dim("machine: " + machine) << '\n';
  }
  if (const std::string clock = clock_line(d); !clock.empty()) out << dim("clock: " + clock) << '\n';
  out << dim("policy: " + policy_line(input.policy)) << "\n\n";
}

void ConsoleReporter::write_table(const ReportInput& input, const std::vector<SceneView>& views,
                                  std::ostream& out) const {
  std::vector<Row> rows{heading(input.document)};
  for (const SceneView& view : views) rows.push_back(row_of(input.document, view));
  const auto widths = widths_of(rows);
  std::string head = padded(rows[0], widths, kColumns);
  head.erase(head.find_last_not_of(' ') + 1);
  out << dim(head) << '\n';
  for (std::size_t i = 0; i < views.size(); ++i) {
    const GateOutcome outcome = views[i].gate.outcome;
    out << padded(rows[i + 1], widths, kColumns - 1) << paint(rows[i + 1].back(), outcome) << '\n';
    for (const std::string& reason : views[i].gate.reasons) {
      out << "    " << paint("- " + reason, outcome) << '\n';
    }
  }
}

void ConsoleReporter::write(const ReportInput& input, std::ostream& out) const {
  const std::vector<SceneView> views = scene_views(input);
  write_header(input, out);
  write_table(input, views, out);
  // Said once for the document, however many scenes share them (a tracer without goldens).
  if (!input.gate.notes.empty() || !input.gate.problems.empty()) out << '\n';
  for (const std::string& problem : input.gate.problems) {
    out << paint("problem: " + problem, GateOutcome::unmeasured) << '\n';
  }
  for (const std::string& note : input.gate.notes) out << "note: " << note << '\n';
  const Headline line = headline(input, views);
  const GateOutcome overall = input.gate.exit_code == 0   ? GateOutcome::pass
                              : input.gate.exit_code == 1 ? GateOutcome::fail
                                                          : GateOutcome::unmeasured;
  out << '\n'
      << paint(fmt::format("{} ({}), exit {}", line.title, line.detail, input.gate.exit_code),
               overall)
      << '\n';
}

}  // namespace

std::unique_ptr<Reporter> make_console_reporter(const ReportOptions& options) {
  return std::make_unique<ConsoleReporter>(options.colour);
}

}  // namespace raygate::report
