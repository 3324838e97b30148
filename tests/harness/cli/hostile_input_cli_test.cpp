// Hostile values on the command line and in the files it names (issue 40), as a user or a script
// gives them: every number is finite and in range, every bad flag, argument and document is a
// usage error (exit 2) naming the option or the JSON path, nothing ends in "internal error", and
// what the user gave is echoed back only as far as it helps.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cli_support.h"
#include "results/results.h"
#include "results_fixture.h"
#include "tracer_fixture.h"

namespace raygate::test {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;
using nlohmann::json;

// A usage error naming `what`, and nothing raygate could not handle.
void expect_usage_error(const CliRun& r, const std::string& what) {
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_THAT(r.out, HasSubstr(what));
  EXPECT_THAT(r.out, Not(HasSubstr("internal error")));
}

// Every FLOAT option of every command, with every spelling strtod takes for a value that is not
// a finite number: CLI11's range checks let NaN through (a NaN --max-minutes stopped a run after
// one round, passed it and stored null).
TEST(HostileInput, EveryNumberOptionRefusesWhatIsNotAFiniteNumber) {
  TempDir dir;
  const std::vector<std::vector<std::string>> commands = {
      {"run", "--adapter", "make-nff", "--max-minutes"},
      {"run", "--adapter", "make-nff", "--max-seconds"},
      {"run", "--adapter", "make-nff", "--target"},
      {"compare", "--adapter", "make-nff", "--max-minutes"},
      {"bisect", "--adapter", "make-nff", "--good", "a", "--bad", "b", "--max-seconds"},
      {"alert", "--significance"},
      {"consistency", "a.json", "b.json", "--min-r2"},
      {"consistency", "a.json", "b.json", "--max-deviation"},
  };
  for (const std::vector<std::string>& command : commands) {
    for (const char* value : {"nan", "NaN", "-nan", "inf", "-Infinity", "1e999"}) {
      std::vector<std::string> args = command;
      args.emplace_back(value);
      SCOPED_TRACE(args.front() + " " + args.at(args.size() - 2) + " " + value);
      expect_usage_error(run_raygate(args, dir), args.at(args.size() - 2));
    }
  }
  // Whole numbers: NaN is not one either, and doctor's rounds are bounded like the rest.
  expect_usage_error(run_raygate({"doctor", "--rounds", "nan"}, dir), "--rounds");
  expect_usage_error(run_raygate({"doctor", "--rounds", "99999999999"}, dir), "--rounds");
  expect_usage_error(run_raygate({"run", "--adapter", "make-nff", "--warmup", "inf"}, dir),
                     "--warmup");
}

// One set of words for every bounded number, whole or not: CLI11 had said "Value  not in range"
// of an empty value, "Value nan not in range" of a count, and took 0x10 as 16.
TEST(HostileInput, BoundedNumbersSayWhatIsWrongAndWhatWouldBeRight) {
  TempDir dir;
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--max-rounds", ""}, "--max-rounds: the value is empty; give a whole number from 1 to"},
      {{"--max-rounds", "nan"}, "--max-rounds: \"nan\" is not a number (NaN)"},
      {{"--max-rounds", "0x10"}, "--max-rounds: \"0x10\" is hexadecimal"},
      {{"--max-rounds", "2.5"}, "--max-rounds: \"2.5\" is not a whole number"},
      {{"--max-rounds", "ten"}, "--max-rounds: \"ten\" is not a whole number"},
      {{"--max-rounds", "-3"},
       "--max-rounds: \"-3\" is out of range; give a whole number from 1 "
       "to 100000"},
      {{"--max-minutes", ""}, "--max-minutes: the value is empty; give a number from 0 to"},
      {{"--target", "2"}, "--target: \"2\" is out of range; give a number from 0.0001 to 1"},
  };
  for (const auto& [option, words] : cases) {
    std::vector<std::string> args = {"run", "--adapter", "make-nff"};
    args.insert(args.end(), option.begin(), option.end());
    SCOPED_TRACE(option.front() + " '" + option.back() + "'");
    expect_usage_error(run_raygate(args, dir), words);
  }
}

