// `raygate import`, `history` and `export` as a user runs them: hand-made results documents go
// in, the table, its JSON, the drift note and the HTML page come out, exports equal the files
// imported byte for byte, and parallel imports into one store lose and duplicate nothing. Two
// tracers' repositories and two adapters give a table each, with trends (and the report's trend
// plot) that stay in their series; a real run records its repository's root commit.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fmt/core.h>

#include <set>

#include "core/sha256.h"
#include "cli_support.h"
#include "results_fixture.h"
#include "store/sqlite_handle.h"
#include "store/store.h"
#include "tracer_fixture.h"

namespace raygate::test {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

DocumentSpec commit(int seed, int day, double balls_ratio, double baseline_seconds = 1.0) {
  DocumentSpec spec;
  spec.sha = fake_sha(seed);
  spec.subject = seed == 3 ? "speed up the BVH build by sorting primitives along the longest axis"
                           : "commit number " + std::to_string(seed);
  spec.commit_time = fmt::format("2026-05-{:02}T09:00:00+00:00", day);
  spec.started_at = fmt::format("2026-05-{:02}T10:00:00Z", day);
  spec.scenes = {{"balls", balls_ratio, 0.01, baseline_seconds},
                 {"gears", 1.5, 0.02, 2.0 * baseline_seconds, 0.0123, ImageVerdict::warn}};
  return spec;
}

class HistoryCli : public ::testing::Test {
 protected:
  std::string write(const std::string& name, const DocumentSpec& spec) {
    const std::filesystem::path path = dir.path() / "docs" / name;
    write_results(make_document(spec), path);
    return "docs/" + name;
  }
  // Three commits on days 1, 2, 3; balls gets slower at the last one.
  std::vector<std::string> three_commits() {
    return {write("c1.json", commit(1, 1, 0.80)), write("c2.json", commit(2, 2, 0.80)),
            write("c3.json", commit(3, 3, 0.88))};
  }
  CliRun import(const std::vector<std::string>& files) {
    std::vector<std::string> args{"import", "--store", "store.db"};
    args.insert(args.end(), files.begin(), files.end());
    return run_raygate(args, dir);
  }
  TempDir dir;
};

TEST_F(HistoryCli, ImportStoresEachDocumentOnce) {
  const auto files = three_commits();
  const CliRun first = import(files);
  ASSERT_EQ(first.exit_code, 0) << first.out;
  EXPECT_THAT(first.out, HasSubstr("imported 3 of 3 documents"));
  EXPECT_THAT(first.out, HasSubstr("(branch main)"));
  const CliRun again = import({files[0]});
  ASSERT_EQ(again.exit_code, 0) << again.out;
  EXPECT_THAT(again.out, HasSubstr("already stored as document 1"));
  EXPECT_THAT(again.out, HasSubstr("imported 0 of 1 documents"));
}

TEST_F(HistoryCli, ImportRefusesWhatIsNotAResultsDocument) {
  write_file_atomically(dir.path() / "adapter.json", R"({"name": "x", "build": []})");
  write_file_atomically(dir.path() / "notes.json", "this is not json");
  const auto files = three_commits();
  const CliRun adapter = import({files[0], "adapter.json"});
  EXPECT_EQ(adapter.exit_code, 2) << adapter.out;
  EXPECT_THAT(adapter.out, HasSubstr("adapter.json: not a raygate results document"));
  const CliRun text = import({"notes.json"});
  EXPECT_EQ(text.exit_code, 2) << text.out;
  EXPECT_THAT(text.out, HasSubstr("notes.json:1:"));
  EXPECT_THAT(text.out, HasSubstr(": not JSON"));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "store.db"));  // checked before storing
}

