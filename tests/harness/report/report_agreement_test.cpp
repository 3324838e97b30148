// Every report format of one compare document says the same thing about each scene (issue 26):
// the change, the interval its verdict was drawn from, that interval's name and the verdict are
// read back out of the console table, the Markdown table, the HTML overview and change plot, the
// JUnit speed case and the JSON report, and must equal each other and the document. The
// documents hold real confidence sequences (measure/change.h summarize_change over seeded
// rounds): a regression, an unchanged scene (decided by the wider equivalence sequence), a scene
// still below the rounds its sequence needs, and a counted (--timing sim) change.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <pugixml.hpp>

#include <cmath>
#include <optional>
#include <random>
#include <regex>
#include <sstream>

#include "gate/policy.h"
#include "gate/verdict.h"
#include "measure/change.h"
#include "measure/confidence_sequence.h"
#include "report/reporter.h"

namespace raygate {
namespace {

struct Expected {
  std::string id;
  double change = 0.0;
  std::optional<Interval> interval;  // nullopt: exact, or not yet bounded
  std::string name;                  // "99.8% CS"; "exact"; "" while unbounded
  std::size_t needed = 0;            // rounds the sequence needs, while unbounded
  std::string verdict;
};

// What a format printed about one scene's change, read back from its text.
struct Printed {
  double change_percent = 0.0;
  std::optional<std::pair<double, double>> interval_percent;
  std::string name;
  std::size_t needed = 0;
  std::string verdict;
};

std::vector<CompareRound> rounds(std::size_t n, double change, double noise, unsigned seed) {
  std::mt19937 random(seed);
  std::normal_distribution<double> wobble(0.0, noise);
  std::vector<CompareRound> out;
  for (std::size_t i = 0; i < n; ++i) {
    const double base = 0.2 * std::exp(wobble(random));
    CompareRound round{std::nullopt, base, base * (1.0 + change) * std::exp(wobble(random))};
    if (i < 3) round.baseline_seconds = 0.4 * std::exp(wobble(random));
    out.push_back(round);
  }
  return out;
}

SceneResult scene(const std::string& id, const ChangeSummary& change) {
  SceneResult s;
  s.entry = {id, id, 1, 64, 64};
  s.status = SceneStatus::measured;
  s.runs.stop_reason = "decided";
  s.change = change;
  s.ratios[Role::base] = change.base;
  s.ratios[Role::head] = change.head;
  s.change_verdict = classify_change(change);
  return s;
}

RevisionRecord revision(Role role, char digit) {
  RevisionRecord r;
  r.role = role;
  r.worktree.sha = std::string(40, digit);
  r.worktree.short_sha = std::string(7, digit);
  r.worktree.subject = role_name(role) + " commit";
  r.adapter_name = "cmake-nff";
  return r;
}

ResultsDocument compare_document(bool simulated) {
  ResultsDocument d;
  d.kind = DocumentKind::compare;
  d.suite = "ci";
  d.revisions = {revision(Role::base, 'a'), revision(Role::head, 'b')};
  if (simulated) {
    d.settings.timing_source = TimingSource::simulated;
    d.settings.tracer_clock = "simulated-cycles";
    ChangeSummary counted = summarize_change(rounds(2, 0.00912, 0.0, 1));
    counted.exact = true;
    d.scenes.push_back(scene("counted", counted));
    return d;
  }
  const SequenceLevels levels{0.01 / 3, 0.05, 0.95};
  d.settings = {};
  d.settings.tracer_clock = "process-cpu";
  d.settings.baseline_clock = "process-cpu";
  d.scenes.push_back(scene("slow", summarize_change(rounds(60, 0.08, 0.01, 2), {}, levels)));
  d.scenes.push_back(scene("same", summarize_change(rounds(80, 0.0, 0.004, 3), {}, levels)));
  d.scenes.push_back(scene("early", summarize_change(rounds(5, 0.01, 0.01, 4), {}, levels)));
  return d;
}

// From the document alone: which interval each verdict is drawn from (docs/statistics.md §6:
// UNCHANGED on the equivalence sequence, REGRESSED and IMPROVED on the decision sequence, and
// INCONCLUSIVE on the one that would decide it at the default +3% limit: the equivalence
// sequence inside the limit) and its name.
Expected expected_of(const SceneResult& s) {
  const ChangeSummary& c = *s.change;
  Expected e{s.entry.id, c.change, std::nullopt, "", 0, std::string(to_string(s.change_verdict))};
  if (c.exact) {
    e.name = "exact";
    return e;
  }
  const bool unchanged = s.change_verdict == ChangeVerdict::unchanged ||
                         (s.change_verdict == ChangeVerdict::inconclusive &&
                          std::abs(c.change) < GatePolicy{}.defaults.max_slowdown);
  const double confidence = unchanged ? c.equivalence_confidence : c.confidence;
  const Interval interval = unchanged ? c.equivalence_interval : c.change_interval;
  const std::size_t needed = min_values_for_median_sequence((1.0 - confidence) / 2.0);
  if (c.rounds < needed) {
    e.needed = needed;
    return e;
  }
  e.interval = interval;
  e.name = fmt::format("{:.4g}% CS", 100.0 * confidence);
  return e;
}

const std::regex kVerdict("\\b(REGRESSED|IMPROVED|UNCHANGED|INCONCLUSIVE)\\b");
const std::regex kBounded(
    R"(([+-]\d+\.\d+)% \[([+-]\d+\.\d+)%, ([+-]\d+\.\d+)%\] (\d+(?:\.\d+)?% C[SI]))");
const std::regex kUnbounded(R"(([+-]\d+\.\d+)%, no interval yet \(needs (\d+) rounds\))");
const std::regex kExact(R"(([+-]\d+\.\d+)% exact \(simulated cycles\))");

// The change and verdict in one piece of text (a table row, a JUnit case).
Printed read_text(const std::string& text) {
  Printed p;
  std::smatch m;
  if (std::regex_search(text, m, kBounded)) {
    p.change_percent = std::stod(m[1]);
    p.interval_percent = {std::stod(m[2]), std::stod(m[3])};
    p.name = m[4];
  } else if (std::regex_search(text, m, kUnbounded)) {
    p.change_percent = std::stod(m[1]);
    p.needed = std::stoul(m[2]);
  } else if (std::regex_search(text, m, kExact)) {
    p.change_percent = std::stod(m[1]);
    p.name = "exact";
  } else {
    ADD_FAILURE() << "no change in: " << text;
  }
  if (std::regex_search(text, m, kVerdict)) p.verdict = m[1];
  return p;
}

std::string render(const ReportInput& input, ReportFormat format) {
  std::ostringstream out;
  make_reporter(format)->write(input, out);
  return out.str();
}

// The line of `text` that starts with `prefix`.
std::string line_starting(const std::string& text, const std::string& prefix) {
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(prefix, 0) == 0) return line;
  }
  ADD_FAILURE() << "no line starting '" << prefix << "' in:\n" << text;
  return "";
}