// Two limits given that cannot both hold are refused; a default above a small limit gives way.
TEST(HostileInput, AMinimumAboveTheMaximumGivenIsAUsageError) {
  TempDir dir;
  for (const char* command : {"run", "compare"}) {
    SCOPED_TRACE(command);
    expect_usage_error(
        run_raygate({command, "--adapter", "make-nff", "--min-rounds", "50", "--max-rounds", "30"},
                    dir),
        "--min-rounds 50 is above --max-rounds 30");
  }
  // --max-rounds 3 alone, below the default minimum, is three rounds: not refused (it goes on to
  // find no repository here, an error of another kind).
  const CliRun small = run_raygate({"run", "--adapter", "make-nff", "--max-rounds", "3", "--repo",
                                    (dir.path() / "none").string()},
                                   dir);
  EXPECT_EQ(small.out.find("--min-rounds"), std::string::npos) << small.out;
  EXPECT_NE(small.exit_code, 0) << small.out;
}

class HostileDocuments : public ::testing::Test {
 protected:
  // A stored-looking run document, changed by `mutate`, written as `name`.
  template <typename Mutate>
  std::string document(const std::string& name, Mutate mutate) {
    DocumentSpec spec;
    spec.sha = fake_sha(1);
    spec.scenes = {{"balls", 1.5}, {"gears", 2.0}};
    json j = to_json(make_document(spec));
    mutate(j);
    write_file_atomically(dir.path() / name, j.dump(1));
    return name;
  }
  TempDir dir;
};

// The sweep of 2026-11-29 (after the first): a full standard output passed, two reports went to
// it back to back, an empty value meant the default, and scenes generate took -t 0 and 0x0.
TEST_F(HostileDocuments, StandardOutputEmptyValuesAndSceneBoundsAreChecked) {
  const std::string run = document("run.json", [](json&) {});
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"report", run, "--format", "json"},
        {"gate", run},
        {"scenes", "list"}}) {
    SCOPED_TRACE(args.front());
    // The shell's redirection: run_process reads a child's output through a pipe.
    ProcessSpec spec = raygate_spec(args, dir);
    spec.argv.insert(spec.argv.begin(), {"/bin/sh", "-c", "exec \"$0\" \"$@\" >/dev/full"});
    const ProcessResult full = run_process(spec);
    EXPECT_EQ(full.exit_code, 3);
    EXPECT_THAT(read_file(spec.stderr_path), HasSubstr("standard output could not be written"));
  }
  expect_usage_error(
      run_raygate({"run", "--adapter", "make-nff", "--format", "json", "--report", "markdown:-"},
                  dir),
      "markdown:- and json:- both go to standard output");
  expect_usage_error(run_raygate({"golden", "verify", "--golden-dir", ""}, dir),
                     "--golden-dir: the value is empty");
  // A policy file that is not there was "/x: cannot open", naming no option.
  expect_usage_error(run_raygate({"gate", run, "--policy", "nope.json"}, dir), "--policy: ");
  expect_usage_error(run_raygate({"merge", run, "-o", "m.json", "--policy", "nope.json"}, dir),
                     "nope.json");
  expect_usage_error(run_raygate({"history", "--series", ""}, dir), "--series: the value is empty");
  expect_usage_error(run_raygate({"scenes", "generate", "balls", "-t", "0"}, dir),
                     "--tessellate: \"0\" is out of range; give a whole number from 1 to 64");
  expect_usage_error(run_raygate({"scenes", "generate", "balls", "--resolution", "0x0"}, dir),
                     "--resolution 0x0: each side must be in 1..16384");
  expect_usage_error(run_raygate({"run", "--adapter", "make-nff", "--target", "0.00009"}, dir),
                     "give a number from 0.0001 to 1");
  // The stated ends are in range (0.0001 was refused, read as a long double below the double).
  const CliRun lowest = run_raygate(
      {"run", "--adapter", "make-nff", "--target", "0.0001", "--repo", "none", "--no-store"}, dir);
  EXPECT_THAT(lowest.out, Not(HasSubstr("--target"))) << lowest.out;
}

// gate and import read every field they trust with its JSON path: a machine of the wrong type,
// a negative budget and a number written null (how a NaN was stored) passed both before.
TEST_F(HostileDocuments, FieldsAReaderTrustsAreCheckedWithTheirPath) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {document("machine.json", [](json& j) { j["machine"] = "a laptop"; }), "$.machine"},
      {document("minutes.json", [](json& j) { j["settings"]["max_minutes"] = -5; }),
       "$.settings.max_minutes: -5 is out of range"},
      {document("null.json", [](json& j) { j["settings"]["max_minutes"] = nullptr; }),
       "$.settings.max_minutes: expected a number, found null"},
      {document("target.json",
                [](json& j) { j["settings"]["target_relative_half_width"] = nullptr; }),
       "$.settings.target_relative_half_width"},
  };
  for (const auto& [file, what] : cases) {
    SCOPED_TRACE(file);
    expect_usage_error(run_raygate({"gate", file}, dir), what);
    expect_usage_error(run_raygate({"import", "--store", "store.db", file}, dir), what);
    expect_usage_error(run_raygate({"report", file}, dir), what);
  }
  EXPECT_EQ(run_raygate({"gate", document("fine.json", [](json&) {})}, dir).exit_code, 0);
}