TEST_F(HistoryCli, TableNewestFirstWithRatiosImageErrorsAndTrend) {
  ASSERT_EQ(import(three_commits()).exit_code, 0);
  const CliRun r = run_raygate({"history", "--store", "store.db"}, dir);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const auto at = [&](int seed) { return r.out.find(fake_sha(seed).substr(0, 7)); };
  ASSERT_NE(at(1), std::string::npos) << r.out;
  EXPECT_LT(at(3), at(2)) << r.out;
  EXPECT_LT(at(2), at(1)) << r.out;
  EXPECT_THAT(r.out, HasSubstr("2026-05-03"));
  EXPECT_THAT(r.out, HasSubstr("speed up the BVH build by sorti…"));
  EXPECT_THAT(r.out, HasSubstr("0.880 ±1.0%"));
  EXPECT_THAT(r.out, HasSubstr("0.0123 warn"));
  EXPECT_THAT(r.out, HasSubstr("▁▁█"));
  EXPECT_THAT(r.out, HasSubstr("+10.0% ↑ vs " + fake_sha(2).substr(0, 7)));
  EXPECT_THAT(r.out, Not(HasSubstr("machine drift")));

  const CliRun last = run_raygate({"history", "--store", "store.db", "--last", "1"}, dir);
  EXPECT_EQ(last.out.find(fake_sha(2).substr(0, 7)), std::string::npos) << last.out;
}

TEST_F(HistoryCli, JsonForMachines) {
  ASSERT_EQ(import(three_commits()).exit_code, 0);
  const CliRun r =
      run_raygate({"history", "--store", "store.db", "--format", "json", "--scene", "balls"}, dir);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const nlohmann::json all = nlohmann::json::parse(r.out);
  ASSERT_EQ(all["tables"].size(), 1u);
  const nlohmann::json& j = all["tables"][0];
  EXPECT_EQ(j["repository"], "path:/tmp/tracer-repo");
  EXPECT_EQ(j["adapter"], "cmake-nff");
  ASSERT_EQ(j["commits"].size(), 3u);
  EXPECT_EQ(j["commits"][0]["sha"], fake_sha(3));
  EXPECT_EQ(j["commits"][0]["branch"], "main");
  const nlohmann::json& balls = j["commits"][0]["scenes"]["balls"];
  EXPECT_DOUBLE_EQ(balls["normalized_ratio"].get<double>(), 0.88);
  EXPECT_DOUBLE_EQ(balls["baseline_median_seconds"].get<double>(), 1.0);
  EXPECT_EQ(balls["image"]["verdict"], "pass");
  EXPECT_EQ(balls["machine"]["hostname"], "ci-runner-1");
  EXPECT_FALSE(j["commits"][0]["scenes"].contains("gears"));
  EXPECT_NEAR(j["trends"]["balls"]["change_vs_previous"].get<double>(), 0.1, 1e-12);
  EXPECT_EQ(j["trends"]["balls"]["series"], j["series"]["balls"]["id"]);
  EXPECT_EQ(j["series"]["balls"]["scene_settings"], "scene=balls size=1 64x64 sampling=center");
  EXPECT_TRUE(all["machine_drift"].is_null());
}

// A store holding bytes that are not UTF-8 (written by a raygate from before text was repaired
// where it enters, or by hand): history's JSON and text, and export, repair them instead of
// failing (nlohmann::json's type_error.316 once made history --format json exit 3).
TEST_F(HistoryCli, TextThatIsNotUtf8InTheStoreIsRepairedOnTheWayOut) {
  ASSERT_EQ(import(three_commits()).exit_code, 0);
  {
    SqliteDb db = SqliteDb::open(dir.path() / "store.db", false);
    db.exec(
        "UPDATE revisions SET subject = subject || ' caf' || CAST(X'E9' AS TEXT) || "
        "CAST(X'1B' AS TEXT) || '[2J'");
    db.exec(
        "UPDATE documents SET document_json = replace(document_json, 'commit number 2', "
        "'commit number 2 ' || CAST(X'FF' AS TEXT))");
    // As that raygate stored it: the hash of the text it wrote (an edit without it is damage).
    std::vector<std::pair<std::int64_t, std::string>> texts;
    SqliteStatement read(db, "SELECT id, document_json FROM documents");
    while (read.step()) texts.emplace_back(read.integer(0), read.text(1));
    for (const auto& [id, text] : texts) {
      SqliteStatement(db, "UPDATE documents SET content_sha256 = ?1 WHERE id = ?2")
          .bind_text(1, sha256_hex(text))
          .bind_int(2, id)
          .run();
    }
  }
  const CliStreams j =
      run_raygate_streams({"history", "--store", "store.db", "--format", "json"}, dir);
  ASSERT_EQ(j.exit_code, 0) << j.err;
  const nlohmann::json all = nlohmann::json::parse(j.out);
  EXPECT_EQ(all["tables"][0]["commits"][1]["subject"], "commit number 2 caf\xEF\xBF\xBD\x1b[2J");

  const CliStreams text = run_raygate_streams({"history", "--store", "store.db"}, dir);
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_THAT(text.out, HasSubstr("caf\xEF\xBF\xBD\\x1b[2J"));  // the ESC shown, not obeyed
  EXPECT_THAT(text.out, Not(HasSubstr("\x1b")));

  const CliStreams exported =
      run_raygate_streams({"export", "--store", "store.db", "-o", "out"}, dir);
  ASSERT_EQ(exported.exit_code, 0) << exported.err;
  bool repaired = false;
  for (const auto& entry : std::filesystem::directory_iterator(dir.path() / "out")) {
    if (read_file(entry.path()).find("commit number 2 \xEF\xBF\xBD") != std::string::npos) {
      repaired = true;
    }
  }
  EXPECT_TRUE(repaired);
}