std::string between(const std::string& text, const std::string& from, const std::string& to) {
  const std::size_t start = text.find(from);
  if (start == std::string::npos) {
    ADD_FAILURE() << "no '" << from << "'";
    return "";
  }
  return text.substr(start, text.find(to, start) - start);
}

// The text a browser shows, spaces collapsed; the plot's tooltip (<title>) is dropped so what
// is read is what is drawn.
std::string without_tags(const std::string& html) {
  std::string text = std::regex_replace(html, std::regex("<title>[^<]*</title>"), " ");
  text = std::regex_replace(text, std::regex("<[^>]*>"), " ");
  return std::regex_replace(text, std::regex("\\s+"), " ");
}

Printed from_json(const nlohmann::json& report, const std::string& id) {
  for (const nlohmann::json& s : report.at("scenes")) {
    if (s.at("id") != id) continue;
    const nlohmann::json& c = s.at("change");
    Printed p;
    p.change_percent = 100.0 * c.at("change").get<double>();
    if (!c.at("interval").is_null()) {
      p.interval_percent = {100.0 * c.at("interval").at("lower").get<double>(),
                            100.0 * c.at("interval").at("upper").get<double>()};
    }
    p.name = c.at("interval_name");
    p.needed = c.at("interval").is_null() && !c.at("exact").get<bool>()
                   ? c.at("rounds_needed").get<std::size_t>()
                   : 0;
    p.verdict = s.at("speed");
    EXPECT_EQ(c.at("verdict"), p.verdict) << id;
    return p;
  }
  ADD_FAILURE() << "no scene " << id << " in the JSON report";
  return {};
}