// scaling counts primitives by generating each scene again: a document naming a scene no SPD
// generator makes was an "internal error".
TEST_F(HostileDocuments, ScalingOfASceneNoGeneratorMakesIsAUsageError) {
  const std::string file =
      document("unknown.json", [](json& j) { j["scenes"][1]["scene"]["scene"] = "nosuch"; });
  expect_usage_error(run_raygate({"scaling", file}, dir),
                     "$.scenes[1].scene.scene: \"nosuch\" is not an SPD scene");
  const std::string huge =
      document("huge.json", [](json& j) { j["scenes"][0]["scene"]["size"] = 100000000; });
  expect_usage_error(run_raygate({"scaling", huge}, dir), "$.scenes[0].scene.size");
}

TEST_F(HostileDocuments, ADocumentArgumentOfConsistencyThatIsNotThereIsAUsageError) {
  const std::string a = document("a.json", [](json&) {});
  expect_usage_error(run_raygate({"consistency", a, "nowhere.json"}, dir), "nowhere.json");
}

TEST(HostileInput, BadFlagsAndFilesAreUsageErrors) {
  TempDir dir;
  // A --baseline the user named that is not there is not a broken installation.
  expect_usage_error(run_raygate({"run", "--adapter", "make-nff", "--baseline", "nope"}, dir),
                     "--baseline nope: not an executable file");
  fs::create_directories(dir.path() / "a-folder");
  expect_usage_error(run_raygate({"compare", "--adapter", "make-nff", "--base", "main", "--head",
                                  "main", "--baseline", "a-folder"},
                                 dir),
                     "--baseline a-folder");
  // libpq checks sslmode only when it connects, and calls a bad one a connection failure.
  const CliRun ssl = run_raygate(
      {"history", "--store", "postgresql://ci@localhost/raygate?sslmode=sometimes"}, dir);
  expect_usage_error(ssl, "sslmode \"sometimes\" is not one of disable, allow, prefer");
  expect_usage_error(
      run_raygate({"history", "--store", "postgresql://ci@localhost/raygate?connect_timeout=x"},
                  dir),
      "connect_timeout");
}

// The project file is read before any command: a symlink loop, or one that points into a folder
// without permission, is the user's to fix, said with its reason.
TEST(HostileInput, AProjectFileThatCannotBeFollowedIsAUsageError) {
  TempDir dir;
  fs::create_symlink("raygate.toml", dir.path() / "raygate.toml");
  expect_usage_error(run_raygate({"history"}, dir), "raygate.toml: cannot read");
  const CliRun named = run_raygate({"--config", "raygate.toml", "history"}, dir);
  expect_usage_error(named, "--config raygate.toml: cannot read");
}

// Every path a command writes beside its main work is checked when the command line is read:
// history --html, validate and golden's --work-dir, scenes -o and export -o exited 3 after the
// work, and consistency --markdown could overwrite one of the documents it read.
TEST_F(HostileDocuments, OutputPathsThatCannotBeWrittenAreUsageErrors) {
  write_file_atomically(dir.path() / "a-file", "x");
  const std::string a = document("a.json", [](json&) {});
  const std::string b = document("b.json", [](json& j) { j["machine"]["hostname"] = "other"; });
  const std::vector<std::vector<std::string>> cases = {
      {"history", "--store", "store.db", "--html", "a-file/plots"},
      {"validate", "--work-dir", "a-file", "balls"},
      {"validate", "--markdown", "a-file/t.md", "balls"},
      {"golden", "verify", "--work-dir", "a-file", "tetra"},
      {"golden", "bless", "--work-dir", "a-file/w", "tetra"},
      {"scenes", "generate", "balls", "-o", "a-file/balls.nff"},
      {"scenes", "convert", "in.nff", "--to", "pov", "-o", "a-file/x.pov"},
      {"export", "--store", "store.db", "-o", "a-file/x.json"},
      {"export", "--store", "store.db", "-o", "a-file"},
      {"consistency", a, b, "--markdown", "a-file/c.md"},
      // The third sweep: these were found unwritable after the work, or by SQLite's words.
      {"report", a, "-o", "a-file/r.md"},
      {"run", "--adapter", "make-nff", "--cache-dir", "a-file"},
      {"golden", "bless", "--golden-dir", "a-file", "tetra"},
      {"import", a, "--store", "a-file/s.db"},
      {"run", "--adapter", "make-nff", "--store", "a-file/s.db"},
  };
  for (const std::vector<std::string>& args : cases) {
    SCOPED_TRACE(args.front() + " " + args.at(args.size() - 2) + " " + args.back());
    expect_usage_error(run_raygate(args, dir), "a-file");
  }
  const std::string kept = read_file(dir.path() / a);
  expect_usage_error(run_raygate({"consistency", a, b, "--markdown", "./" + a}, dir),
                     "--markdown and the document a.json name the same file");
  EXPECT_EQ(read_file(dir.path() / a), kept);
}