TEST_F(HistoryCli, SaysWhenTheMachineMovedAndTheCodeDidNot) {
  std::vector<std::string> files = three_commits();
  files.push_back(write("c4.json", commit(4, 4, 0.80, 0.8)));  // baseline 20% faster, ratio held
  ASSERT_EQ(import(files).exit_code, 0);
  const CliRun r = run_raygate({"history", "--store", "store.db"}, dir);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_THAT(r.out, HasSubstr("machine drift: on ci-runner-1 (Test CPU 3000) the baseline took "
                               "20.0% less time"));
  EXPECT_THAT(r.out, HasSubstr("the machine got faster, not the code"));
  const CliRun j = run_raygate({"history", "--store", "store.db", "--format", "json"}, dir);
  EXPECT_EQ(nlohmann::json::parse(j.out)["machine_drift"]["machine_got"], "faster");
}

TEST_F(HistoryCli, HtmlPageWithOnePlotPerScene) {
  ASSERT_EQ(import(three_commits()).exit_code, 0);
  const CliRun r = run_raygate({"history", "--store", "store.db", "--html", "page"}, dir);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const std::string html = read_file(dir.path() / "page" / "history.html");
  EXPECT_TRUE(html.starts_with("<!DOCTYPE html>"));
  std::size_t svgs = 0;
  for (std::size_t at = html.find("<svg "); at != std::string::npos;
       at = html.find("<svg ", at + 1)) {
    ++svgs;
  }
  EXPECT_EQ(svgs, 2u);
  std::size_t closes = 0;
  for (std::size_t at = html.find("</svg>"); at != std::string::npos;
       at = html.find("</svg>", at + 1)) {
    ++closes;
  }
  EXPECT_EQ(closes, 2u);
  // The HTML report's trend plot (report/html_svg.cpp): band, line, points.
  EXPECT_THAT(html, HasSubstr("<polygon class=\"trend-band\" points=\""));
  EXPECT_THAT(html, HasSubstr("<polyline class=\"trend-line\" points=\""));
  // A history page marks its newest commit (report/html_svg.cpp trend marks).
  EXPECT_THAT(html, HasSubstr("<title>newest: " + fake_sha(3).substr(0, 7) + " speed up the BVH"));
  EXPECT_THAT(html, HasSubstr("ratio 0.880 [0.871, 0.889]"));
  EXPECT_THAT(html, Not(HasSubstr("<script")));
  EXPECT_THAT(html, Not(HasSubstr("https://")));
  EXPECT_THAT(html, Not(HasSubstr("http://")));  // inline SVG needs no namespace URL either
}

// Two tracers' repositories (root commits A and B), each measured with two adapters, in one
// store: B's teapot is 1.718x A's, so a trend across both would say "+71.8%".
const std::string kRepoA = "root:" + std::string(40, 'a');
const std::string kRepoB = "root:" + std::string(40, 'b');