void expect_same(const Expected& e, const Printed& p, const std::string& where) {
  SCOPED_TRACE(where + ", scene " + e.id);
  const double tolerance = e.name == "exact" ? 0.0005 : 0.05 + 1e-9;  // as printed
  EXPECT_NEAR(p.change_percent, 100.0 * e.change, tolerance);
  EXPECT_EQ(p.verdict, e.verdict);
  EXPECT_EQ(p.name, e.name);
  EXPECT_EQ(p.needed, e.needed);
  ASSERT_EQ(p.interval_percent.has_value(), e.interval.has_value());
  if (e.interval) {
    EXPECT_NEAR(p.interval_percent->first, 100.0 * e.interval->lower, tolerance);
    EXPECT_NEAR(p.interval_percent->second, 100.0 * e.interval->upper, tolerance);
  }
}

void check_every_format(const ResultsDocument& document) {
  const GatePolicy policy;
  const GateResult gate = evaluate_gate(document, policy);
  const ReportInput input{document, gate, policy, {}, {}, {}, 0};
  const std::string console = render(input, ReportFormat::console);
  const std::string markdown = render(input, ReportFormat::markdown);
  const std::string html = render(input, ReportFormat::html);
  const nlohmann::json json = nlohmann::json::parse(render(input, ReportFormat::json));
  pugi::xml_document junit;
  ASSERT_TRUE(junit.load_string(render(input, ReportFormat::junit).c_str()));

  for (const SceneResult& scene : document.scenes) {
    const Expected e = expected_of(scene);
    const std::string id = scene.entry.id;
    expect_same(e, read_text(line_starting(console, id + " ")), "console");
    expect_same(e, read_text(between(markdown, "| " + id + " |", "\n")), "markdown");
    const std::string row = between(html, "<a href=\"#scene-" + id + "\">", "</tr>");
    expect_same(e, read_text(without_tags(row)), "html overview");
    // The scene's change plot: the number and the interval under it, verdict from its tag.
    const std::string plot = without_tags(
        between(html.substr(html.find("id=\"scene-" + id + "\"")), "change-plot", "</svg>"));
    if (e.interval) {
      expect_same(e, read_text(fmt::format("{} {}", plot, e.verdict)), "html change plot");
    }
    const std::string speed_out =
        junit
            .select_node(
                fmt::format("//testcase[@classname='raygate.ci.{}'][@name='speed']", id).c_str())
            .node()
            .child("system-out")
            .text()
            .as_string();
    expect_same(e, read_text(speed_out), "junit");
    expect_same(e, from_json(json, id), "json");
  }
}

TEST(ReportAgreement, EveryFormatPrintsTheSameChangeIntervalNameAndVerdict) {
  const ResultsDocument document = compare_document(false);
  // The three kinds of row this test is about really are there.
  ASSERT_EQ(document.scenes[0].change_verdict, ChangeVerdict::regressed);
  ASSERT_EQ(document.scenes[1].change_verdict, ChangeVerdict::unchanged);
  ASSERT_EQ(document.scenes[2].change_verdict, ChangeVerdict::inconclusive);
  ASSERT_NE(document.scenes[1].change->equivalence_confidence,
            document.scenes[1].change->confidence);
  check_every_format(document);
}

TEST(ReportAgreement, ACountedChangeIsExactEverywhereWithoutATestOrSeconds) {
  const ResultsDocument document = compare_document(true);
  check_every_format(document);
  const GatePolicy policy;
  const GateResult gate = evaluate_gate(document, policy);
  const ReportInput input{document, gate, policy, {}, {}, {}, 0};
  const std::string html = render(input, ReportFormat::html);
  EXPECT_EQ(html.find("Mann–Whitney"), std::string::npos);  // no p beside an exact change
  EXPECT_NE(html.find(" cycles"), std::string::npos);
  EXPECT_EQ(html.find("0.200 s"), std::string::npos);
}

// Head's ratio is base's times the change, so the ratio columns never move against the change.
TEST(ReportAgreement, RatioColumnsMoveWithTheChange) {
  const ResultsDocument document = compare_document(false);
  const GatePolicy policy;
  const GateResult gate = evaluate_gate(document, policy);
  const std::string console =
      render({document, gate, policy, {}, {}, {}, 0}, ReportFormat::console);
  const std::regex ratios(R"((\d+\.\d+) -> (\d+\.\d+))");
  for (const SceneResult& scene : document.scenes) {
    const std::string line = line_starting(console, scene.entry.id + " ");
    std::smatch m;
    ASSERT_TRUE(std::regex_search(line, m, ratios)) << line;
    const double moved = std::stod(m[2]) / std::stod(m[1]) - 1.0;
    const double change = scene.change->change;
    if (std::abs(moved) > 0.01 || std::abs(change) > 0.01) {
      EXPECT_GT(moved * change, 0.0) << line;
    }
  }
}

}  // namespace
}  // namespace raygate