// The third sweep's (2026-11-29) values that slipped through or were said in CLI11's words.
TEST_F(HostileDocuments, ThirdSweepValuesAreRefusedInRaygatesWords) {
  const std::string run = document("run.json", [](json&) {});
  expect_usage_error(run_raygate({"report", run, "-o", "."}, dir), "is a directory");
  expect_usage_error(run_raygate({"import", run, "--store", "/dev/null"}, dir),
                     "--store: /dev/null is not a regular file");
  // A per-scene budget of 0 s ran one round.
  expect_usage_error(run_raygate({"run", "--adapter", "make-nff", "--max-seconds", "0"}, dir),
                     "give a number from 1 to 10000000");
  expect_usage_error(run_raygate({"scenes", "generate", "balls", "--size", "1e9"}, dir),
                     "--size: \"1e9\" is not a whole number");
  expect_usage_error(run_raygate({"report", run, "--format", "json", "--format", "html"}, dir),
                     "--format is given 2 times; give it once");
  expect_usage_error(
      run_raygate({"run", "--adapter", "make-nff", "--store", "s.db", "--no-store"}, dir),
      "raygate: error: --store and --no-store cannot be given together; give one");
  // The seventh sweep: an argument left out was CLI11's "files is required".
  expect_usage_error(run_raygate({"import", "--store", "s.db"}, dir),
                     "raygate: error: no files given; name at least one");
  expect_usage_error(run_raygate({"adapter", "check"}, dir), "no files given; name at least one");
  // Sweep 12: a path with bytes that are not UTF-8 ended in "internal error: [json.exception.
  // type_error.316]", for --golden-dir only after the whole measurement.
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"run", "--adapter", "make-nff", "--cache-dir", "nu\xff\xfe"},
        {"run", "--adapter", "make-nff", "--golden-dir", "\xff"},
        {"merge", "a\xff.json", "b.json", "-o", "m.json"}}) {
    expect_usage_error(run_raygate(args, dir), "not UTF-8 text (byte 0xFF at ");
  }
  // Sweep 13: from a folder named in Latin-1, every baseline render aborted (its stats held the
  // path) and `golden bless` ended in an internal error; TMPDIR so named did the same to doctor.
  fs::create_directories(dir.path() / "d\xff");
  ProcessSpec latin1 = raygate_spec({"validate", "tetra"}, dir);
  latin1.working_directory = dir.path() / "d\xff";
  const ProcessResult r = run_process(latin1);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(read_file(latin1.stdout_path),
              HasSubstr("is not UTF-8 text: raygate writes the paths"));
  const CliStreams tmpdir = run_raygate_streams({"doctor", "--rounds", "2"}, dir,
                                                {{"TMPDIR", (dir.path() / "d\xff").string()}});
  EXPECT_EQ(tmpdir.exit_code, 2) << tmpdir.err;
  EXPECT_THAT(tmpdir.err, HasSubstr("d\xef\xbf\xbd is not UTF-8 text"));
  // history and merge compare these times as text: "yesterday" sorted among them.
  const std::string dated = document("dated.json", [](json& j) { j["started_at"] = "yesterday"; });
  expect_usage_error(run_raygate({"gate", dated}, dir),
                     "$.started_at: \"yesterday\" is not an ISO 8601 time");
  // The fourth sweep: a day no calendar has, a commit time that is none, 100,000 digits.
  for (const auto& [key, text] :
       {std::pair<std::string, std::string>{"finished_at", "2026-02-30T25:61:00Z"},
        {"started_at", std::string(100000, '1')}}) {
    const std::string odd = document("odd.json", [&](json& j) { j[key] = text; });
    expect_usage_error(run_raygate({"gate", odd}, dir), "$." + key + ": \"");
  }
  // A store read that is no file: SQLite's "disk I/O error" (exit 3) before.
  expect_usage_error(run_raygate({"history", "--store", "/dev/null"}, dir),
                     "results store /dev/null: not a regular file");
}

