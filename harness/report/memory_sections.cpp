#include "report/memory_sections.h"

#include <fmt/core.h>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/format.h"
#include "core/sanitize.h"
#include "gate/memory_gate.h"
#include "report/html_parts.h"

namespace raygate::report {
namespace {

struct MemoryRow {
  std::string scene;
  std::string peak;     // "8.1 MiB -> 58.3 MiB" (compare) or "8.1 MiB" (run)
  std::string change;   // "+50.2 MiB (+620%)"; "" for a run
  std::string verdict;  // REGRESSED ...; "" for a run
};

std::string delta_text(const MemorySummary& s) {
  const std::string sign = s.delta_kib < 0.0 ? "-" : "+";
  return fmt::format("{}{} ({})", sign, memory_text(std::abs(s.delta_kib)),
                     signed_percent(s.change));
}

std::vector<MemoryRow> memory_rows(const ReportInput& input) {
  const ResultsDocument& d = input.document;
  std::vector<MemoryRow> rows;
  for (const SceneResult& scene : d.scenes) {
    const std::string& id = scene.entry.id;
    if (is_compare(d.kind)) {
      const auto judged = judge_scene_memory(scene, input.policy.for_scene(id));
      if (!judged) continue;
      rows.push_back(
          {id,
           memory_text(judged->summary.base_kib) + " -> " + memory_text(judged->summary.head_kib),
           delta_text(judged->summary), std::string(to_string(judged->verdict))});
    } else if (const auto peak = median_peak_kib(scene.runs, Role::tracer)) {
      rows.push_back({id, memory_text(*peak), "", ""});
    }
  }
  return rows;
}

// "the tracer's whole process tree at once (cgroup v2 memory.peak)": what the peaks are (issue
// 40).
std::string method_note(const ReportInput& input) {
  std::vector<std::string> parts;
  for (const PeakMethod method : peak_methods(input.document)) {
    parts.push_back(describe_peak_method(method));
  }
  if (parts.empty()) return "the tracer's own";
  return "the tracer's " + fmt::format("{}", fmt::join(parts, " and "));
}

std::string limit_note(const ReportInput& input) {
  if (!is_compare(input.document.kind)) return "median over the rounds";
  return fmt::format("median of each side; limit {} (changes under max(1 MiB, 2%) not judged)",
                     signed_percent(input.policy.defaults.max_memory_increase, 0));
}

std::vector<const SceneResult*> explained_scenes(const ReportInput& input) {
  std::vector<const SceneResult*> out;
  for (const SceneResult& scene : input.document.scenes) {
    if (scene.explanation) out.push_back(&scene);
  }
  return out;
}

// Aligned columns of plain text (console and Markdown code blocks).
std::string aligned(const std::vector<std::vector<std::string>>& rows, const std::string& indent) {
  std::vector<std::size_t> widths;
  for (const auto& row : rows) {
    widths.resize(std::max(widths.size(), row.size()));
    for (std::size_t i = 0; i < row.size(); ++i) widths[i] = std::max(widths[i], row[i].size());
  }
  std::string text;
  for (const auto& row : rows) {
    std::string line = indent;
    for (std::size_t i = 0; i < row.size(); ++i) {
      line += i + 1 == row.size() ? row[i] : fmt::format("{:<{}}  ", row[i], widths[i]);
    }
    line.erase(line.find_last_not_of(' ') + 1);
    text += line + "\n";
  }
  return text;
}

std::string memory_table_text(const std::vector<MemoryRow>& rows, bool compare) {
  std::vector<std::vector<std::string>> cells;
  cells.push_back(compare
                      ? std::vector<std::string>{"scene", "peak base -> head", "change", "memory"}
                      : std::vector<std::string>{"scene", "peak"});
  for (const MemoryRow& r : rows) {
    cells.push_back(compare ? std::vector<std::string>{r.scene, r.peak, r.change, r.verdict}
                            : std::vector<std::string>{r.scene, r.peak});
  }
  return aligned(cells, "  ");
}

std::string signed_count(double value) {
  return fmt::format("{}{}", value >= 0.0 ? "+" : "", abbreviated_count(value));
}

std::string count_pair(std::uint64_t base, std::uint64_t head) {
  return abbreviated_count(static_cast<double>(base)) + " -> " +
         abbreviated_count(static_cast<double>(head));
}

// By cycles (sim mode): the change, its share and the instructions. By instructions (callgrind):
// the self change, its share, self and inclusive instructions, and the inclusive change.
std::vector<std::vector<std::string>> function_cells(const Explanation& e, std::size_t top) {
  const bool cycles = e.cost == ExplainCost::estimated_cycles;
  std::vector<std::vector<std::string>> cells;
  if (cycles) {
    cells.push_back({"change (cycles)", "share", "instructions base -> head", "function"});
  } else {
    cells.push_back({"self change (instr.)", "share", "self base -> head", "inclusive base -> head",
                     "inclusive change", "function"});
  }
  for (std::size_t i = 0; i < e.functions.size() && i < top; ++i) {
    const FunctionChange& f = e.functions[i];
    std::vector<std::string> row{signed_count(e.delta_of(f)),
                                 signed_percent(share_of_change(e, f), 0),
                                 count_pair(f.base_instructions, f.head_instructions)};
    if (!cycles) {
      row.push_back(count_pair(f.base_inclusive_instructions, f.head_inclusive_instructions));
      row.push_back(signed_count(f.delta_inclusive_instructions()));
    }
    row.push_back(f.name);
    cells.push_back(std::move(row));
  }
  return cells;
}

std::string cost_note(const Explanation& e) {
  if (e.source == ExplainSource::simulated_runs) {
    return "from the sim runs' own cachegrind files (no extra runs)";
  }
  if (e.native_seconds <= 0.0) return fmt::format("profiling took {:.1f} s", e.profile_seconds);
  return fmt::format(
      "profiling took {:.1f} s for one base and one head run, {:.0f}x their "
      "{:.2f} s measured",
      e.profile_seconds, e.profile_seconds / e.native_seconds, e.native_seconds);
}

std::string explanation_heading(const SceneResult& scene, const Explanation& e) {
  const double base = e.base_cost();
  const double head = e.head_cost();
  return fmt::format("{}: where the time went ({}; {} {} -> {}, {}; {})", scene.entry.id,
                     e.profiler,
                     e.cost == ExplainCost::instructions ? "instructions" : "estimated cycles",
                     abbreviated_count(base), abbreviated_count(head),
                     signed_percent(base > 0.0 ? head / base - 1.0 : 0.0), cost_note(e));
}

// Inside a Markdown code block only a backtick run could end it.
std::string code_safe(std::string text) {
  std::replace(text.begin(), text.end(), '`', '\'');
  return markup_text(text);
}

}  // namespace

std::string memory_console(const ReportInput& input) {
  const std::vector<MemoryRow> rows = memory_rows(input);
  if (rows.empty()) return "";
  return fmt::format("\nmemory (peak of {}; {}):\n{}", method_note(input), limit_note(input),
                     memory_table_text(rows, is_compare(input.document.kind)));
}

std::string explanation_console(const ReportInput& input) {
  std::string text;
  for (const SceneResult* scene : explained_scenes(input)) {
    text += fmt::format("\n{}:\n{}", explanation_heading(*scene, *scene->explanation),
                        aligned(function_cells(*scene->explanation, kConsoleExplained), "  "));
  }
  return text;
}

std::string memory_markdown(const ReportInput& input) {
  const std::vector<MemoryRow> rows = memory_rows(input);
  if (rows.empty()) return "";
  return fmt::format("\n**Memory** (peak of {}; {})\n\n```\n{}```\n", method_note(input),
                     limit_note(input),
                     code_safe(memory_table_text(rows, is_compare(input.document.kind))));
}

std::string explanation_markdown(const ReportInput& input) {
  std::string text;
  for (const SceneResult* scene : explained_scenes(input)) {
    text += fmt::format(
        "\n**{}**\n\n```\n{}```\n", code_safe(explanation_heading(*scene, *scene->explanation)),
        code_safe(aligned(function_cells(*scene->explanation, kMarkdownExplained), "")));
  }
  return text;
}

std::string memory_html(const ReportInput& input) {
  using html::escape;
  const std::vector<MemoryRow> rows = memory_rows(input);
  if (rows.empty()) return "";
  const bool compare = is_compare(input.document.kind);
  std::string out = fmt::format(
      "<section class=\"card memory\"><h2>Memory</h2><p>Peak memory of {}; "
      "{}.</p><table><thead><tr><th>scene</th><th>{}</th>{}</tr></thead><tbody>",
      escape(method_note(input)), escape(limit_note(input)), compare ? "peak base → head" : "peak",
      compare ? "<th>change</th><th>memory</th>" : "");
  for (const MemoryRow& r : rows) {
    out += fmt::format("<tr><td>{}</td><td class=\"num\">{}</td>", escape(r.scene), escape(r.peak));
    if (compare) {
      // The same tag as the scene table's speed column, so the two read alike.
      out +=
          fmt::format("<td class=\"num\">{0}</td><td><span class=\"tag speed-{1}\">{1}</span></td>",
                      escape(r.change), escape(r.verdict));
    }
    out += "</tr>";
  }
  return out + "</tbody></table></section>";
}

namespace {

// "<td class=num>a → b</td>"
std::string pair_cell(const std::string& base, const std::string& head) {
  return fmt::format("<td class=\"num\">{} → {}</td>", html::escape(base), html::escape(head));
}

std::string function_row_html(const Explanation& e, const FunctionChange& f) {
  using html::escape;
  const auto count = [](std::uint64_t n) { return abbreviated_count(static_cast<double>(n)); };
  std::string row = fmt::format("<tr><td class=\"num\">{}</td><td class=\"num\">{}</td>",
                                escape(signed_count(e.delta_of(f))),
                                escape(signed_percent(share_of_change(e, f), 0)));
  if (e.cost == ExplainCost::estimated_cycles) {
    row += pair_cell(abbreviated_count(f.base_cycles), abbreviated_count(f.head_cycles));
  }
  row += pair_cell(count(f.base_instructions), count(f.head_instructions));
  if (e.inclusive) {
    row += pair_cell(count(f.base_inclusive_instructions), count(f.head_inclusive_instructions));
    row += fmt::format("<td class=\"num\">{}</td>",
                       escape(signed_count(f.delta_inclusive_instructions())));
  }
  // "???": the profiler knew no source file (no debug information).
  return row + fmt::format("<td><code>{}</code>{}</td></tr>", escape(f.name),
                           f.file.empty() || f.file == "???"
                               ? ""
                               : "<br><small>" + escape(f.file) + "</small>");
}

std::string function_head_html(const Explanation& e) {
  std::string head = e.cost == ExplainCost::estimated_cycles
                         ? "<th>change (cycles)</th><th>share</th><th>cycles base → head</th>"
                           "<th>instructions base → head</th>"
                         : "<th>self change (instructions)</th><th>share</th>"
                           "<th>self instructions base → head</th>";
  if (e.inclusive) head += "<th>inclusive base → head</th><th>inclusive change</th>";
  return "<thead><tr>" + head + "<th>function</th></tr></thead>";
}

}  // namespace

std::string explanation_html(const ReportInput& input) {
  using html::escape;
  std::string out;
  for (const SceneResult* scene : explained_scenes(input)) {
    const Explanation& e = *scene->explanation;
    out += fmt::format(
        "<section class=\"card explain\"><h2>Where the time went: {}</h2><p>{}</p>"
        "<table>{}<tbody>",
        escape(scene->entry.id), escape(explanation_heading(*scene, e)), function_head_html(e));
    for (const FunctionChange& f : e.functions) out += function_row_html(e, f);
    out += "</tbody></table></section>";
  }
  return out;
}

namespace {

// ["cgroup-v2"]: the same words as the document's runs.
nlohmann::json method_words(const ReportInput& input) {
  nlohmann::json words = nlohmann::json::array();
  for (const PeakMethod method : peak_methods(input.document)) {
    words.push_back(std::string(to_string(method)));
  }
  return words;
}

}  // namespace

nlohmann::json memory_json(const ReportInput& input, const SceneResult& scene) {
  const ResultsDocument& d = input.document;
  if (!is_compare(d.kind)) {
    const auto peak = median_peak_kib(scene.runs, Role::tracer);
    return peak ? nlohmann::json{{"peak_kib", *peak}, {"peak_method", method_words(input)}}
                : nlohmann::json(nullptr);
  }
  const auto judged = judge_scene_memory(scene, input.policy.for_scene(scene.entry.id));
  if (!judged) return nullptr;
  const MemorySummary& s = judged->summary;
  return {
      {"base_peak_kib", s.base_kib},        {"head_peak_kib", s.head_kib},
      {"delta_kib", s.delta_kib},           {"change", s.change},
      {"noise_kib", s.noise_kib()},         {"limit", judged->limit},
      {"peak_method", method_words(input)}, {"verdict", std::string(to_string(judged->verdict))}};
}

}  // namespace raygate::report
