// Adapter validation: the shipped adapters load, a complete adapter reads back field by field,
// and each kind of mistake gives its exact message, with the JSONPath and a suggestion.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "adapter/adapter.h"
#include "core/error.h"
#include "core/fs.h"

namespace raygate {
namespace {

const std::string kOrigin = "adapters/x.json";

std::string error_of(const std::string& text) {
  try {
    parse_adapter(text, kOrigin);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "(no error)";
}

// A minimal valid adapter with `extra` spliced in as further members (or replacing one).
std::string with(const std::string& extra,
                 const std::string& run = R"(["t", "{scene}", "{image}"])",
                 const std::string& image = R"("{image}")") {
  std::string text =
      R"({"name": "t", "scene_format": "nff", "run": )" + run + R"(, "image": )" + image;
  if (!extra.empty()) text += ", " + extra;
  return text + "}";
}

TEST(AdapterLoad, ShippedAdaptersAreValid) {
  const std::filesystem::path dir = std::filesystem::path(RAYGATE_SOURCE_DIR) / "adapters";
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".json") continue;
    SCOPED_TRACE(entry.path().string());
    EXPECT_NO_THROW(load_adapter(entry.path()));
    ++count;
  }
  EXPECT_GE(count, 3);
}

TEST(AdapterLoad, BaselineAdapterBuildsTheBaselineAndRunsBbox) {
  const Adapter a = load_adapter(std::filesystem::path(RAYGATE_SOURCE_DIR) / "adapters" /
                                 "raygate-baseline-bbox.json");
  EXPECT_EQ(a.name, "raygate-baseline-bbox");
  ASSERT_EQ(a.build.size(), 2u);
  EXPECT_EQ(a.build[0][2], "{raygate_source}");
  EXPECT_NE(std::find(a.build[1].begin(), a.build[1].end(), "raygate-baseline"), a.build[1].end());
  EXPECT_EQ(a.run, (std::vector<std::string>{"{build}/bin/raygate-baseline", "{scene}", "-o",
                                             "{image}", "--accel", "bbox"}));
  // Timed by its process like any tracer (the baseline then by the same clock, DESIGN.md §11):
  // "auto", so CPU time for its one thread.
  EXPECT_EQ(a.timing.source, TimingSource::process);
  EXPECT_TRUE(a.timing.metric_by_threads);
  EXPECT_EQ(a.timing.metric, TimingMetric::cpu);
}

// The README's complete example must stay a valid adapter.
TEST(AdapterLoad, ReadmeExampleIsValid) {
  const std::string readme =
      read_file(std::filesystem::path(RAYGATE_SOURCE_DIR) / "adapters" / "README.md");
  const std::size_t section = readme.find("## A complete example");
  ASSERT_NE(section, std::string::npos);
  const std::size_t begin = readme.find("```json\n", section);
  ASSERT_NE(begin, std::string::npos);
  const std::size_t end = readme.find("```", begin + 8);
  const Adapter a = parse_adapter(readme.substr(begin + 8, end - begin - 8), "README.md");
  EXPECT_EQ(a.name, "my-tracer");
  EXPECT_EQ(a.source_dir, "renderer");
}

TEST(AdapterLoad, ReadsEveryField) {
  const Adapter a = parse_adapter(R"({
    "name": "my-tracer", "description": "d", "scene_format": "pbrt", "source_dir": "renderer/",
    "requires": ["libtbb-dev", "libfoo1:amd64"],
    "build": [["cmake", "-S", "{src}", "-B", "{build}"],
              ["cmake", "--build", "{build}", "-j", "{jobs}"]],
    "run": ["{build}/tracer", "--threads", "{threads}"], "stdin": "{scene}", "cwd": "{build}",
    "image": "{workdir}/trace.ppm", "env": {"OMP_NUM_THREADS": "{threads}", "OUT": "{workdir}"},
    "timing": {"source": "reported", "regex": "took ([0-9]+) ms", "unit": "ms"},
    "threads": 8, "pin_cpus": true, "submodules": false,
    "timeout_s": {"build": 60.5, "run": 10}})",
                                  "f.json");
  EXPECT_EQ(a.file, "f.json");
  EXPECT_EQ(a.name, "my-tracer");
  EXPECT_EQ(a.description, "d");
  EXPECT_EQ(a.scene_format, SceneFormat::pbrt);
  EXPECT_EQ(a.source_dir, "renderer");
  EXPECT_EQ(a.packages, (std::vector<std::string>{"libtbb-dev", "libfoo1:amd64"}));
  ASSERT_EQ(a.build.size(), 2u);
  EXPECT_EQ(a.build[1].back(), "{jobs}");
  EXPECT_EQ(a.run.size(), 3u);
  EXPECT_EQ(a.stdin_template, "{scene}");
  EXPECT_EQ(a.cwd, "{build}");
  EXPECT_EQ(a.image, "{workdir}/trace.ppm");
  EXPECT_EQ(a.env.at("OMP_NUM_THREADS"), "{threads}");
  EXPECT_EQ(a.timing.source, TimingSource::reported);
  EXPECT_EQ(a.timing.unit, TimeUnit::milliseconds);
  EXPECT_EQ(a.threads, 8);
  EXPECT_TRUE(a.pin_cpus);
  EXPECT_FALSE(a.submodules);
  EXPECT_DOUBLE_EQ(a.timeouts.build_seconds, 60.5);
  EXPECT_DOUBLE_EQ(a.timeouts.run_seconds, 10);
}