// The fourth sweep (2026-11-29): outputs that would overwrite what the command reads, a tracer's
// images blessed over the baseline's goldens, places only trying could show unwritable, a store
// that is no database, and a compare scene with no change.
// The fifth sweep: a name of more than 255 bytes in a path raygate reads ended in the system's
// "filesystem error: status: File name too long [<5,000 bytes>]", exit 3.
TEST_F(HostileDocuments, FifthSweepNamesTooLongToReadAreTheUsers) {
  const std::string long_name = (dir.path() / std::string(5000, 'a')).string();
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"history", "--store", long_name},
        {"adapter", "check", long_name}}) {
    const CliRun r = run_raygate(args, dir);
    expect_usage_error(r, "too long");
    EXPECT_LT(r.out.size(), 1000u) << r.out.size();
  }
  // ... and a results store was replaced by a report or a scene (`report -o results.db`), and
  // `export -o results.db` said only "is not a directory".
  const std::string run = document("run.json", [](json&) {});
  ASSERT_EQ(run_raygate({"import", run, "--store", "team.db"}, dir).exit_code, 0);
  const std::string store = read_file(dir.path() / "team.db");
  expect_usage_error(run_raygate({"report", run, "-o", "team.db"}, dir),
                     "team.db is an SQLite database (a results store?)");
  expect_usage_error(run_raygate({"scenes", "generate", "tetra", "-o", "team.db"}, dir),
                     "is an SQLite database");
  EXPECT_EQ(read_file(dir.path() / "team.db"), store);
  // An output named by a link: refused, the link and its target as they were (a link planted in
  // a tracer's repository must not send a report over another file).
  write_file_atomically(dir.path() / "keep.txt", "kept");
  fs::create_symlink(dir.path() / "keep.txt", dir.path() / "latest.md");
  expect_usage_error(run_raygate({"report", run, "-o", "latest.md"}, dir),
                     "latest.md is a symbolic link (to ");
  EXPECT_TRUE(fs::is_symlink(dir.path() / "latest.md"));
  EXPECT_EQ(read_file(dir.path() / "keep.txt"), "kept");
  // gate printed a document's control bytes (a NUL, an escape) as they were; report escaped them.
  const std::string odd = document("odd.json", [](json& j) {
    for (json& revision : j["revisions"]) revision["worktree"]["subject"] = "x\u0000\u001b[2Jy";
    json failed = j["scenes"][0]["rounds"][0]["runs"]["tracer"];
    failed["ok"] = false;
    failed["outcome"] = "a\u0000\u001b[2Jb";
    j["scenes"][0]["failure"] = {{"role", "tracer"}, {"run", failed}};
    j["scenes"][0]["status"] = "failed";
  });
  const CliRun gated = run_raygate({"gate", odd}, dir);
  EXPECT_EQ(gated.out.find('\0'), std::string::npos) << gated.out;
  EXPECT_EQ(gated.out.find('\x1b'), std::string::npos) << gated.out;
  // Sweep 12: a newline in a forged failure text started a line of its own in gate's and
  // report's console output (a fake "gate: PASS" in a CI log).
  const std::string forged = document("forged.json", [](json& j) {
    json failed = j["scenes"][0]["rounds"][0]["runs"]["tracer"];
    failed["ok"] = false;
    failed["outcome"] = "crashed\ngate: PASS: 1 scene";
    j["scenes"][0]["failure"] = {{"role", "tracer"}, {"run", failed}};
    j["scenes"][0]["status"] = "failed";
  });
  for (const char* command : {"gate", "report"}) {
    const CliRun r = run_raygate({command, forged}, dir);
    EXPECT_EQ(r.out.find("\ngate: PASS"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("crashed\\x0agate: PASS"), std::string::npos) << r.out;
  }
  // Values said in CLI11's words, or a form blamed for a number out of range.
  expect_usage_error(
      run_raygate({"scenes", "generate", "tetra", "-s", "99999999999999999999"}, dir),
      "is past any count raygate takes");
  expect_usage_error(
      run_raygate({"scenes", "generate", "tetra", "--resolution", "16x99999999999"}, dir),
      "each side must be in 1..16384");
  expect_usage_error(
      run_raygate({"run", "--adapter", "make-nff", "--schedule", "duet", "--duet-cpus", "-1"}, dir),
      "--duet-cpus -1: CPUs are numbered from 0");
  // Sweep 12: a tracer of 2 pinned threads ran on both duet CPUs while the other side ran.
  json threaded =
      json::parse(read_file(fs::path(RAYGATE_SOURCE_DIR) / "adapters" / "make-nff.json"));
  threaded["threads"] = 2;
  threaded["pin_cpus"] = true;
  write_file_atomically(dir.path() / "threaded.json", threaded.dump());
  expect_usage_error(
      run_raygate({"run", "--adapter", "threaded.json", "--schedule", "duet"}, dir),
      "--schedule duet runs two programs at once, one CPU each, but make-nff's tracer runs 2 "
      "threads");
  write_file_atomically(dir.path() / "notes.txt", "x");
  expect_usage_error(run_raygate({"export", "--store", "team.db", "-o", "notes.txt"}, dir),
                     "a file not named .json; export writes FILE.json, or a directory");
}