DocumentSpec tracer_commit(int seed, int day, double ratio, const std::string& repository,
                           const std::string& adapter = "cmake-nff") {
  DocumentSpec spec = commit(seed, day, ratio);
  spec.scenes = {{"teapot", ratio}};
  spec.repository_id = repository;
  spec.adapter = adapter;
  return spec;
}

std::size_t count(const std::string& text, const std::string& part) {
  std::size_t n = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
  return n;
}

TEST_F(HistoryCli, OneTablePerRepositoryAndAdapterWithTrendsThatStayInTheirSeries) {
  ASSERT_EQ(import({write("a1.json", tracer_commit(1, 1, 1.0, kRepoA)),
                    write("b2.json", tracer_commit(2, 2, 1.718, kRepoB)),
                    write("a3.json", tracer_commit(3, 3, 1.0, kRepoA)),
                    write("b4.json", tracer_commit(4, 4, 1.718, kRepoB)),
                    write("a5.json", tracer_commit(5, 5, 2.0, kRepoA, "meson")),
                    write("b6.json", tracer_commit(6, 6, 3.0, kRepoB, "meson"))})
                .exit_code,
            0);
  const CliRun r = run_raygate({"history", "--store", "store.db"}, dir);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(count(r.out, "\nrepository root:"), 4u) << r.out;
  EXPECT_THAT(r.out, HasSubstr("repository root:aaaaaaaaaaaa, adapter cmake-nff: 2 commits"));
  EXPECT_THAT(r.out, HasSubstr("repository root:bbbbbbbbbbbb, adapter cmake-nff: 2 commits"));
  EXPECT_THAT(r.out, HasSubstr("repository root:bbbbbbbbbbbb, adapter meson: 1 commit,"));
  EXPECT_THAT(r.out, Not(HasSubstr("71.8%"))) << r.out;
  EXPECT_THAT(r.out, HasSubstr("+0.0% → vs " + fake_sha(1).substr(0, 7)));
  EXPECT_THAT(r.out, HasSubstr("+0.0% → vs " + fake_sha(2).substr(0, 7)));
  EXPECT_EQ(count(r.out, "first measurement"), 2u) << r.out;  // each meson table

  const CliRun b = run_raygate(
      {"history", "--store", "store.db", "--repository", "bbbbbbbb", "--adapter", "meson"}, dir);
  ASSERT_EQ(b.exit_code, 0) << b.out;
  EXPECT_EQ(count(b.out, "\nrepository "), 1u) << b.out;
  EXPECT_THAT(b.out, HasSubstr(fake_sha(6).substr(0, 7)));
  EXPECT_THAT(b.out, Not(HasSubstr(fake_sha(4).substr(0, 7))));
  const CliRun json = run_raygate({"history", "--store", "store.db", "--format", "json"}, dir);
  const nlohmann::json tables = nlohmann::json::parse(json.out)["tables"];
  ASSERT_EQ(tables.size(), 4u);
  EXPECT_EQ(tables[0]["repository"], kRepoB);  // the newest first
  EXPECT_EQ(tables[0]["adapter"], "meson");
  const CliRun suite = run_raygate({"history", "--store", "store.db", "--suite", "full"}, dir);
  EXPECT_THAT(suite.out, HasSubstr("no results in"));
  // A series named that is not there: a typo, exit 2 as alert's, not "no results" and exit 0.
  const CliRun series = run_raygate({"history", "--store", "store.db", "--series", "zz"}, dir);
  EXPECT_EQ(series.exit_code, 2) << series.out;
  EXPECT_THAT(series.out, HasSubstr("--series zz: no series in"));
}

// The HTML report's trend plot (trends_from_store, here through `raygate merge`) shows the
// document's own series only.
TEST_F(HistoryCli, TheReportsTrendPlotStaysInTheDocumentsSeries) {
  ASSERT_EQ(import({write("a1.json", tracer_commit(1, 1, 1.0, kRepoA)),
                    write("b2.json", tracer_commit(2, 2, 1.718, kRepoB)),
                    write("a3.json", tracer_commit(3, 3, 1.0, kRepoA))})
                .exit_code,
            0);
  DocumentSpec shard = tracer_commit(4, 4, 1.718, kRepoB);
  shard.shard = "1/1";
  const std::string shard_file = write("b4-shard.json", shard);
  const CliRun merged = run_raygate({"merge", shard_file, "-o", "merged.json", "--store",
                                     "store.db", "--report", "html:report.html"},
                                    dir);
  ASSERT_TRUE(std::filesystem::exists(dir.path() / "report.html")) << merged.out;
  const std::string html = read_file(dir.path() / "report.html");
  // (find, not HasSubstr: a failure should not print the whole page)
  EXPECT_NE(html.find("Trend over 2 commits"), std::string::npos);
  EXPECT_EQ(html.find(fake_sha(3).substr(0, 7)), std::string::npos);
}

