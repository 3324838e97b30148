// The command line's conventions (docs/cli.md), as a user meets them: results on standard output
// only when asked and nothing else there (--report json:-, --format json); colour by --color and
// NO_COLOR on a real (pseudo-)terminal; --quiet; one spelling of output flags with the old ones
// kept as deprecated aliases; RAYGATE_* variables and raygate.toml under the command line.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cli_support.h"
#include "results_fixture.h"
#include "terminal_support.h"
#include "tracer_fixture.h"

namespace raygate::test {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;
using nlohmann::json;

constexpr const char* kEscape = "\033[";

class Conventions : public ::testing::Test {
 protected:
  // A stored document of one run whose balls image failed: the console report colours it.
  std::string document() {
    DocumentSpec spec;
    spec.sha = fake_sha(1);
    spec.scenes = {{"balls", 0.8, 0.01, 1.0, 0.5, ImageVerdict::fail}, {"gears", 1.5}};
    write_results(make_document(spec), dir.path() / "doc.json");
    return "doc.json";
  }
  void import_document() {
    const CliRun r = run_raygate({"import", "--store", "store.db", document()}, dir);
    ASSERT_EQ(r.exit_code, 0) << r.out;
  }
  TempDir dir;
};

TEST_F(Conventions, NoColorIsHonouredOnATerminal) {
  const std::vector<std::string> report{"report", document()};
  const TerminalRun coloured = run_on_terminal(report, dir.path(), {{"NO_COLOR", std::nullopt}});
  ASSERT_EQ(coloured.exit_code, 0) << coloured.out;
  EXPECT_THAT(coloured.out, HasSubstr(kEscape)) << "a terminal gets colour by default";

  const TerminalRun no_color = run_on_terminal(report, dir.path(), {{"NO_COLOR", "1"}});
  ASSERT_EQ(no_color.exit_code, 0) << no_color.out;
  EXPECT_THAT(no_color.out, HasSubstr("balls"));
  EXPECT_THAT(no_color.out, Not(HasSubstr(kEscape)));

  // An empty NO_COLOR does not count (no-color.org); --color beats the variable either way.
  EXPECT_THAT(run_on_terminal(report, dir.path(), {{"NO_COLOR", ""}}).out, HasSubstr(kEscape));
  EXPECT_THAT(
      run_on_terminal({"report", "doc.json", "--color", "always"}, dir.path(), {{"NO_COLOR", "1"}})
          .out,
      HasSubstr(kEscape));
  EXPECT_THAT(run_on_terminal({"--color", "never", "report", "doc.json"}, dir.path(),
                              {{"NO_COLOR", std::nullopt}})
                  .out,
              Not(HasSubstr(kEscape)));
}

TEST_F(Conventions, NoColourWhenNotATerminalUnlessAlways) {
  document();
  EXPECT_THAT(run_raygate_streams({"report", "doc.json"}, dir, {}).out, Not(HasSubstr(kEscape)));
  EXPECT_THAT(run_raygate_streams({"report", "doc.json", "--color", "always"}, dir).out,
              HasSubstr(kEscape));
  EXPECT_EQ(run_raygate_streams({"report", "doc.json", "--color", "sometimes"}, dir).exit_code, 2);
}

TEST_F(Conventions, GateAndScenesListPrintJsonAlone) {
  document();
  const CliStreams gate = run_raygate_streams({"gate", "doc.json", "--format", "json"}, dir);
  EXPECT_EQ(gate.exit_code, 1) << gate.err;  // the failed image
  const json verdict = json::parse(gate.out);
  EXPECT_EQ(verdict["exit_code"], 1);
  EXPECT_EQ(verdict["verdict"], "fail");
  EXPECT_THAT(run_raygate_streams({"gate", "doc.json"}, dir).out, HasSubstr("gate: FAIL"));

  const CliStreams scenes = run_raygate_streams({"scenes", "list", "--format", "json"}, dir);
  ASSERT_EQ(scenes.exit_code, 0) << scenes.err;
  const json list = json::parse(scenes.out);
  ASSERT_EQ(list["scenes"].size(), 13u);
  EXPECT_EQ(list["scenes"][0]["name"], "balls");
  EXPECT_TRUE(list["scenes"][0]["default_size"].is_number());
}

TEST_F(Conventions, DeprecatedSpellingsStillWorkAndSaySo) {
  import_document();
  const CliStreams old_json =
      run_raygate_streams({"history", "--store", "store.db", "--json"}, dir);
  ASSERT_EQ(old_json.exit_code, 0) << old_json.err;
  EXPECT_TRUE(json::accept(old_json.out)) << old_json.out;
  EXPECT_THAT(old_json.err, HasSubstr("--json is deprecated; use --format json"));
  const CliStreams new_json =
      run_raygate_streams({"history", "--store", "store.db", "--format", "json"}, dir);
  EXPECT_EQ(new_json.out, old_json.out);
  EXPECT_THAT(new_json.err, Not(HasSubstr("deprecated")));

  const CliStreams old_out =
      run_raygate_streams({"export", "--store", "store.db", "--out", "a.json"}, dir);
  ASSERT_EQ(old_out.exit_code, 0) << old_out.err;
  EXPECT_TRUE(fs::exists(dir.path() / "a.json"));
  EXPECT_THAT(old_out.err, HasSubstr("--out is deprecated; use --output"));
  const CliStreams new_out =
      run_raygate_streams({"export", "--store", "store.db", "--output", "b.json"}, dir);
  ASSERT_EQ(new_out.exit_code, 0) << new_out.err;
  EXPECT_EQ(read_file(dir.path() / "a.json"), read_file(dir.path() / "b.json"));
  EXPECT_EQ(
      run_raygate_streams({"export", "--store", "store.db", "--out", "c.json", "-o", "d.json"}, dir)
          .exit_code,
      2);
  EXPECT_EQ(run_raygate_streams({"export", "--store", "store.db"}, dir).exit_code, 2);
}

TEST_F(Conventions, ConfigFileThenEnvironmentThenCommandLine) {
  // A store that does not exist is named in the error: which one was used.
  write_file_atomically(dir.path() / "raygate.toml",
                        "# the project's defaults\nstore = \"from-file.db\"\n");
  const auto store_named = [&](const std::vector<std::string>& args,
                               const std::map<std::string, std::string>& env) {
    const CliStreams r = run_raygate_streams(args, dir, env);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    return r.err;
  };
  const std::map<std::string, std::string> unset{{"RAYGATE_STORE", ""}};
  EXPECT_THAT(store_named({"history"}, unset), HasSubstr((dir.path() / "from-file.db").string()));
  EXPECT_THAT(store_named({"history"}, {{"RAYGATE_STORE", "from-env.db"}}),
              HasSubstr("from-env.db"));
  EXPECT_THAT(
      store_named({"history", "--store", "from-cli.db"}, {{"RAYGATE_STORE", "from-env.db"}}),
      HasSubstr("from-cli.db"));
  write_file_atomically(dir.path() / "other.toml", "store = \"other.db\"\n");
  EXPECT_THAT(store_named({"--config", "other.toml", "history"}, unset), HasSubstr("other.db"));

  // The required --adapter and the suite come from them too (refused here, so nothing runs).
  const CliStreams adapter =
      run_raygate_streams({"run", "--no-store"}, dir, {{"RAYGATE_ADAPTER", "no-such-adapter"}});
  EXPECT_EQ(adapter.exit_code, 2);
  EXPECT_THAT(adapter.err, HasSubstr("adapter 'no-such-adapter' not found"));

  write_file_atomically(dir.path() / "bad.toml", "store = \"x.db\"\nadaptor = \"cmake-nff\"\n");
  const CliStreams bad = run_raygate_streams({"--config", "bad.toml", "history"}, dir);
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_THAT(bad.err, HasSubstr("bad.toml:2: unknown key 'adaptor'"));
  EXPECT_EQ(run_raygate_streams({"--config", "missing.toml", "history"}, dir).exit_code, 2);
}

TEST_F(Conventions, ProjectAdapterDoesNotFilterHistory) {
  import_document();
  const CliStreams r = run_raygate_streams({"history", "--store", "store.db", "--format", "json"},
                                           dir, {{"RAYGATE_ADAPTER", "some-other-adapter"}});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(json::parse(r.out)["tables"].size(), 1u);
}

TEST_F(Conventions, QuietKeepsOnlyResults) {
  import_document();
  const CliStreams chatty = run_raygate_streams({"alert", "--store", "store.db"}, dir);
  EXPECT_THAT(chatty.err, HasSubstr("judging"));
  const CliStreams quiet = run_raygate_streams({"alert", "--quiet", "--store", "store.db"}, dir);
  EXPECT_EQ(quiet.err, "");
  EXPECT_EQ(quiet.out, chatty.out);
}

// `raygate run --report json:-` on the fixture tracer: standard output is the JSON report and
// nothing else; progress and the console table went to standard error.
TEST_F(Conventions, RunReportJsonToStandardOutputIsPureJson) {
  testing::GitFixture repo(dir.path() / "tracer-repo");
  repo.write("tracer.cpp", TracerSources{}.fast);
  repo.write("Makefile", read_file(kFixture / "Makefile"));
  repo.commit("the tracer");
  write_file_atomically(dir.path() / "tiny.json", kTinySuite);
  fs::create_directories(dir.path() / "no-goldens");
  const std::vector<std::string> run{
      "run",       "--repo",       "tracer-repo", "--adapter",    "make-nff", "--suite",
      "tiny.json", "--scene",      "tetra",       "--max-rounds", "1",        "--warmup",
      "0",         "--golden-dir", "no-goldens",  "--no-store",   "--report", "json:-"};
  const CliStreams r = run_raygate_streams(run, dir);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const json report = json::parse(r.out);  // throws on anything but one JSON document
  EXPECT_EQ(report["verdict"], "pass");
  EXPECT_EQ(report["scenes"][0]["id"], "tetra");
  EXPECT_THAT(r.err, HasSubstr("measuring make-nff"));
  EXPECT_THAT(r.err, HasSubstr("raygate: pass (1 scene"));  // the console table

  std::vector<std::string> quiet = run;
  quiet.insert(quiet.begin() + 1, "--quiet");
  const CliStreams q = run_raygate_streams(quiet, dir);
  ASSERT_EQ(q.exit_code, 0) << q.err;
  EXPECT_TRUE(json::accept(q.out)) << q.out;
  EXPECT_EQ(q.err, "");
}

// Naming the wrong kind of thing is a usage error (2), not "could not measure" (3), and never an
// internal error (issue 25, class 12).
TEST_F(Conventions, AnEmptyRepoAFolderAsStoreAndAFileAsCacheAreUsageErrors) {
  fs::create_directories(dir.path() / "a-folder");
  write_file_atomically(dir.path() / "a-file", "not a folder");
  const CliStreams repo = run_raygate_streams(
      {"run", "--repo", "", "--adapter", "raygate-baseline-bbox", "--no-store"}, dir);
  EXPECT_EQ(repo.exit_code, 2) << repo.err;
  EXPECT_THAT(repo.err, HasSubstr("--repo: the value is empty; leave the option out"));
  const CliStreams store = run_raygate_streams({"history", "--store", "a-folder"}, dir);
  EXPECT_EQ(store.exit_code, 2) << store.err;
  EXPECT_THAT(store.err, HasSubstr("is a directory"));
  const CliStreams cache = run_raygate_streams(
      {"run", "--adapter", "raygate-baseline-bbox", "--cache-dir", "a-file", "--no-store"}, dir);
  EXPECT_EQ(cache.exit_code, 2) << cache.err;
  EXPECT_THAT(cache.err, HasSubstr("--cache-dir: cannot write "));  // as the command line is read
  EXPECT_THAT(cache.err, HasSubstr("a-file is not a directory"));
  const CliStreams pins = run_raygate_streams(
      {"run", "--adapter", "raygate-baseline-bbox", "--no-pin", "--pin", "1", "--no-store"}, dir);
  EXPECT_EQ(pins.exit_code, 2) << pins.err;
  EXPECT_THAT(pins.err, HasSubstr("--no-pin and --pin exclude each other"));
  // The sweep of 2026-11-29: a CPU named twice, and --pin beside a duet (not used), were taken.
  const CliStreams twice = run_raygate_streams(
      {"run", "--adapter", "raygate-baseline-bbox", "--pin", "0,0", "--no-store"}, dir);
  EXPECT_EQ(twice.exit_code, 2) << twice.err;
  EXPECT_THAT(twice.err, HasSubstr("--pin names CPU 0 twice"));
  const CliStreams duet = run_raygate_streams({"run", "--adapter", "raygate-baseline-bbox",
                                               "--schedule", "duet", "--pin", "0", "--no-store"},
                                              dir);
  EXPECT_EQ(duet.exit_code, 2) << duet.err;
  EXPECT_THAT(duet.err, HasSubstr("--pin applies to the alternate schedule"));
  // -o over the store the run records into would replace the store with the document.
  const CliStreams over = run_raygate_streams(
      {"run", "--adapter", "raygate-baseline-bbox", "--store", "s.db", "-o", "s.db"}, dir);
  EXPECT_EQ(over.exit_code, 2) << over.err;
  EXPECT_THAT(over.err, HasSubstr("--output and --store name the same file"));
}

// The sweep of 2026-11-28: `raygate nosuchcmd` said only "A subcommand is required".
TEST_F(Conventions, AnUnknownCommandIsNamed) {
  const CliStreams unknown = run_raygate_streams({"nosuchcmd"}, dir);
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_THAT(unknown.err, HasSubstr("unknown command 'nosuchcmd'"));
  const CliStreams none = run_raygate_streams({}, dir);
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_THAT(none.err, HasSubstr("A subcommand is required"));
}

// Hostile sweep O1, O2, f03, y-cfg2: each refused with exit 2 and a plain message before
// anything is built or measured (no repository is needed to say so).
TEST_F(Conventions, BadStoreGoldenCacheAndConfigAreRefusedUpFront) {
  fs::create_directories(dir.path() / "cache");
  write_file_atomically(dir.path() / "cache" / "runs", "not a folder");
  write_file_atomically(dir.path() / "a-file", "not a folder");
  const std::vector<std::string> run = {"run", "--adapter", "raygate-baseline-bbox"};
  const auto refused = [&](std::vector<std::string> extra, const std::string& said) {
    SCOPED_TRACE(extra.back());
    extra.insert(extra.begin(), run.begin(), run.end());
    const CliStreams r = run_raygate_streams(extra, dir);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_THAT(r.err, HasSubstr(said));
    EXPECT_THAT(r.err, Not(HasSubstr("measuring")));
  };
  refused({"--store", "postgresql://u@h:99999/db"},
          "--store postgresql://u@h:99999/db: not a valid PostgreSQL URL (port \"99999\"");
  refused({"--store", "postgresql://u@localhost/db?sslmode=bogus"}, "sslmode \"bogus\"");
  refused({"--no-store", "--golden-dir", ""}, "--golden-dir: the value is empty");
  refused({"--no-store", "--golden-dir", "a-file"}, "--golden-dir a-file: exists and is not a");
  refused(
      {"--no-store", "--cache-dir", "cache"},
      "--cache-dir cache: " + (fs::path("cache") / "runs").string() + " is a file, not a folder");
  const CliStreams config = run_raygate_streams({"--config", "cache", "history"}, dir);
  EXPECT_EQ(config.exit_code, 2) << config.err;
  EXPECT_THAT(config.err, HasSubstr("--config cache: is a directory, not a config file"));
}

}  // namespace
}  // namespace raygate::test