// The fifth sweep's leftovers: a decimal option took " 5" where a count refused it, --duet-cpus
// without the duet went unused, a 300-byte --golden-dir was found after the build, and a
// revision's commit id "zzzz" was read (history and the trend marks match revisions by it).
TEST_F(HostileDocuments, FifthSweepLeftoversAreRefusedBeforeAnythingRuns) {
  const std::vector<std::string> run = {"run", "--adapter", "make-nff", "--no-store"};
  const auto with = [&run](std::vector<std::string> extra) {
    extra.insert(extra.begin(), run.begin(), run.end());
    return extra;
  };
  expect_usage_error(run_raygate(with({"--max-seconds", " 5"}), dir),
                     "--max-seconds: \" 5\" has space around the number");
  expect_usage_error(run_raygate(with({"--target", "0.5 "}), dir), "has space around");
  expect_usage_error(run_raygate({"scenes", "generate", "tetra", "--resolution", " 10x10"}, dir),
                     "expected WIDTHxHEIGHT");
  expect_usage_error(run_raygate(with({"--duet-cpus", "0,1"}), dir),
                     "--duet-cpus applies to the duet schedule");
  expect_usage_error(run_raygate(with({"--golden-dir", std::string(300, 'g')}), dir),
                     "--golden-dir: the path is too long for the file system");
  const std::string odd =
      document("sha.json", [](json& j) { j["revisions"][0]["worktree"]["sha"] = "zzzz"; });
  for (const char* command : {"gate", "report"}) {
    expect_usage_error(run_raygate({command, odd}, dir),
                       "worktree.sha: \"zzzz\" is not a commit id");
  }
  const std::string uncommitted = document("mine.json", [](json& j) {
    j["revisions"][0]["worktree"]["sha"] = "uncommitted";
    j["revisions"][0]["worktree"]["short_sha"] = "uncommitted";  // as checkout writes it
  });
  EXPECT_EQ(run_raygate({"gate", uncommitted}, dir).exit_code, 0);
  // A short id is the start of the sha (it names export's files and is printed for the commit).
  const std::string climbing = document(
      "short.json", [](json& j) { j["revisions"][0]["worktree"]["short_sha"] = "../../../esc"; });
  for (const char* command : {"gate", "import"}) {
    expect_usage_error(run_raygate({command, climbing}, dir),
                       "worktree.short_sha: \"../../../esc\" is not the start of sha");
  }
}

