// What every reporter says, computed once: the scenes in reading order (failures first), the
// outcome of each scene's speed and image parts, the headline, and the numbers as text. The
// formats differ in layout only; the words and numbers come from here, so a Markdown comment
// and an HTML page can never disagree.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/format.h"
#include "measure/change.h"
#include "report/reporter.h"

namespace raygate::report {

struct SceneView {
  const SceneResult* result = nullptr;
  SceneGate gate;
  GateOutcome speed_outcome = GateOutcome::pass;
  GateOutcome image_outcome = GateOutcome::pass;
  std::vector<std::string> speed_reasons;  // the gate's reasons about time or a crash
  std::vector<std::string> image_reasons;  // the gate's reasons starting "image "
  bool has_images() const { return !result->images.empty(); }
};

// Scenes ordered fail, unmeasured, warn, pass; document order within each.
std::vector<SceneView> scene_views(const ReportInput& input);

// The revision roles measured against the baseline: {tracer} or {base, head}.
std::vector<Role> ratio_roles(const ResultsDocument& document);
// The role whose image and ratio a reader cares about: head for compare, else tracer.
Role primary_role(const ResultsDocument& document);

struct Headline {
  std::string title;   // "raygate: 1 regression", "raygate: pass"
  std::string detail;  // "mount +7.9%", "4 scenes, 1 warning"
};
Headline headline(const ReportInput& input, const std::vector<SceneView>& views);
// "pass", "fail" or "could not measure", from the gate's exit code.
std::string verdict_word(int exit_code);

// The scene's worst image verdict in a reader's words ("no golden" for "missing"); `none`
// when no image was checked.
std::string image_text(const SceneGate& gate, const std::string& none);
// An image check's verdict in a reader's words: "no golden" for ImageVerdict::missing (a
// note, never a problem), the verdict's own word otherwise.
std::string image_verdict_text(ImageVerdict verdict);

// The change column's heading, the same in every format: the change is the median of per-round
// head/base, the interval the one its verdict was drawn from (measure/change.h
// deciding_interval), named in each row because UNCHANGED and REGRESSED use different levels.
inline constexpr const char* kChangeHeading = "change [deciding interval]";

// One scene's change as every format shows it, taken apart for the formats that print numbers
// (JSON, the HTML plot) and for the test that checks all formats agree.
struct ChangeCell {
  double change = 0.0;
  // The interval `verdict` was drawn from; nullopt for an exact change, or while the interval
  // is unbounded (rounds < rounds_needed).
  std::optional<Interval> interval;
  std::string interval_name;  // "99.33% CS", "95% CI", "exact"; "" while unbounded
  double interval_confidence = 0.0;
  std::size_t rounds = 0;
  std::size_t rounds_needed = 0;
  bool exact = false;
  ChangeVerdict verdict = ChangeVerdict::inconclusive;
  std::string text;  // change_text(): what the change column prints
};
// The scene's change as the gate judged it (`gate.speed` under the policy's limit
// `gate.speed_limit`); nullopt when the scene has no change (a run, or a failed scene).
std::optional<ChangeCell> change_cell(const SceneResult& scene, const SceneGate& gate);
// "+7.9% [+6.1%, +9.8%] 99.33% CS, 40 rounds" (CS: anytime-valid confidence sequence; CI: a
// one-look interval in older documents); "+0.4%, no interval yet (needs 16 rounds), 9 rounds";
// "+0.912% exact (simulated cycles)" when counted (--timing sim); "" without a change.
std::string change_text(const SceneView& view);
// "process CPU seconds (auto: one thread), baseline process CPU": how the runs were timed, from
// the document's settings; "" when it does not say.
std::string clock_line(const ResultsDocument& document);
// A run's median cost in the document's unit (settings.unit): "0.512 s", or "1.76e+09 cycles"
// when simulated.
std::string cost_text(const ResultsDocument& document, double value);

// The data columns of the scenes table, in order, between the scene's name and its outcome:
// console, Markdown and HTML all lay out these (a new column is one entry here and one case in
// cell_text; HTML may style a kind, as it does speed and image).
enum class ColumnKind { ratio, change, speed, image };
struct TableColumn {
  ColumnKind kind;
  std::string heading;
};
std::vector<TableColumn> table_columns(const ResultsDocument& document);
// What the table's numbers are, said once under the heading: "ratio = time(tracer) /
// time(baseline), median over rounds; head's = base's x (1 + change); change = median of
// per-round head/base, [the interval its verdict was drawn from]".
std::string columns_line(const ResultsDocument& document);
// A cell's text; `arrow` joins base and head ratios, `none` stands for no image checked.
std::string cell_text(ColumnKind kind, const ResultsDocument& document, const SceneView& view,
                      const std::string& arrow = "->", const std::string& none = "-");

// A run: "0.512 [0.507, 0.518]"; a compare: "0.512 -> 0.553" (arrow as given).
std::string ratio_text(const ResultsDocument& document, const SceneResult& scene,
                       const std::string& arrow = "->");
// Geometric-mean change of the suite, head against base; nullopt for a run.
std::optional<double> suite_change(const ResultsDocument& document);

// A JSON value as text: strings bare, anything else as compact JSON.
std::string value_text(const nlohmann::json& value);
// "Intel Xeon (2 cores), Linux 6.1.0 x86_64, host ci-runner-3": whatever the machine JSON has.
std::string machine_line(const nlohmann::json& machine);
// "abc1234 Fix the BVH split (main)"; "" for a role not in the document. The subject and the
// revision each show their first line, at most 200 bytes ("…" where cut).
std::string revision_line(const ResultsDocument& document, Role role);
// "max slowdown +3.0% (...); images fail when more than 0.02% of pixels differ by over 0.004 in
// a channel and warn when fewer do". A document without a change (`run`) is judged on its images only: its line leaves
// the slowdown limit out. A compare's adds why each confidence sequence has its level (the
// significance; each scene's share of the false alarms, and Holm's larger shares).
std::string policy_line(const GatePolicy& policy, const ResultsDocument& document);

// The image of `role` per the document's image checks, or its first successful run.
std::filesystem::path role_image(const SceneResult& scene, Role role);
// The golden image the checks compared with, or "".
std::filesystem::path golden_image(const SceneResult& scene);
std::filesystem::path resolve(const ReportInput& input, const std::filesystem::path& path);

}  // namespace raygate::report
