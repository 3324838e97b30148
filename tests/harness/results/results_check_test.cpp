// A results document read from disk is untrusted input (issue 25, class 7): a document with an
// unknown kind, status or verdict, a scene listed twice, a number out of range or not finite, or
// a field of the wrong type is a usage error naming the file and the JSON path of the first
// problem, whichever reader takes it (they all go through results_from_json). Table-driven: each
// row breaks one field of a valid run or compare document.
#include <gtest/gtest.h>

#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/fs.h"
#include "results/results.h"
#include "results_fixture.h"

namespace raygate {
namespace {

using nlohmann::json;

json run_document() {
  test::DocumentSpec spec;
  spec.sha = test::fake_sha(1);
  spec.scenes = {{"balls", 1.5}, {"gears", 2.0}};
  return to_json(test::make_document(spec));
}

json compare_document() {
  test::DocumentSpec spec;
  spec.sha = test::fake_sha(2);
  spec.kind = DocumentKind::compare;
  spec.roles = {Role::base, Role::head};
  spec.with_change = true;
  spec.scenes = {{"balls", 1.5}, {"gears", 2.0}};
  return to_json(test::make_document(spec));
}

struct BadDocument {
  const char* name;
  bool compare;  // break a compare document, else a run document
  std::function<void(json&)> mutate;
  const char* path;     // the JSON path the message must name
  const char* problem;  // and a part of what it says
};

const double kNaN = std::numeric_limits<double>::quiet_NaN();

// One shard record of settings.merged_shards (results/measurement_settings.h MergedShard).
json merged_shard(json machine) {
  return {{"index", 1},
          {"count", 2},
          {"document", "shard-1.json"},
          {"raygate_version", "0.1.0"},
          {"started_at", "2026-11-28T10:00:00Z"},
          {"finished_at", "2026-11-28T10:05:00Z"},
          {"complete", true},
          {"scenes", {"balls"}},
          {"machine", std::move(machine)}};
}

const std::vector<BadDocument>& bad_documents() {
  static const std::vector<BadDocument> rows = {
      {"unknown kind", false, [](json& j) { j["kind"] = "weird"; }, "$.kind",
       "unknown value \"weird\""},
      {"kind of the wrong type", false, [](json& j) { j["kind"] = 3; }, "$.kind",
       "expected a string, found number 3"},
      {"unknown scene status", false, [](json& j) { j["scenes"][1]["status"] = "exploded"; },
       "$.scenes[1].status", "unknown value \"exploded\""},
      // The sweep of 2026-11-29: a failed scene without its failure passed the gate.
      {"a failed scene with no failure", false,
       [](json& j) { j["scenes"][0]["status"] = "failed"; }, "$.scenes[0].status",
       "\"failed\" with no failure (null)"},
      // ... and a change of -100% inside [+29%, +36%] turned a regression into a warning.
      {"a change outside its interval", true,
       [](json& j) {
         j["scenes"][0]["change"]["change"] = -1.0;
         j["scenes"][0]["change"]["change_interval"] = {{"lower", 0.29}, {"upper", 0.36}};
       },
       "$.scenes[0].change.change", "lies outside its change_interval"},
      {"unknown stop reason", false, [](json& j) { j["scenes"][0]["stop_reason"] = "bored"; },
       "$.scenes[0].stop_reason",
       "unknown value \"bored\" (one of: stop_converged, stop_budget_rounds, stop_budget_time, "
       "failed, continue, \"\")"},
      {"a scene listed twice", false, [](json& j) { j["scenes"].push_back(j["scenes"][0]); },
       "$.scenes[2].scene.id", "scene \"balls\" is listed twice"},
      {"unknown change verdict", true,
       [](json& j) { j["scenes"][0]["change"]["verdict"] = "FASTER"; },
       "$.scenes[0].change.verdict", "unknown value \"FASTER\""},
      {"unknown interval kind", true,
       [](json& j) { j["scenes"][1]["change"]["interval_kind"] = "bootstrap"; },
       "$.scenes[1].change.interval_kind", "unknown value \"bootstrap\""},
      {"unknown image verdict", false,
       [](json& j) { j["scenes"][1]["images"][0]["verdict"] = "failed"; },
       "$.scenes[1].images[0].verdict", "unknown value \"failed\""},
      {"an unknown revision role", false, [](json& j) { j["revisions"][0]["role"] = "mallory"; },
       "$.revisions[0].role", "unknown value \"mallory\""},
      {"a role listed twice", true, [](json& j) { j["revisions"][1]["role"] = "base"; },
       "$.revisions[1].role", "role \"base\" is listed twice"},
      {"a ratio of an unknown role", false,
       [](json& j) { j["scenes"][0]["ratios"]["mallory"] = j["scenes"][0]["ratios"]["tracer"]; },
       "$.scenes[0].ratios.mallory", "unknown role"},
      {"a run of an unknown role", false,
       [](json& j) { j["scenes"][0]["rounds"][0]["order"][0] = "ghost"; },
       "$.scenes[0].rounds[0].order[0]", "unknown role \"ghost\""},
      {"a negative ratio", false,
       [](json& j) { j["scenes"][0]["ratios"]["tracer"]["normalized_ratio"] = -2.0; },
       "$.scenes[0].ratios.tracer.normalized_ratio", "out of range"},
      {"an interval upside down", false,
       [](json& j) {
         j["scenes"][0]["ratios"]["tracer"]["ratio_interval"] = {{"lower", 3.0}, {"upper", 1.0}};
       },
       "$.scenes[0].ratios.tracer.ratio_interval", "lower is above upper"},
      // The fourth sweep: a ratio of 0 printed "+-inf%" in history; one outside its own
      // interval was stored as it read; a run that finished before it began was merged.
      {"a ratio of 0", false,
       [](json& j) { j["scenes"][0]["ratios"]["tracer"]["normalized_ratio"] = 0.0; },
       "$.scenes[0].ratios.tracer.normalized_ratio", "is 0"},
      // Sweep 17: 1e308 was imported, and every later history called the store damaged.
      {"a ratio past what the store reads back", false,
       [](json& j) {
         j["scenes"][0]["ratios"]["tracer"]["normalized_ratio"] = 1e308;
         j["scenes"][0]["ratios"]["tracer"]["ratio_interval"] = {{"lower", 1.0}, {"upper", 1e308}};
       },
       "$.scenes[0].ratios.tracer.normalized_ratio", "out of range (from 0 to 1e+18)"},
      {"a ratio outside its interval", false,
       [](json& j) {
         j["scenes"][0]["ratios"]["tracer"]["ratio_interval"] = {{"lower", 3.0}, {"upper", 4.0}};
       },
       "$.scenes[0].ratios.tracer.normalized_ratio", "outside its ratio_interval [3, 4]"},
      {"finished before it started", false,
       [](json& j) {
         j["started_at"] = "2026-11-28T10:00:00+01:00";
         j["finished_at"] = "2026-11-28T08:59:59Z";
       },
       "$.finished_at", "is before started_at"},
      {"a shard that is none", false, [](json& j) { j["shard"] = "5/2"; }, "$.shard",
       "\"5/2\" is not a shard K/N"},
      // The fifth sweep: a confidence of 0 (or 1) ended in an internal error.
      {"a confidence of 0", true, [](json& j) { j["scenes"][0]["change"]["confidence"] = 0.0; },
       "$.scenes[0].change.confidence", "0.0 is not a confidence level"},
      {"a one-look confidence of 1", true,
       [](json& j) {
         j["scenes"][0]["change"]["interval_kind"] = "confidence-sequence";
         j["scenes"][0]["change"]["one_look_confidence"] = 1.0;
       },
       "$.scenes[0].change.one_look_confidence", "1.0 is not a confidence level"},
      {"a p-value above 1", true,
       [](json& j) { j["scenes"][0]["change"]["mann_whitney"]["p_value"] = 1.5; },
       "$.scenes[0].change.mann_whitney.p_value", "out of range"},
      {"a confidence above 1", true, [](json& j) { j["scenes"][0]["change"]["confidence"] = 95; },
       "$.scenes[0].change.confidence", "out of range"},
      {"a change below -100%", true, [](json& j) { j["scenes"][0]["change"]["change"] = -3.0; },
       "$.scenes[0].change.change", "out of range"},
      {"negative run seconds", false,
       [](json& j) { j["scenes"][0]["rounds"][0]["runs"]["tracer"]["seconds"] = -1.0; },
       "$.scenes[0].rounds[0].runs.tracer.seconds", "out of range"},
      {"wall seconds of a century", false,
       [](json& j) { j["scenes"][0]["rounds"][0]["runs"]["baseline"]["wall_seconds"] = 3.2e9; },
       "$.scenes[0].rounds[0].runs.baseline.wall_seconds", "out of range"},
      {"a measure past any count of cycles", false,
       [](json& j) { j["scenes"][0]["rounds"][0]["runs"]["baseline"]["seconds"] = 1e30; },
       "$.scenes[0].rounds[0].runs.baseline.seconds", "out of range"},
      {"run seconds not a number", false,
       [](json& j) { j["scenes"][0]["rounds"][0]["runs"]["tracer"]["seconds"] = "fast"; },
       "$.scenes[0].rounds[0].runs.tracer.seconds", "expected a number, found string \"fast\""},
      {"run seconds null (a NaN written)", false,
       [](json& j) { j["scenes"][0]["rounds"][0]["runs"]["tracer"]["seconds"] = nullptr; },
       "$.scenes[0].rounds[0].runs.tracer.seconds", "expected a number, found null"},
      {"a NaN in memory", false,
       [](json& j) { j["scenes"][0]["rounds"][0]["runs"]["tracer"]["seconds"] = kNaN; },
       "$.scenes[0].rounds[0].runs.tracer.seconds", "expected a finite number"},
      {"rounds as a fraction", false,
       [](json& j) { j["scenes"][0]["ratios"]["tracer"]["rounds"] = 2.5; },
       "$.scenes[0].ratios.tracer.rounds", "expected a whole number, found number 2.5"},
      {"rounds negative", false, [](json& j) { j["scenes"][0]["ratios"]["tracer"]["rounds"] = -4; },
       "$.scenes[0].ratios.tracer.rounds", "out of range"},
      {"a huge memory", false,
       [](json& j) {
         j["scenes"][0]["rounds"][0]["runs"]["tracer"]["max_rss_kib"] = 18446744073709551615ull;
       },
       "$.scenes[0].rounds[0].runs.tracer.max_rss_kib", "out of range"},
      {"a zero-sized image", false, [](json& j) { j["scenes"][0]["scene"]["width"] = 0; },
       "$.scenes[0].scene.width", "out of range"},
      // Read into an int: 10^12 once came out as -727379968 in scaling's message.
      {"a size too large for an int", false,
       [](json& j) { j["scenes"][0]["scene"]["size"] = 1000000000000; }, "$.scenes[0].scene.size",
       "out of range"},
      {"percent over 100", false,
       [](json& j) { j["scenes"][0]["images"][0]["metrics"]["percent_over_fail"] = 250.0; },
       "$.scenes[0].images[0].metrics.percent_over_fail", "out of range"},
      {"max pixel too short", false,
       [](json& j) {
         j["scenes"][0]["images"][0]["metrics"]["max_pixel"] = {1, 2};
       },
       "$.scenes[0].images[0].metrics.max_pixel", "expected [x, y, channel]"},
      {"a negative score", false, [](json& j) { j["scores"]["tracer"]["score"] = -1.0; },
       "$.scores.tracer.score", "out of range"},
      {"scenes not an array", false, [](json& j) { j["scenes"] = json::object(); }, "$.scenes",
       "expected an array, found an object"},
      {"a scene not an object", false, [](json& j) { j["scenes"][1] = 7; }, "$.scenes[1]",
       "expected an object, found number 7"},
      {"complete as a word", false, [](json& j) { j["complete"] = "yes"; }, "$.complete",
       "expected true or false, found string \"yes\""},
      {"a missing field deep down", false,
       [](json& j) { j["scenes"][1]["rounds"][0]["runs"]["tracer"].erase("wall_seconds"); },
       "$.scenes[1].rounds[0].runs.tracer", "missing required key 'wall_seconds'"},
      {"a missing top field", false, [](json& j) { j.erase("revisions"); }, "$",
       "missing required key 'revisions'"},
      {"unknown baseline timing", false, [](json& j) { j["baseline"]["timing"] = "sundial"; },
       "$.baseline.timing", "unknown value \"sundial\""},
      // The timing words and counters come from the timing modes' registry
      // (runner/timing/timing_check.h): every one a mode writes is read, no other.
      {"unknown tracer clock", false, [](json& j) { j["settings"]["tracer_clock"] = "sundial"; },
       "$.settings.tracer_clock", "unknown value \"sundial\" (one of: process-wall"},
      {"unknown unit", true, [](json& j) { j["settings"]["unit"] = "furlongs"; }, "$.settings.unit",
       "unknown value \"furlongs\" (one of: seconds"},
      {"unknown counter", false,
       [](json& j) {
         json run = j["scenes"][1]["rounds"][0]["runs"]["baseline"];
         run["counters"]["joules"] = {{"value", 1.0}, {"unit", "joules"}};
         j["scenes"][1]["warmup"]["baseline"] = json::array({run});
       },
       "$.scenes[1].warmup.baseline[0].counters.joules",
       "unknown counter \"joules\" (known: startup_seconds)"},
      {"a counter in another unit", true,
       [](json& j) {
         j["scenes"][0]["rounds"][0]["runs"]["head"]["counters"]["startup_seconds"] = {
             {"value", 1.0}, {"unit", "ms"}};
       },
       "$.scenes[0].rounds[0].runs.head.counters.startup_seconds.unit",
       "\"ms\" is not the unit of startup_seconds (\"seconds\")"},
      {"a counter below zero", false,
       [](json& j) {
         j["scenes"][0]["rounds"][0]["runs"]["tracer"]["counters"]["startup_seconds"] = {
             {"value", -0.5}, {"unit", "seconds"}};
       },
       "$.scenes[0].rounds[0].runs.tracer.counters.startup_seconds.value", "out of range"},
      {"unknown build record version", false,
       [](json& j) { j["revisions"][0]["build"]["record_version"] = 9; },
       "$.revisions[0].build.record_version", "out of range"},
      {"build step argv not strings", false,
       [](json& j) {
         j["revisions"][0]["build"]["steps"] = json::array({{{"argv", {"make", 1}},
                                                             {"outcome", "ok"},
                                                             {"succeeded", true},
                                                             {"wall_seconds", 1.0},
                                                             {"cpu_seconds", 1.0},
                                                             {"log", "l"}}});
       },
       "$.revisions[0].build.steps[0].argv[1]", "expected a string, found number 1"},
      {"schema version zero", false, [](json& j) { j["schema_version"] = 0; }, "$.schema_version",
       "expected 1 or more"},
      {"a key that is not a word", false,
       [](json& j) { j["scores"]["tr acer"] = j["scores"]["tracer"]; }, "$.scores[\"tr acer\"]",
       "unknown role"},
      {"cachegrind counter negative", false,
       [](json& j) {
         json counters;
         for (const char* key :
              {"Ir", "I1mr", "ILmr", "Dr", "D1mr", "DLmr", "Dw", "D1mw", "DLmw"}) {
           counters[key] = 1;
         }
         counters["Dw"] = -5;
         j["scenes"][0]["rounds"][0]["runs"]["tracer"]["cachegrind"] = counters;
       },
       "$.scenes[0].rounds[0].runs.tracer.cachegrind.Dw", "must not be negative"},
      // The machine the reports, the drift rule and consistency read (issue 40).
      {"machine of the wrong type", false, [](json& j) { j["machine"] = 5; }, "$.machine",
       "expected an object, found number 5"},
      {"machine hostname a number", false, [](json& j) { j["machine"]["hostname"] = 7; },
       "$.machine.hostname", "expected a string, found number 7"},
      {"machine load of two minutes", false,
       [](json& j) {
         j["machine"]["load_average"] = {1.0, 2.0};
       },
       "$.machine.load_average", "expected [1, 5, 15] minutes' load"},
      {"machine cores negative", false, [](json& j) { j["machine"]["online_cpus"] = -2; },
       "$.machine.online_cpus", "out of range"},
      // A merged document's shards' machines, read as the document's own is.
      {"merged shard's machine of the wrong type", false,
       [](json& j) { j["settings"]["merged_shards"] = json::array({merged_shard(5)}); },
       "$.settings.merged_shards[0].machine", "expected an object, found number 5"},
      {"merged shard's machine hostname a number", false,
       [](json& j) {
         j["settings"]["merged_shards"] = json::array({merged_shard({{"hostname", 7}})});
       },
       "$.settings.merged_shards[0].machine.hostname", "expected a string, found number 7"},
      // The settings a gate and a report trust: in range, and a number where one is required
      // (null is how a NaN was written).
      {"negative time budget", false, [](json& j) { j["settings"]["max_minutes"] = -5; },
       "$.settings.max_minutes", "-5 is out of range (from 0 to 1000000)"},
      {"time budget written null", false, [](json& j) { j["settings"]["max_minutes"] = nullptr; },
       "$.settings.max_minutes", "expected a number, found null"},
      {"target above one", true, [](json& j) { j["settings"]["target_relative_half_width"] = 2.5; },
       "$.settings.target_relative_half_width", "out of range"},
      {"significance NaN", true, [](json& j) { j["settings"]["significance"] = kNaN; },
       "$.settings.significance", "out of range"},
      {"max slowdown negative", true, [](json& j) { j["settings"]["max_slowdown"] = -0.1; },
       "$.settings.max_slowdown", "out of range"},
      // Settings under which nothing could fail (a policy file refuses them too).
      {"significance zero", true, [](json& j) { j["settings"]["significance"] = 0; },
       "$.settings.significance", "out of range"},
      {"image tolerance negative", false, [](json& j) { j["settings"]["image_tolerance"] = -1; },
       "$.settings.image_tolerance", "out of range"},
      // Names that become folders (golden/<adapter>/, runs/<scene>/) must not climb out.
      {"adapter name climbing out", false,
       [](json& j) { j["revisions"][0]["adapter"]["name"] = "../../../tmp/x"; },
       "$.revisions[0].adapter.name", "\"../../../tmp/x\" may hold only letters"},
      {"scene id climbing out", false, [](json& j) { j["scenes"][0]["scene"]["id"] = "../../x"; },
       "$.scenes[0].scene.id", "\"../../x\" may hold only letters"},
      // A run relabelled as a compare has no change to judge; a compare without head is half.
      {"a run called a compare", false, [](json& j) { j["kind"] = "compare"; },
       "$.revisions[0].role", "unknown value \"tracer\""},
      {"no revisions", false, [](json& j) { j["revisions"] = json::array(); }, "$.revisions",
       "a run document records 1 revision (the tracer), found 0"},
      // Null is how a ratio of no rounds is written; one with rounds would print as 0.000.
      {"a measured ratio written null", false,
       [](json& j) { j["scenes"][0]["ratios"]["tracer"]["normalized_ratio"] = nullptr; },
       "$.scenes[0].ratios.tracer.normalized_ratio", "is null, but"},
      {"a score written null", false, [](json& j) { j["scores"]["tracer"]["score"] = nullptr; },
       "$.scores.tracer.score", "is null, but it scores"},
  };
  return rows;
}

TEST(ResultsCheck, ValidRunAndCompareDocumentsAreRead) {
  EXPECT_EQ(results_from_json(run_document(), "run.json").scenes.size(), 2u);
  // --timing sim: a run's seconds hold estimated cycles, billions of them.
  json sim = run_document();
  sim["scenes"][0]["rounds"][0]["runs"]["tracer"]["seconds"] = 4.2e10;
  sim["scenes"][0]["ratios"]["tracer"]["tracer_median_seconds"] = 4.2e10;
  EXPECT_EQ(results_from_json(sim, "sim.json").scenes.size(), 2u);
  // Every registered mode's clock names are read (issue 40: `--timing user` documents were
  // refused), and documents from before the clocks were matched ("in-process-cpu").
  for (const char* clock : {"process-user", "process-cpu", "reported", "simulated-cycles"}) {
    json timed = run_document();
    timed["settings"]["tracer_clock"] = clock;
    timed["baseline"]["timing"] = clock == std::string("reported") ? "in-process" : clock;
    EXPECT_NO_THROW(results_from_json(timed, "timed.json")) << clock;
  }
  json older = run_document();
  older["baseline"]["timing"] = "in-process-cpu";
  EXPECT_NO_THROW(results_from_json(older, "older.json"));
  json merged = run_document();
  merged["settings"]["merged_shards"] = json::array({merged_shard({{"hostname", "ci-1"}})});
  EXPECT_NO_THROW(results_from_json(merged, "merged.json"));
  const ResultsDocument compare = results_from_json(compare_document(), "compare.json");
  ASSERT_TRUE(compare.scenes[0].change.has_value());
  EXPECT_EQ(compare.scenes[0].change_verdict, ChangeVerdict::unchanged);
}

TEST(ResultsCheck, EveryBadDocumentIsAUsageErrorNamingTheFileAndPath) {
  for (const BadDocument& row : bad_documents()) {
    json j = row.compare ? compare_document() : run_document();
    row.mutate(j);
    try {
      results_from_json(j, "forged.json");
      ADD_FAILURE() << row.name << ": read without an error";
    } catch (const UsageError& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.rfind("forged.json: ", 0), 0u) << row.name << ": " << message;
      EXPECT_NE(message.find(std::string(row.path) + ": "), std::string::npos)
          << row.name << ": " << message;
      EXPECT_NE(message.find(row.problem), std::string::npos) << row.name << ": " << message;
    }
  }
}

// Only the first problem is said, in document order: a person fixes one at a time.
TEST(ResultsCheck, TheFirstProblemIsTheOneSaid) {
  json j = run_document();
  j["kind"] = "weird";
  j["scenes"][1]["status"] = "exploded";
  try {
    results_from_json(j, "two.json");
    FAIL() << "no error";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("$.kind"), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find("exploded"), std::string::npos) << e.what();
  }
}

// Through the file reader every command uses: 1e400 is caught by the JSON reader (line and
// column), an impossible status by the check (path).
TEST(ResultsCheck, ReadResultsNamesTheFileForEveryKindOfProblem) {
  TempDir dir;
  const std::filesystem::path path = dir.path() / "results.json";
  json j = run_document();
  j["scenes"][0]["status"] = "exploded";
  write_file_atomically(path, j.dump(1));
  try {
    read_results(path);
    FAIL() << "no error";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find(path.string() + ": $.scenes[0].status: unknown value"),
              std::string::npos)
        << e.what();
  }
  std::string text = run_document().dump(1);
  const std::string key = "\"seconds_spent\": ";
  const std::size_t at = text.find(key) + key.size();
  text.replace(at, text.find(',', at) - at, "1e400");
  write_file_atomically(path, text);
  try {
    read_results(path);
    FAIL() << "no error";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("$.scenes[0].seconds_spent"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("out of range"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace raygate