// The tenth sweep: words and counts a reader acts on that it took as they came.
TEST_F(HostileDocuments, TenthSweepFieldsAreCheckedWithTheirPath) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {document("metric.json", [](json& j) { j["settings"]["metric"] = "sundial"; }),
       "$.settings.metric"},
      {document("basis.json",
                [](json& j) {
                  j["settings"]["shard"] = {{"index", 1},
                                            {"count", 2},
                                            {"suite_scenes", {"balls", "gears"}},
                                            {"cost_basis", "vibes"}};
                }),
       "$.settings.shard.cost_basis: \"vibes\" is not a cost basis"},
      {document("twice.json",
                [](json& j) {
                  j["settings"]["shard"] = {
                      {"index", 1}, {"count", 2}, {"suite_scenes", {"balls", "balls"}}};
                }),
       "scene \"balls\" is listed twice"},
      {document(
           "own.json",
           [](json& j) { j["scenes"][0]["rounds"][0]["runs"]["tracer"]["max_rss_own"] = "yes"; }),
       "$.scenes[0].rounds[0].runs.tracer.max_rss_own"},
      {document("moon.json", [](json& j) { j["scenes"][0]["images"][0]["reference"] = "moon"; }),
       "$.scenes[0].images[0].reference: unknown value \"moon\""},
      {document("label.json",
                [](json& j) {
                  j["shard"] = "2/2";
                  j["settings"]["shard"] = {
                      {"index", 1}, {"count", 2}, {"suite_scenes", {"balls", "gears"}}};
                }),
       "$.shard: \"2/2\", but settings.shard is 1/2"},
      {document("identical.json",
                [](json& j) {
                  json& image = j["scenes"][0]["images"][0];
                  image["verdict"] = "fail";
                  for (const char* zero : {"max_error", "pixels_over_warn", "nonfinite_values"}) {
                    image["metrics"][zero] = 0;
                  }
                  image["metrics"]["size_mismatch"] = false;
                }),
       "\"fail\", but its metrics say the images are identical"},
      {document("sizes.json",
                [](json& j) { j["scenes"][0]["images"][0]["metrics"]["size_mismatch"] = true; }),
       "\"pass\", but its metrics say the sizes differ"},
      {document("budget.json",
                [](json& j) {
                  j["scenes"][0]["rounds"][0]["runs"]["tracer"]["stopped_by_budget"] = true;
                }),
       "a run stopped by the budget did not succeed"},
  };
  for (const auto& [file, what] : cases) {
    SCOPED_TRACE(file);
    expect_usage_error(run_raygate({"gate", file}, dir), what);
  }
  // A policy given to gate judges speed and memory; an image's verdict needs its pixels.
  write_file_atomically(dir.path() / "loose.json", R"({"image_tolerance": 0.5})");
  const CliRun judged =
      run_raygate({"gate", document("fine.json", [](json&) {}), "--policy", "loose.json"}, dir);
  EXPECT_THAT(judged.out, HasSubstr("images keep the verdicts they were measured with"));
  // A newer raygate's keys: the settings' are kept, the others said to be dropped.
  const std::string newer = document("newer.json", [](json& j) {
    j["zzz_top"] = 1;
    j["scenes"][0]["zzz_scene"] = "x";
    j["settings"]["zzz_setting"] = true;
  });
  const CliRun imported = run_raygate({"import", "--store", "s.db", newer}, dir);
  EXPECT_EQ(imported.exit_code, 0) << imported.out;
  EXPECT_THAT(imported.out, HasSubstr("keys this raygate does not know are not stored"));
  EXPECT_THAT(imported.out, HasSubstr("$.scenes[0].zzz_scene, $.zzz_top"));
  EXPECT_THAT(imported.out, Not(HasSubstr("zzz_setting")));
}

