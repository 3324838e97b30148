// The JUnit XML report, for the test tab of CI systems (GitLab, Jenkins, GitHub test-report
// actions): one <testsuite> for the document, a <testcase> per scene and part (speed, image),
// <failure> with the numbers for what the gate failed, <skipped> for what could not be measured,
// and the revisions, machine and policy as <properties>. pugixml writes it, so subjects and
// reasons with <, & or quotes come out as well-formed XML; characters XML 1.0 forbids (an ESC in
// a subject, which pugixml would write as "&#27;" and CI parsers reject) are made visible first.
#include <fmt/format.h>
#include <pugixml.hpp>

#include <algorithm>

#include "core/sanitize.h"
#include "report/report_model.h"
#include "report/reporters.h"

namespace raygate::report {
namespace {

struct Tally {
  std::size_t tests = 0, failures = 0, skipped = 0;
};

void add_property(pugi::xml_node properties, const std::string& name, const std::string& value) {
  pugi::xml_node property = properties.append_child("property");
  property.append_attribute("name") = name.c_str();
  property.append_attribute("value") = value.c_str();
}

void add_properties(pugi::xml_node suite, const ReportInput& input) {
  const ResultsDocument& d = input.document;
  pugi::xml_node properties = suite.append_child("properties");
  add_property(properties, "kind", std::string(to_string(d.kind)));
  add_property(properties, "suite", d.suite);
  add_property(properties, "exit_code", std::to_string(input.exit_code()));
  add_property(properties, "raygate_version", d.raygate_version);
  add_property(properties, "baseline", d.baseline.version);
  for (const RevisionRecord& revision : d.revisions) {
    const std::string role = role_name(revision.role);
    add_property(properties, "revision." + role, revision_line(d, revision.role));
    add_property(properties, "sha." + role, revision.worktree.sha);
    if (!revision.repository.empty()) add_property(properties, "repository", revision.repository);
  }
  if (d.machine.is_object()) {
    for (const auto& [key, value] : d.machine.items()) {
      add_property(properties, "machine." + key, value_text(value));
    }
  }
  if (const std::string clock = clock_line(d); !clock.empty()) {
    add_property(properties, "clock", clock);
  }
  add_property(properties, "policy", policy_line(input.policy, input.document));
}

std::string joined(const std::vector<std::string>& lines) {
  return fmt::format("{}", fmt::join(lines, "\n"));
}

// One testcase: passed (with notes in system-out), failed, or skipped. An `undecided` warning
// (INCONCLUSIVE: neither shown within the limit nor beyond it) is skipped too: a passed test in
// the CI's test tab would say it was shown fine (the sweep of 2026-11-29: +53% after 4 rounds
// was green there, its warning only in system-out).
void add_case(pugi::xml_node suite, Tally& tally, const std::string& classname,
              const std::string& name, double seconds, GateOutcome outcome,
              const std::vector<std::string>& reasons, const std::string& numbers,
              bool undecided = false) {
  pugi::xml_node testcase = suite.append_child("testcase");
  testcase.append_attribute("classname") = classname.c_str();
  testcase.append_attribute("name") = name.c_str();
  testcase.append_attribute("time") = fmt::format("{:.3f}", seconds).c_str();
  ++tally.tests;
  const std::string message = reasons.empty() ? std::string(to_string(outcome)) : reasons.front();
  if (outcome == GateOutcome::fail) {
    ++tally.failures;
    pugi::xml_node failure = testcase.append_child("failure");
    failure.append_attribute("message") = message.c_str();
    failure.append_attribute("type") = name.c_str();
    failure.text().set(joined(reasons).c_str());
  } else if (outcome == GateOutcome::unmeasured || (outcome == GateOutcome::warn && undecided)) {
    ++tally.skipped;
    testcase.append_child("skipped").append_attribute("message") = message.c_str();
  }
  std::string out = numbers;
  if (outcome == GateOutcome::warn) out += "\nwarning: " + joined(reasons);
  if (!out.empty()) testcase.append_child("system-out").text().set(out.c_str());
}

std::string speed_numbers(const ResultsDocument& d, const SceneView& view) {
  std::string text = fmt::format("speed {}; normalized ratio {}", to_string(view.gate.speed),
                                 ratio_text(d, *view.result));
  if (const std::string change = change_text(view); !change.empty()) {
    text += "; change " + change;
  }
  return text;
}

std::string image_numbers(const SceneView& view) {
  std::vector<std::string> lines;
  for (const ImageCheck& check : view.result->images) {
    std::string line = fmt::format("{} vs {}: {}", to_string(check.role),
                                   to_string(check.reference), image_verdict_text(check.verdict));
    if (const std::string detail = check_detail(check); !detail.empty()) line += ": " + detail;
    lines.push_back(line);
  }
  return joined(lines);
}

void add_scene(pugi::xml_node suite, Tally& tally, const ReportInput& input,
               const SceneView& view) {
  const ResultsDocument& d = input.document;
  const std::string classname = fmt::format("raygate.{}.{}", d.suite, view.gate.id);
  add_case(suite, tally, classname, "speed", view.result->runs.seconds_spent, view.speed_outcome,
           view.speed_reasons, speed_numbers(d, view),
           view.gate.speed == SpeedVerdict::inconclusive);
  if (view.has_images()) {
    const bool undecided =
        std::any_of(view.result->images.begin(), view.result->images.end(),
                    [](const ImageCheck& c) { return c.verdict == ImageVerdict::inconclusive; });
    add_case(suite, tally, classname, "image", 0.0, view.image_outcome, view.image_reasons,
             image_numbers(view), undecided);
  } else {
    add_case(suite, tally, classname, "image", 0.0, GateOutcome::unmeasured,
             {"no image was checked"}, "");
  }
}

void set_counts(pugi::xml_node node, const Tally& tally) {
  node.append_attribute("tests") = tally.tests;
  node.append_attribute("failures") = tally.failures;
  node.append_attribute("errors") = 0;
  node.append_attribute("skipped") = tally.skipped;
}

// The one place JUnit text is made XML 1.0 safe: every attribute and text node under `node`,
// once the document is built and before it is saved.
void make_xml_safe(pugi::xml_node node) {
  for (pugi::xml_attribute attribute : node.attributes()) {
    attribute.set_value(markup_text(attribute.value()).c_str());
  }
  if (node.type() == pugi::node_pcdata || node.type() == pugi::node_cdata) {
    node.set_value(markup_text(node.value()).c_str());
  }
  for (pugi::xml_node child : node.children()) make_xml_safe(child);
}

class JunitReporter final : public Reporter {
 public:
  void write(const ReportInput& input, std::ostream& out) const override {
    const ResultsDocument& d = input.document;
    pugi::xml_document xml;
    pugi::xml_node decl = xml.append_child(pugi::node_declaration);
    decl.append_attribute("version") = "1.0";
    decl.append_attribute("encoding") = "UTF-8";
    pugi::xml_node suites = xml.append_child("testsuites");
    suites.append_attribute("name") = "raygate";
    pugi::xml_node suite = suites.append_child("testsuite");
    suite.append_attribute("name") =
        fmt::format("raygate {} {}", to_string(d.kind), d.suite).c_str();
    if (!d.started_at.empty()) suite.append_attribute("timestamp") = d.started_at.c_str();
    add_properties(suite, input);
    Tally tally;
    double seconds = 0.0;
    for (const SceneView& view : scene_views(input)) {
      add_scene(suite, tally, input, view);
      seconds += view.result->runs.seconds_spent;
    }
    set_counts(suites, tally);
    set_counts(suite, tally);
    suite.append_attribute("time") = fmt::format("{:.3f}", seconds).c_str();
    make_xml_safe(xml);
    xml.save(out, "  ", pugi::format_default, pugi::encoding_utf8);
  }
};

}  // namespace

std::unique_ptr<Reporter> make_junit_reporter(const ReportOptions&) {
  return std::make_unique<JunitReporter>();
}

}  // namespace raygate::report