// End to end: `raygate run` records the tracer repository's root commit, and history heads the
// table with it.
class HistoryOfRuns : public TracerRepoTest {};

TEST_F(HistoryOfRuns, ARunRecordsItsRepositorysRootCommitAndHistoryShowsIt) {
  const std::string first = commit(sources_.fast, "first");
  const std::string second = commit(sources_.fast + "\n// a comment\n", "second");
  for (const std::string& rev : {first, second}) {
    const std::filesystem::path out = dir_.path() / ("run-" + rev.substr(0, 7) + ".json");
    const CliRun run =
        run_raygate({"run", "--repo", repo_.path().string(), "--rev", rev, "--adapter", "make-nff",
                     "--suite", suite_.string(), "--cache-dir", cache_.string(), "--golden-dir",
                     "no-goldens", "--max-rounds", "2", "--warmup", "0", "--out", out.string()},
                    dir_);
    ASSERT_EQ(run.exit_code, 0) << run.out;
    EXPECT_EQ(read_results(out).revisions.at(0).repository_id, "root:" + first);
  }
  const CliRun history =
      run_raygate({"history", "--store", (cache_ / "results.db").string()}, dir_);
  ASSERT_EQ(history.exit_code, 0) << history.out;
  EXPECT_TRUE(
      has(history.out, "repository root:" + first.substr(0, 12) + ", adapter make-nff: 2 commits"))
      << history.out;
}

TEST_F(HistoryCli, ExportGivesBackTheImportedFilesByteForByte) {
  const auto files = three_commits();
  ASSERT_EQ(import(files).exit_code, 0);
  const CliRun one = run_raygate(
      {"export", "--store", "store.db", "--sha", fake_sha(2).substr(0, 10), "-o", "one.json"}, dir);
  ASSERT_EQ(one.exit_code, 0) << one.out;
  EXPECT_EQ(read_file(dir.path() / "one.json"), read_file(dir.path() / files[1]));

  const CliRun all = run_raygate({"export", "--store", "store.db", "-o", "out"}, dir);
  ASSERT_EQ(all.exit_code, 0) << all.out;
  EXPECT_THAT(all.out, HasSubstr("wrote 3 documents"));
  std::set<std::string> exported;
  for (const auto& entry : std::filesystem::directory_iterator(dir.path() / "out")) {
    exported.insert(read_file(entry.path()));
  }
  std::set<std::string> imported;
  for (const std::string& file : files) imported.insert(read_file(dir.path() / file));
  EXPECT_EQ(exported, imported);

  const CliRun many = run_raygate({"export", "--store", "store.db", "-o", "all.json"}, dir);
  EXPECT_EQ(many.exit_code, 2) << many.out;
  const CliRun none =
      run_raygate({"export", "--store", "store.db", "--sha", "ffff", "-o", "x"}, dir);
  EXPECT_EQ(none.exit_code, 2) << none.out;
  EXPECT_THAT(none.out, HasSubstr("no document"));
}