TEST(AdapterLoad, Defaults) {
  const Adapter a = parse_adapter(with(""), "f.json");
  EXPECT_TRUE(a.build.empty());
  EXPECT_EQ(a.cwd, "{workdir}");
  EXPECT_FALSE(a.stdin_template.has_value());
  EXPECT_EQ(a.timing.source, TimingSource::process);
  EXPECT_EQ(a.timing.metric, TimingMetric::cpu);  // "auto" with one thread
  EXPECT_TRUE(a.timing.metric_by_threads);
  EXPECT_EQ(a.threads, 1);
  EXPECT_FALSE(a.pin_cpus);
  EXPECT_TRUE(a.submodules);
  EXPECT_DOUBLE_EQ(a.timeouts.build_seconds, 1800);
  EXPECT_DOUBLE_EQ(a.timeouts.run_seconds, 600);
}

TEST(AdapterLoad, AutoMetricFollowsThreadsAndAnExplicitOneStays) {
  const auto load = [](const std::string& extra) { return parse_adapter(with(extra), "f.json"); };
  EXPECT_EQ(load(R"("threads": 4)").timing.metric, TimingMetric::wall);
  EXPECT_EQ(load(R"("timing": {"metric": "auto"}, "threads": 4)").timing.metric,
            TimingMetric::wall);
  EXPECT_EQ(load(R"("timing": {"metric": "auto"})").timing.metric, TimingMetric::cpu);
  const Adapter wall = load(R"("timing": {"source": "process", "metric": "wall"})");
  EXPECT_EQ(wall.timing.metric, TimingMetric::wall);
  EXPECT_FALSE(wall.timing.metric_by_threads);
  const Adapter cpu = load(R"("timing": {"metric": "cpu"}, "threads": 8)");
  EXPECT_EQ(cpu.timing.metric, TimingMetric::cpu);
  EXPECT_FALSE(cpu.timing.metric_by_threads);
  EXPECT_THROW(load(R"("timing": {"metric": "fastest"})"), UsageError);
}

// "images": deterministic unless said otherwise; a Monte Carlo tracer gets {seed} (in argv or
// env) and the shipped path tracer's adapter is one.
TEST(AdapterLoad, ImagesKindAndSeed) {
  EXPECT_EQ(parse_adapter(with(""), "x").images, ImageKind::deterministic);
  const Adapter mc = parse_adapter(
      with(R"("images": "monte-carlo")", R"(["t", "{scene}", "{image}", "--seed={seed}"])"), "x");
  EXPECT_EQ(mc.images, ImageKind::monte_carlo);
  EXPECT_EQ(to_string(mc.images), "monte-carlo");
  EXPECT_EQ(
      parse_adapter(with(R"("images": "monte-carlo", "env": {"SEED": "{seed}"})"), "x").images,
      ImageKind::monte_carlo);
  const Adapter shipped = load_adapter(std::filesystem::path(RAYGATE_SOURCE_DIR) / "adapters" /
                                       "cmake-path-tracer.json");
  EXPECT_EQ(shipped.images, ImageKind::monte_carlo);
}