TEST_F(HostileDocuments, FourthSweepInputsAreNotOverwrittenAndPlacesAreTried) {
  const std::string run = document("run.json", [](json&) {});
  write_file_atomically(dir.path() / "policy.json", "{}");
  write_file_atomically(dir.path() / "adapter.json",
                        read_file(fs::path(RAYGATE_SOURCE_DIR) / "adapters" / "make-nff.json"));
  const std::string kept = read_file(dir.path() / "policy.json");
  expect_usage_error(
      run_raygate({"report", run, "--policy", "policy.json", "-o", "policy.json"}, dir),
      "--policy and --output name the same file");
  expect_usage_error(run_raygate({"run", "--adapter", "adapter.json", "-o", "adapter.json"}, dir),
                     "--adapter and --output name the same file");
  expect_usage_error(run_raygate({"run", "--adapter", "make-nff", "--policy", "policy.json",
                                  "--report", "html:policy.json"},
                                 dir),
                     "--policy and --report html:policy.json name the same file");
  EXPECT_EQ(read_file(dir.path() / "policy.json"), kept);
  // /proc takes no file though root may "write" it; a name past NAME_MAX; a text file as store.
  expect_usage_error(run_raygate({"run", "--adapter", "make-nff", "-o", "/proc/x.json"}, dir),
                     "--output: cannot write /proc/x.json");
  expect_usage_error(run_raygate({"report", run, "-o", std::string(300, 'r') + ".md"}, dir),
                     "more than the 255 a file system allows");
  expect_usage_error(run_raygate({"run", "--adapter", "make-nff", "--store", "policy.json"}, dir),
                     "--store: policy.json is not an SQLite database");
  // Sweep 12: a store of a newer raygate's schema was found only after the whole measurement.
  ASSERT_EQ(run_raygate({"import", run, "--store", "newer.db"}, dir).exit_code, 0);
  {
    std::fstream store(dir.path() / "newer.db", std::ios::in | std::ios::out | std::ios::binary);
    store.seekp(60);
    store.write("\0\0\0\x63", 4);  // SQLite's user_version, big-endian: schema 99
  }
  expect_usage_error(run_raygate({"run", "--adapter", "make-nff", "--store", "newer.db"}, dir),
                     "newer.db: schema version 99 is newer than this raygate knows");
  // The baseline's goldens, copied: a tracer's run blessed into them mixed two tracers.
  fs::copy(fs::path(RAYGATE_SOURCE_DIR) / "golden" / "raygate-baseline", dir.path() / "g",
           fs::copy_options::recursive);
  expect_usage_error(
      run_raygate({"golden", "bless", "--from-run", run, "--golden-dir", "g", "--work-dir", "w"},
                  dir),
      "holds the baseline's goldens");
  expect_usage_error(run_raygate({"golden", "verify", "--from-run", run, "nosuch", "--golden-dir",
                                  "g", "--work-dir", "w"},
                                 dir),
                     "scene 'nosuch' is not in");
  // "-o -" made a file named "-" (report's -o - is standard output); --help into a full disk
  // exited 0.
  expect_usage_error(run_raygate({"run", "--adapter", "make-nff", "-o", "-"}, dir),
                     "--output -: the results document is a file");
  ProcessSpec help = raygate_spec({"--help"}, dir);
  help.argv.insert(help.argv.begin(), {"/bin/sh", "-c", "exec \"$0\" \"$@\" >/dev/full"});
  EXPECT_EQ(run_process(help).exit_code, 3);
  // A compare whose scene has no change judged nothing: it passed as "measured".
  DocumentSpec spec;
  spec.sha = fake_sha(2);
  spec.kind = DocumentKind::compare;
  spec.roles = {Role::base, Role::head};
  spec.with_change = true;
  spec.scenes = {{"balls", 1.5}};
  json compare = to_json(make_document(spec));
  compare["scenes"][0]["change"] = nullptr;
  write_file_atomically(dir.path() / "compare.json", compare.dump(1));
  const CliRun gate = run_raygate({"gate", "compare.json"}, dir);
  EXPECT_EQ(gate.exit_code, 3) << gate.out;
  EXPECT_THAT(gate.out, HasSubstr("no change of head against base was measured"));
}

class LongRevision : public TracerRepoTest {};

// A 100,000-character --rev exited 3 and printed 200 KB: it is a usage error, and what is echoed
// back of it is a few dozen characters.
TEST_F(LongRevision, IsAUsageErrorThatEchoesLittleOfIt) {
  commit(sources_.fast, "the tracer");
  for (const std::string& rev : {std::string(100000, 'a'), std::string("main\x1b[2J")}) {
    const CliRun r =
        run_raygate({"run", "--repo", repo_.path().string(), "--rev", rev, "--adapter", "make-nff",
                     "--suite", suite_.string(), "--cache-dir", cache_.string()},
                    dir_);
    expect_usage_error(r, "cannot name anything in");
    EXPECT_LT(r.out.size(), 2000u) << r.out.substr(0, 2000);
  }
  // Through CLI11's own messages too: a value for a number as long as a paste.
  const CliRun number = run_raygate(
      {"run", "--adapter", "make-nff", "--max-minutes", std::string(100000, '9')}, dir_);
  expect_usage_error(number, "--max-minutes");
  EXPECT_LT(number.out.size(), 20000u);
}

class WrongSizeImage : public TracerRepoTest {};

// A tracer that renders 10x10 whatever the scene asks: with no goldens to compare with, the
// image's size is still checked against the scene's (it passed without a word before).
TEST_F(WrongSizeImage, FailsARunWithoutGoldens) {
  const std::string source =
      patched(sources_.fast, "else if (word == \"resolution\") in >> s.width >> s.height;",
              "else if (word == \"resolution\") { in >> s.width >> s.height; s.width = "
              "s.height = 10; }");
  commit(source, "a tracer that renders 10x10");
  const CliRun r = run_raygate({"run", "--repo", repo_.path().string(), "--adapter", "make-nff",
                                "--suite", suite_.string(), "--cache-dir", cache_.string(),
                                "--golden-dir", (dir_.path() / "no-goldens").string(), "--scene",
                                "tetra", "--max-rounds", "1", "--warmup", "0", "--no-store"},
                               dir_);
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_THAT(r.out, HasSubstr("the image is 10x10, but the scene renders at 128x128"));
}

}  // namespace
}  // namespace raygate::test