// The seventh sweep: `history --html DIR` and `export -o DIR/` replaced a symbolic link where
// they write (its target untouched), where -o and --report refuse one. Both are refused now,
// before anything is written, and the link and its target stay as they were.
TEST_F(HistoryCli, ALinkWhereHistoryOrExportWritesIsRefused) {
  ASSERT_EQ(import(three_commits()).exit_code, 0);
  write_file_atomically(dir.path() / "keep.txt", "kept");
  std::filesystem::create_directories(dir.path() / "page");
  std::filesystem::create_symlink(dir.path() / "keep.txt", dir.path() / "page" / "history.html");
  const CliRun html = run_raygate({"history", "--store", "store.db", "--html", "page"}, dir);
  EXPECT_EQ(html.exit_code, 2) << html.out;
  EXPECT_THAT(html.out, HasSubstr("--html: page/history.html is a symbolic link (to "));
  ASSERT_EQ(run_raygate({"export", "--store", "store.db", "-o", "out"}, dir).exit_code, 0);
  const std::filesystem::path first = *std::filesystem::directory_iterator(dir.path() / "out");
  std::filesystem::remove(first);
  std::filesystem::create_symlink(dir.path() / "keep.txt", first);
  const CliRun exported = run_raygate({"export", "--store", "store.db", "-o", "out/"}, dir);
  EXPECT_EQ(exported.exit_code, 2) << exported.out;
  EXPECT_THAT(exported.out, HasSubstr(first.filename().string() + " is a symbolic link"));
  std::filesystem::create_symlink(dir.path() / "keep.txt", dir.path() / "one.json");
  const CliRun one = run_raygate(
      {"export", "--store", "store.db", "--sha", fake_sha(2).substr(0, 10), "-o", "one.json"}, dir);
  EXPECT_EQ(one.exit_code, 2) << one.out;
  EXPECT_THAT(one.out, HasSubstr("one.json is a symbolic link"));
  EXPECT_TRUE(std::filesystem::is_symlink(first));
  EXPECT_EQ(read_file(dir.path() / "keep.txt"), "kept");
}

// A missing store file is the user's to fix; a team store server that is not there is not.
// (The team store end to end: tests/harness/store/store_postgres_cli_test.cpp.)
TEST_F(HistoryCli, MissingStoreIsAUsageErrorAndAnAbsentServerAnInfrastructureError) {
  const CliRun missing = run_raygate({"history", "--store", "nope.db"}, dir);
  EXPECT_EQ(missing.exit_code, 2) << missing.out;
  EXPECT_THAT(missing.out, HasSubstr("does not exist"));
  const CliRun pg =
      run_raygate({"history", "--store", "postgresql://ci:s3cret@127.0.0.1:1/raygate"}, dir);
  EXPECT_EQ(pg.exit_code, 3) << pg.out;
  EXPECT_THAT(pg.out, HasSubstr("postgresql://ci@127.0.0.1:1/raygate"));
  EXPECT_THAT(pg.out, Not(HasSubstr("s3cret")));
  const CliRun run_help = run_raygate({"run", "--help"}, dir);
  EXPECT_THAT(run_help.out, HasSubstr("--no-store"));
  EXPECT_THAT(run_help.out, HasSubstr("<cache-dir>/results.db"));
}

TEST_F(HistoryCli, ParallelImportsLoseAndDuplicateNothing) {
  constexpr int kImporters = 5;
  constexpr int kEach = 4;
  const std::string shared = write("shared.json", commit(999, 20, 0.7));
  std::vector<Process> importers;
  for (int i = 0; i < kImporters; ++i) {
    ProcessSpec spec;
    spec.argv = {RAYGATE_EXE, "import", "--store", "store.db", shared};
    for (int k = 0; k < kEach; ++k) {
      const int seed = 10 * (i + 1) + k;
      spec.argv.push_back(write(fmt::format("p{}.json", seed), commit(seed, 1 + k, 0.9)));
    }
    spec.working_directory = dir.path();
    spec.stdout_path = dir.path() / fmt::format("import-{}.log", i);
    spec.stderr_path = spec.stdout_path;
    spec.timeout = std::chrono::minutes(2);
    importers.push_back(Process::start(spec));
  }
  for (std::size_t i = 0; i < importers.size(); ++i) {
    const ProcessResult result = importers[i].wait();
    EXPECT_TRUE(result.succeeded()) << result.describe() << "\n"
                                    << read_file(dir.path() / fmt::format("import-{}.log", i));
  }
  const auto store = open_store((dir.path() / "store.db").string(), StoreOpen::must_exist);
  EXPECT_EQ(store->documents({}).size(), static_cast<std::size_t>(kImporters * kEach + 1));
}

}  // namespace
}  // namespace raygate::test