TEST(AdapterLoad, LoadNamesAMissingFile) {
  TempDir dir;
  try {
    load_adapter(dir.path() / "none.json");
    FAIL() << "expected UsageError";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("none.json"), std::string::npos) << e.what();
  }
}

TEST(AdapterLoad, LoadPrefixesTheFilePath) {
  TempDir dir;
  const auto path = dir.path() / "bad.json";
  write_file_atomically(path, with(R"("tiemout_s": {})"));
  try {
    load_adapter(path);
    FAIL() << "expected UsageError";
  } catch (const UsageError& e) {
    EXPECT_EQ(std::string(e.what()), path.string() + ": $.tiemout_s: unknown key 'tiemout_s' " +
                                         "(did you mean 'timeout_s'?)");
  }
}

struct Broken {
  const char* what;
  std::string text;
  std::string message;  // after "adapters/x.json: ", or after "adapters/x.json" when it starts
                        // with ":LINE:COLUMN: " (what the JSON reader itself refuses)
};

// gtest prints the case's name, not its bytes, when one fails.
void PrintTo(const Broken& broken, std::ostream* os) { *os << broken.what; }

class BrokenAdapter : public testing::TestWithParam<Broken> {};

TEST_P(BrokenAdapter, GivesItsExactMessage) {
  const std::string& message = GetParam().message;
  EXPECT_EQ(error_of(GetParam().text), kOrigin + (message.starts_with(":") ? "" : ": ") + message);
}

