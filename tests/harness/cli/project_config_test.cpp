// Project defaults (cli/project_config.h) without running raygate: paths in the file relative to
// its folder, names of shipped adapters and suites kept, URLs kept, the environment over the
// file, empty variables unset, --config found among the arguments, sections refused.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "cli/project_config.h"
#include "core/error.h"
#include "core/fs.h"

namespace raygate::cli {
namespace {

using ::testing::HasSubstr;

// What read_project_config says refusing `file`; "accepted" when it does not refuse it.
std::string refusal(const std::filesystem::path& file) {
  try {
    read_project_config(file);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(ProjectConfig, PathsAreRelativeToTheFileNamesAndUrlsStay) {
  const TempDir dir;
  write_file_atomically(dir.path() / "ci" / "tracer.json", "{}");
  write_file_atomically(dir.path() / "raygate.toml",
                        "repo = \"..\"\nadapter = \"ci/tracer.json\"\nsuite = \"ci\"\n"
                        "policy = \"ci/gate.json\"\nstore = \"postgresql://ci@db/raygate\"\n");
  const ProjectDefaults d = read_project_config(dir.path() / "raygate.toml");
  EXPECT_EQ(d.at("repo").value, dir.path().parent_path().string());
  EXPECT_EQ(d.at("adapter").value, (dir.path() / "ci" / "tracer.json").string());
  EXPECT_EQ(d.at("suite").value, "ci");  // no such file beside it: a shipped suite's name
  EXPECT_EQ(d.at("policy").value, (dir.path() / "ci" / "gate.json").string());
  EXPECT_EQ(d.at("store").value, "postgresql://ci@db/raygate");
  EXPECT_EQ(d.at("suite").origin, (dir.path() / "raygate.toml").string() + ":3");
}

// The sweep of 2026-11-29: a file saved with a byte-order mark said "unknown key 'repo'".
TEST(ProjectConfig, AByteOrderMarkIsReadPast) {
  const TempDir dir;
  write_file_atomically(dir.path() / "raygate.toml", "\xEF\xBB\xBFsuite = \"ci\"\n");
  EXPECT_EQ(read_project_config(dir.path() / "raygate.toml").at("suite").value, "ci");
}

TEST(ProjectConfig, EnvironmentOverTheFileAndEmptyIsUnset) {
  const TempDir dir;
  write_file_atomically(dir.path() / "p.toml", "adapter = \"cmake-nff\"\nsuite = \"full\"\n");
  const std::map<std::string, std::string> env{{"RAYGATE_CONFIG", (dir.path() / "p.toml").string()},
                                               {"RAYGATE_ADAPTER", "povray"},
                                               {"RAYGATE_SUITE", ""}};
  const auto getenv = [&](const char* name) -> const char* {
    const auto at = env.find(name);
    return at == env.end() ? nullptr : at->second.c_str();
  };
  const ProjectDefaults d = load_project_defaults("", getenv);
  EXPECT_EQ(d.at("adapter").value, "povray");
  EXPECT_EQ(d.at("adapter").origin, "RAYGATE_ADAPTER");
  EXPECT_EQ(d.at("suite").value, "full");
  EXPECT_FALSE(d.contains("store"));
  EXPECT_THROW(load_project_defaults((dir.path() / "none.toml").string(), getenv), UsageError);
}

TEST(ProjectConfig, SectionsAndListsAreRefusedWithTheLine) {
  const TempDir dir;
  write_file_atomically(dir.path() / "a.toml", "store = \"x.db\"\n[run]\nadapter = \"y\"\n");
  EXPECT_THAT(refusal(dir.path() / "a.toml"),
              HasSubstr("a.toml:2:1: [run]: sections are not read"));
  // The seventh sweep: a section with no key after it was read as nothing, even by --version.
  write_file_atomically(dir.path() / "end.toml", "store = \"x.db\"\n  [x]  \n");
  EXPECT_THAT(refusal(dir.path() / "end.toml"),
              HasSubstr("end.toml:2:3: [x]: sections are not read"));
  write_file_atomically(dir.path() / "b.toml", "suite = [\"ci\", \"full\"]\n");
  EXPECT_THROW(read_project_config(dir.path() / "b.toml"), UsageError);
  // A list of one was read as its one value (the sweep of 2026-11-29: a store named `a`).
  write_file_atomically(dir.path() / "c.toml", "store = [\"a\"]\n");
  EXPECT_THAT(refusal(dir.path() / "c.toml"),
              HasSubstr("c.toml:1:9: store is a list; give one value"));
}

// The tenth sweep: a key given twice was "raygate.toml:1: store: expected one value", at the line
// that was right; a key that begins with another's name ("storex") was placed on its line.
TEST(ProjectConfig, AKeyGivenTwiceIsRefusedAtItsSecondLine) {
  const TempDir dir;
  write_file_atomically(dir.path() / "a.toml",
                        "store = \"a.db\"\nsuite = \"ci\"\nstore = \"b.db\"\n");
  EXPECT_THAT(refusal(dir.path() / "a.toml"),
              HasSubstr("a.toml:3: store is given again (first at line 1)"));
  write_file_atomically(dir.path() / "b.toml", "store = \"a.db\"\nstorex = 1\n");
  EXPECT_THAT(refusal(dir.path() / "b.toml"), HasSubstr("b.toml:2: unknown key 'storex'"));
}

// Hostile sweep Y1, y-bad: CLI11 kept the quote of an unterminated string as part of the value
// (a store named `"x.db`) and took `store =` as no line at all.
TEST(ProjectConfig, AnUnterminatedStringOrAMissingValueIsRefusedAtItsLine) {
  const TempDir dir;
  const auto refusal = [&](const std::string& text) -> std::string {
    write_file_atomically(dir.path() / "raygate.toml", text);
    try {
      read_project_config(dir.path() / "raygate.toml");
    } catch (const UsageError& e) {
      return e.what();
    }
    return "accepted";
  };
  const std::string file = (dir.path() / "raygate.toml").string();
  EXPECT_THAT(refusal("store = \"x.db\n"), HasSubstr(file + ":1:9: unterminated string"));
  EXPECT_THAT(refusal("repo = \".\"\nsuite = 'ci\n"),
              HasSubstr(file + ":2:9: unterminated string"));
  EXPECT_THAT(refusal("repo = \".\"\nstore = \n"), HasSubstr(file + ":2: store has no value"));
  EXPECT_THAT(refusal("store =\r\n"), HasSubstr(file + ":1: store has no value"));
  EXPECT_EQ(refusal("store = \"x.db\"  \nsuite = 'ci'\n# adapter = \"\n"), "accepted");
  // The fifth sweep: a NUL byte cut the value short without a word.
  EXPECT_THAT(refusal(std::string("suite = 'ci'\nstore = \"a\0b.db\"\n", 30)),
              HasSubstr(file + ":2:11: a NUL byte"));
}

TEST(ProjectConfig, AFolderNamedAsTheConfigIsSaidToBeAFolder) {
  const TempDir dir;
  const auto no_env = [](const char*) -> const char* { return nullptr; };
  try {
    load_project_defaults(dir.path().string(), no_env);
    FAIL() << "a folder was accepted as --config";
  } catch (const UsageError& e) {
    EXPECT_THAT(e.what(), HasSubstr("--config " + dir.path().string() + ": is a directory"));
  }
  try {
    load_project_defaults((dir.path() / "none.toml").string(), no_env);
    FAIL() << "a missing --config was accepted";
  } catch (const UsageError& e) {
    EXPECT_THAT(e.what(), HasSubstr("none.toml: no such file"));
  }
  // The seventh sweep: RAYGATE_CONFIG=/dev/zero was "no such file".
  const auto dev_zero = [](const char* name) -> const char* {
    return std::string_view(name) == "RAYGATE_CONFIG" ? "/dev/zero" : nullptr;
  };
  try {
    load_project_defaults("", dev_zero);
    FAIL() << "a device was accepted as RAYGATE_CONFIG";
  } catch (const UsageError& e) {
    EXPECT_THAT(e.what(), HasSubstr("RAYGATE_CONFIG=/dev/zero: is not a regular file"));
  }
}

// The fourth sweep: a folder named raygate.toml in the working directory was passed over, and
// the project's defaults with it, without a word.
TEST(ProjectConfig, ADefaultConfigThatIsAFolderIsSaidToBeOne) {
  const TempDir dir;
  std::filesystem::create_directory(dir.path() / "raygate.toml");
  const std::filesystem::path before = std::filesystem::current_path();
  std::filesystem::current_path(dir.path());
  std::string said = "accepted";
  try {
    load_project_defaults("", [](const char*) -> const char* { return nullptr; });
  } catch (const UsageError& e) {
    said = e.what();
  }
  std::filesystem::current_path(before);
  EXPECT_THAT(said, HasSubstr("./raygate.toml is a directory, not a config file"));
  EXPECT_THAT(said, HasSubstr("--config FILE"));
}

TEST(ProjectConfig, ConfigArgumentIsFoundBeforeParsing) {
  const char* spaced[] = {"raygate", "history", "--config", "x.toml"};
  EXPECT_EQ(find_config_argument(4, spaced), "x.toml");
  const char* joined[] = {"raygate", "--config=y.toml", "run"};
  EXPECT_EQ(find_config_argument(3, joined), "y.toml");
  const char* none[] = {"raygate", "run", "--", "--config", "z"};
  EXPECT_EQ(find_config_argument(5, none), "");
  EXPECT_EQ(environment_name("store"), "RAYGATE_STORE");
}

// A raygate.toml whose policy names a missing file (issue 25, class 12): only a command that
// takes --policy and was not given one fails, with the file's line; the others, --version and
// --help included, parse as if the key were not there.
TEST(ProjectConfig, ARefusedDefaultFailsOnlyTheCommandThatUsesIt) {
  const TempDir dir;
  write_file_atomically(dir.path() / "raygate.toml", "policy = \"missing.json\"\n");
  write_file_atomically(dir.path() / "given.json", "{}");
  const ProjectDefaults defaults = read_project_config(dir.path() / "raygate.toml");
  const auto parse = [&](std::vector<std::string> args) {
    CLI::App app{"test"};
    app.set_version_flag("--version", "1.0");
    std::string policy;
    std::string other;
    app.add_subcommand("report")->add_option("--policy", policy)->check(CLI::ExistingFile);
    app.add_subcommand("adapter")->add_option("--name", other);
    apply_project_defaults(app, defaults);
    std::reverse(args.begin(), args.end());
    app.parse(args);
    return policy;
  };
  EXPECT_NO_THROW(parse({"adapter", "--name", "x"}));
  EXPECT_THROW(parse({"--version"}), CLI::Success);
  EXPECT_THROW(parse({"--help"}), CLI::Success);
  EXPECT_EQ(parse({"report", "--policy", (dir.path() / "given.json").string()}),
            (dir.path() / "given.json").string());
  try {
    parse({"report"});
    FAIL() << "the missing policy was accepted";
  } catch (const UsageError& e) {
    EXPECT_THAT(e.what(), HasSubstr((dir.path() / "raygate.toml").string() + ":1: report policy"));
    EXPECT_THAT(e.what(), HasSubstr("missing.json"));
  }
}

// docs/store.md: passwords are never printed. --help printed a store default from raygate.toml
// or RAYGATE_STORE whole, and a line without '=' was echoed by CLI11's error (a sweep).
TEST(ProjectConfig, AStorePasswordIsNeitherShownInHelpNorEchoedByARefusal) {
  const TempDir dir;
  write_file_atomically(dir.path() / "raygate.toml",
                        "store = \"postgresql://ci:s3cr3tPW@db:5432/raygate\"\n");
  const ProjectDefaults defaults = read_project_config(dir.path() / "raygate.toml");
  CLI::App app{"test"};
  std::string store;
  CLI::Option* option = app.add_subcommand("history")->add_option("--store", store);
  apply_project_defaults(app, defaults);
  EXPECT_EQ(option->get_default_str(), "postgresql://ci@db:5432/raygate");
  write_file_atomically(dir.path() / "bad.toml",
                        "# team store\nstore \"postgresql://ci:s3cr3tPW@db/raygate\"\n");
  const std::string refused = refusal(dir.path() / "bad.toml");
  EXPECT_THAT(refused, HasSubstr("bad.toml:2:1: no '=' on this line"));
  EXPECT_EQ(refused.find("s3cr3tPW"), std::string::npos) << refused;
}

}  // namespace
}  // namespace raygate::cli