INSTANTIATE_TEST_SUITE_P(
    Messages, BrokenAdapter,
    testing::Values(
        Broken{"unknown_key", with(R"("tiemout_s": {"run": 5})"),
               "$.tiemout_s: unknown key 'tiemout_s' (did you mean 'timeout_s'?)"},
        Broken{"unknown_key_far", with(R"("colour": 1)"),
               "$.colour: unknown key 'colour' (known keys: name, description, scene_format, "
               "source_dir, requires, build, run, stdin, cwd, image, env, timing, threads, "
               "pin_cpus, submodules, timeout_s, images)"},
        Broken{"unknown_nested_key", with(R"("timing": {"sorce": "process"})"),
               "$.timing.sorce: unknown key 'sorce' (did you mean 'source'?)"},
        Broken{"wrong_type_in_step", with(R"("build": [["make"], ["make", "-j", 8]])"),
               "$.build[1][2]: expected a string, found number 8"},
        Broken{"wrong_type_run", with("", R"("tracer {scene}")"),
               "$.run: expected an array, found string \"tracer {scene}\""},
        Broken{"wrong_type_bool", with(R"("pin_cpus": "yes")"),
               "$.pin_cpus: expected true or false, found string \"yes\""},
        Broken{"threads_float", with(R"("threads": 1.5)"),
               "$.threads: expected an integer, found number 1.5"},
        Broken{"missing_name",
               R"({"scene_format": "nff", "run": ["t", "{scene}"], "image": "{workdir}/a"})",
               "$: missing required key 'name'"},
        Broken{"missing_image", R"({"name": "t", "scene_format": "nff", "run": ["t", "{scene}"]})",
               "$: missing required key 'image'"},
        Broken{"bad_format",
               R"({"name": "t", "scene_format": "nfff", "run": ["t"], "image": "{image}"})",
               "$.scene_format: expected one of nff, pov, obj, pbrt, found \"nfff\" "
               "(did you mean 'nff'?)"},
        Broken{"bad_name",
               R"({"name": "my tracer", "scene_format": "nff", "run": ["t"], "image": "{image}"})",
               "$.name: 'my tracer' must be letters, digits, '.', '_' or '-' (it names folders)"},
        // A NUL would end the C string the argument becomes (issue 25, class 12): in run, a
        // build step, env, cwd, stdin and source_dir alike.
        Broken{"nul_in_run", with("", R"(["t", "{scene}", "-o\u0000x", "{image}"])"),
               "$.run[2]: contains a NUL character (\\u0000) at byte 2; a process argument, "
               "environment value or path ends at the first one, so the rest would be lost"},
        Broken{"nul_in_build", with(R"("build": [["make", "a\u0000b"]])"),
               "$.build[0][1]: contains a NUL character (\\u0000) at byte 1; a process "
               "argument, environment value or path ends at the first one, so the rest would "
               "be lost"},
        Broken{"nul_in_env", with(R"("env": {"OPT": "\u0000"})"),
               "$.env.OPT: contains a NUL character (\\u0000) at byte 0; a process argument, "
               "environment value or path ends at the first one, so the rest would be lost"},
        Broken{"nul_in_cwd", with(R"("cwd": "{workdir}\u0000/x")"),
               "$.cwd: contains a NUL character (\\u0000) at byte 9; a process argument, "
               "environment value or path ends at the first one, so the rest would be lost"},
        Broken{"nul_in_source_dir", with(R"("source_dir": "src\u0000")"),
               "$.source_dir: contains a NUL character (\\u0000) at byte 3; a process "
               "argument, environment value or path ends at the first one, so the rest would "
               "be lost"},
        Broken{"unknown_placeholder", with("", R"(["t", "-o", "{image}", "{scen}"])"),
               "$.run[3]: unknown placeholder '{scen}' (did you mean '{scene}'?)"},
        Broken{"unknown_placeholder_far", with("", R"(["t", "{scene}", "{image}", "{colour}"])"),
               "$.run[3]: unknown placeholder '{colour}' (known: {src}, {repo_root}, {build}, "
               "{jobs}, {threads}, {scene}, {image}, {workdir}, {raygate_source}, {scene_stem}, "
               "{width}, {height}, {seed})"},
        Broken{"unmatched_brace", with("", R"(["t", "{scene}", "{image", "{image}"])"),
               "$.run[2]: unmatched '{' (write '{{' for a literal brace)"},
        Broken{"scene_in_build", with(R"("build": [["make", "{scene}"]])"),
               "$.build[0][1]: placeholder '{scene}' is not available in build steps (available: "
               "{src}, {repo_root}, {build}, {jobs}, {raygate_source})"},
        Broken{"jobs_in_run", with("", R"(["t", "{scene}", "{image}", "-j{jobs}"])"),
               "$.run[3]: placeholder '{jobs}' is not available in run settings (available: "
               "{src}, {repo_root}, {build}, {threads}, {scene}, {image}, {workdir}, "
               "{raygate_source}, {scene_stem}, {width}, {height}, {seed})"},
        Broken{"monte_carlo_without_seed", with(R"("images": "monte-carlo")"),
               "$.run: \"images\": \"monte-carlo\" needs '{seed}' in run or env (e.g. "
               "\"--seed\", \"{seed}\"): every run must render with its own seed"},
        Broken{"seed_when_deterministic", with("", R"(["t", "{scene}", "{image}", "{seed}"])"),
               "$.run: '{seed}' is only given to \"images\": \"monte-carlo\" tracers; add "
               "that, or drop '{seed}'"},
        Broken{"bad_images_kind", with(R"("images": "montecarlo")"),
               "$.images: expected one of deterministic, monte-carlo, found \"montecarlo\" "
               "(did you mean 'monte-carlo'?)"},
        Broken{"placeholder_in_env", with(R"("env": {"N": "{job}"})"),
               "$.env.N: unknown placeholder '{job}' (did you mean '{jobs}'?)"},
        Broken{"missing_scene", with("", R"(["t", "-o", "{image}"])"),
               "$.run: the scene never reaches the tracer: put '{scene}' in run (or "
               "\"stdin\": \"{scene}\" for a tracer that reads standard input)"},
        Broken{"image_not_fresh", with("", R"(["t", "{scene}"])", R"("out.ppm")"),
               "$.image: must be '{image}' or a path under '{workdir}/' (both are fresh for "
               "every run, so an image left by an earlier run is never taken for this one), "
               "found \"out.ppm\""},
        Broken{"image_never_passed", with("", R"(["t", "{scene}"])"),
               "$.image: '{image}' is never given to the tracer: put '{image}' in run or env, "
               "or name the file the tracer writes, e.g. \"{workdir}/trace.ppm\""},
        Broken{"workdir_unknown",
               with(R"("cwd": "{build}")", R"(["t", "{scene}"])", R"("{workdir}/trace.ppm")"),
               "$.image: the tracer cannot know '{workdir}': run it there (\"cwd\": "
               "\"{workdir}\", the default) or pass '{workdir}' in run or env"},
        Broken{"bad_regex",
               with(R"("timing": {"source": "reported", "regex": "time: ([0-9.]+ s"})"),
               "$.timing.regex: does not compile: missing closing parenthesis at character 17"},
        Broken{"regex_without_group",
               with(R"("timing": {"source": "reported", "regex": "time: [0-9.]+"})"),
               "$.timing.regex: must have exactly one capture group (the number), found 0; "
               "write other groups as (?:...)"},
        Broken{"regex_missing", with(R"("timing": {"source": "reported"})"),
               "$.timing: missing required key 'regex'"},
        Broken{"regex_with_process", with(R"x("timing": {"regex": "([0-9]+)"})x"),
               "$.timing.regex: only used with \"source\": \"reported\""},
        Broken{"bad_timeout", with(R"("timeout_s": {"build": 0})"),
               "$.timeout_s.build: must be a positive number of seconds, found number 0"},
        Broken{"negative_timeout", with(R"("timeout_s": {"run": -5})"),
               "$.timeout_s.run: must be a positive number of seconds, found number -5"},
        Broken{"overflowing_timeout", with(R"("timeout_s": {"run": 1e10})"),
               "$.timeout_s.run: must be between 0.001 and 604800 seconds (one week), found "
               "number 10000000000.0"},
        Broken{"vanishing_timeout", with(R"("timeout_s": {"build": 1e-9})"),
               "$.timeout_s.build: must be between 0.001 and 604800 seconds (one week), found "
               "number 1e-09"},
        Broken{"duplicate_key", with(R"("run": ["u", "{scene}", "{image}"])"),
               ":1:94: $: duplicate key 'run' (JSON keeps only one of them; remove the other)"},
        Broken{"nested_duplicate_key",
               with(R"("build": [["make"], {"a": 1, "a": 2}], "timing": {"source": "process"})"),
               ":1:123: $.build[1]: duplicate key 'a' (JSON keeps only one of them; remove the "
               "other)"},
        Broken{"duplicate_env_key", with(R"("env": {"A": "1", "B": "2", "A": "3"})"),
               ":1:122: $.env: duplicate key 'A' (JSON keeps only one of them; remove the "
               "other)"},
        Broken{
            "name_too_long_for_a_file",
            R"({"name": ")" + std::string(300, 'n') +
                R"(", "scene_format": "nff", "run": ["t", "{scene}", "{image}"], "image": "{image}"})",
            "$.name: 'nnnnnnnnnnnnnnnnnnnn...' is 300 bytes long, more than the 64 allowed "
            "(it is part of cache folder names)"},
        Broken{
            "name_climbing_out",
            R"({"name": "../../x", "scene_format": "nff", "run": ["t", "{scene}", "{image}"], "image": "{image}"})",
            "$.name: '../../x' must be letters, digits, '.', '_' or '-' (it names folders)"},
        Broken{"zero_threads", with(R"("threads": 0)"),
               "$.threads: must be between 1 and 4096, found number 0"},
        Broken{"relative_cwd", with(R"("cwd": "out")"),
               "$.cwd: must start with {workdir}, {build}, {src}, {repo_root}, {raygate_source} "
               "or '/', found \"out\""},
        Broken{"bad_env_name", with(R"("env": {"OMP THREADS": "1"})"),
               "$.env[\"OMP THREADS\"]: 'OMP THREADS' is not a valid environment variable name "
               "(letters, digits and '_', not starting with a digit)"},
        // std::regex recursed a frame per character: these overflowed the stack (exit 139).
        Broken{
            "long_name",
            R"({"name": ")" + std::string(100000, 'a') +
                R"(", "scene_format": "nff", "run": ["t", "{scene}", "{image}"], "image": "{image}"})",
            "$.name: 'aaaaaaaaaaaaaaaaaaaa...' is 100000 bytes long, more than the 64 allowed "
            "(it is part of cache folder names)"},
        Broken{"long_package", with(R"("requires": [")" + std::string(100000, 'a') + R"("])"),
               "$.requires[0]: 'aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa... (100000 bytes)' is not "
               "a Debian package name (lower-case letters, digits, '+', '-' and '.')"},
        Broken{"long_env_name", with(R"("env": {")" + std::string(100000, 'A') + R"(": "1"})"),
               "$.env[\"AAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAA\"... (100000 bytes)]: "
               "'AAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAA... (100000 bytes)' is not a valid "
               "environment variable name (letters, digits and '_', not starting with a digit)"},
        Broken{"bad_package", with(R"("requires": ["libTBB"])"),
               "$.requires[0]: 'libTBB' is not a Debian package name (lower-case letters, "
               "digits, '+', '-' and '.')"},
        Broken{"source_dir_escapes", with(R"("source_dir": "../other")"),
               "$.source_dir: must be a folder inside the repository, found \"../other\""},
        Broken{"empty_step", with(R"("build": [[]])"),
               "$.build[0]: a command needs at least the program to run"},
        Broken{"not_an_object", "[1, 2]", "$: expected an object, found an array"},
        Broken{"bad_json", "{\n  \"name\": \"t\",\n  \"run\" [\"t\"]\n}",
               ":3:9: not JSON: syntax error while parsing object separator - unexpected '['; "
               "expected ':'"},
        Broken{"empty_file", " \n", "the file is empty (an adapter is a JSON object)"},
        Broken{"truncated", "{\"name\": \"t\",",
               ":1:14: not JSON: syntax error while parsing object key - unexpected end of "
               "input; expected string literal"},
        Broken{"overflowing_number", with(R"("threads": 1e400)"),
               ":1:105: $.threads: number 1e400 is out of range (a double holds magnitudes up "
               "to about 1.8e308)"}),
    [](const testing::TestParamInfo<Broken>& param_info) {
      return std::string(param_info.param.what);
    });

// A commit is untrusted: a source_dir that is a link in it would run the build steps in any
// folder the link names (a sweep: a build wrote into /tmp/.../victimdir).
TEST(AdapterLoad, ASourceDirThatIsALinkInTheCheckoutIsRefused) {
  TempDir dir;
  std::filesystem::create_directories(dir.path() / "repo" / "real" / "src");
  std::filesystem::create_directories(dir.path() / "victim");
  std::filesystem::create_directory_symlink(dir.path() / "victim", dir.path() / "repo" / "vlink");
  std::filesystem::create_directory_symlink("real", dir.path() / "repo" / "up");
  Adapter a = parse_adapter(with(R"("source_dir": "real/src")"), kOrigin);
  EXPECT_EQ(source_directory(a, dir.path() / "repo"), dir.path() / "repo" / "real" / "src");
  for (const char* linked : {"vlink", "up/src"}) {
    a.source_dir = linked;
    try {
      source_directory(a, dir.path() / "repo");
      ADD_FAILURE() << linked << " was followed";
    } catch (const UsageError& e) {
      EXPECT_NE(std::string(e.what()).find("is a symbolic link in this commit"), std::string::npos)
          << e.what();
    }
  }
}

}  // namespace
}  // namespace raygate
