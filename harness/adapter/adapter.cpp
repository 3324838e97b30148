// Loading an adapter: JSON text -> checked fields -> cross-field rules -> Adapter. Each reader
// validates one key completely, so a message always names the key that is wrong.
#include "adapter/adapter.h"

#include <fmt/format.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <regex>

#include "core/json_field.h"
#include "adapter/placeholders.h"
#include "adapter/reported_time.h"
#include "core/suggest.h"
#include "core/enum_words.h"
#include "core/error.h"
#include "core/fs.h"
#include "core/json_reader.h"
#include "core/sha256.h"

namespace raygate {
namespace {

// The file's words for its enums, spelt once: read_enum offers them, to_string writes them.
constexpr EnumWords<SceneFormat, 4> kSceneFormatWords{{{SceneFormat::nff, "nff"},
                                                       {SceneFormat::pov, "pov"},
                                                       {SceneFormat::obj, "obj"},
                                                       {SceneFormat::pbrt, "pbrt"}}};
constexpr EnumWords<TimingSource, 3> kTimingSourceWords{{{TimingSource::process, "process"},
                                                         {TimingSource::reported, "reported"},
                                                         {TimingSource::simulated, "simulated"}}};
constexpr EnumWords<TimeUnit, 3> kTimeUnitWords{
    {{TimeUnit::seconds, "s"}, {TimeUnit::milliseconds, "ms"}, {TimeUnit::clock, "h:m:s"}}};
constexpr EnumWords<ImageKind, 2> kImageKindWords{
    {{ImageKind::deterministic, "deterministic"}, {ImageKind::monte_carlo, "monte-carlo"}}};

using nlohmann::json;

const std::vector<std::string>& top_level_keys() {
  static const std::vector<std::string> keys{
      "name",    "description", "scene_format", "source_dir", "requires", "build",
      "run",     "stdin",       "cwd",          "image",      "env",      "timing",
      "threads", "pin_cpus",    "submodules",   "timeout_s",  "images"};
  return keys;
}

std::string join(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& w : words) out += (out.empty() ? "" : ", ") + w;
  return out;
}

// std::regex matches by recursion, one frame per character: a 30,000-character name overflowed
// the stack (the fourth sweep). Names, package names and variable names are short; a text past
// kMaxMatched does not match, and its message quotes only its start (shown()).
constexpr std::size_t kMaxMatched = 256;

bool matches(const std::string& text, const char* pattern) {
  return text.size() <= kMaxMatched && std::regex_match(text, std::regex(pattern));
}

std::string shown(const std::string& text) {
  return text.size() <= 40 ? text
                           : fmt::format("{}... ({} bytes)", text.substr(0, 40), text.size());
}

// One of a fixed set of words; the index of the match.
std::size_t read_choice(const JsonField& field, const std::vector<std::string>& choices) {
  const std::string word = field.as_string();
  for (std::size_t i = 0; i < choices.size(); ++i) {
    if (choices[i] == word) return i;
  }
  std::string message = "expected one of " + join(choices) + ", found " + json(word).dump();
  if (const auto guess = closest_match(word, choices)) {
    message += " (did you mean '" + *guess + "'?)";
  }
  field.fail(message);
}

// One of an enum's words, offered in the table's order.
template <typename Enum, std::size_t N>
Enum read_enum(const JsonField& field, const EnumWords<Enum, N>& words) {
  std::vector<std::string> choices;
  for (const auto& [value, word] : words) choices.emplace_back(word);
  return words[read_choice(field, choices)].first;
}

// A string that reaches a process (argument, environment value, path): C strings end at the
// first NUL, so "\u0000" in one would cut it short without a word (issue 25, class 12).
std::string read_process_string(const JsonField& field) {
  std::string text = field.as_string();
  if (const std::size_t at = text.find('\0'); at != std::string::npos) {
    field.fail(
        fmt::format("contains a NUL character (\\u0000) at byte {}; a process argument, "
                    "environment value or path ends at the first one, so the rest "
                    "would be lost",
                    at));
  }
  return text;
}

std::string read_template(const JsonField& field, TemplateField where) {
  std::string text = read_process_string(field);
  if (const auto error = template_error(text, where)) field.fail(*error);
  return text;
}

std::vector<std::string> read_argv(const JsonField& field, TemplateField where) {
  std::vector<std::string> argv;
  for (const JsonField& element : field.elements()) argv.push_back(read_template(element, where));
  if (argv.empty()) field.fail("a command needs at least the program to run");
  if (argv[0].empty()) field.fail("the program name (first element) is empty");
  return argv;
}

constexpr std::size_t kMaxAdapterName = 64;

std::string read_name(const JsonField& field) {
  std::string name = field.as_string();
  // Build folders are "<name>-<sha>-<hash>" (builder/build_cache.h), so the name gets less
  // than the 128 bytes core/path_component.h allows any one file name.
  if (name.size() > kMaxAdapterName) {
    field.fail(
        fmt::format("'{}...' is {} bytes long, more than the {} allowed (it is part of "
                    "cache folder names)",
                    name.substr(0, 20), name.size(), kMaxAdapterName));
  }
  // It names cache folders, golden folders and result records, so it must be safe as a file
  // name: the rules of core/path_component.h, and shorter.
  if (!matches(name, "[A-Za-z0-9][A-Za-z0-9._-]*")) {
    field.fail("'" + name + "' must be letters, digits, '.', '_' or '-' (it names folders)");
  }
  return name;
}

std::string read_source_dir(const JsonField& field) {
  std::string dir = read_process_string(field);
  const std::filesystem::path path(dir);
  bool escapes = path.is_absolute();
  for (const auto& part : path) escapes = escapes || part == "..";
  if (escapes) field.fail("must be a folder inside the repository, found " + json(dir).dump());
  if (dir.find_first_of("{}") != std::string::npos) {
    field.fail("is a plain folder name; placeholders are not expanded here");
  }
  std::string normal = path.lexically_normal().generic_string();
  while (!normal.empty() && normal.back() == '/') normal.pop_back();
  return normal == "." ? "" : normal;
}

// A relative cwd would be relative to wherever raygate was started: never what was meant.
std::string read_cwd(const JsonField& field) {
  std::string cwd = read_template(field, TemplateField::run);
  for (const char* folder : {"{workdir}", "{build}", "{src}", "{repo_root}", "{raygate_source}"}) {
    if (cwd.rfind(folder, 0) == 0) return cwd;
  }
  if (cwd.empty() || cwd[0] != '/') {
    field.fail(
        "must start with {workdir}, {build}, {src}, {repo_root}, {raygate_source} or "
        "'/', found " +
        json(cwd).dump());
  }
  return cwd;
}

std::vector<std::string> read_packages(const JsonField& field) {
  std::vector<std::string> packages;
  for (const JsonField& element : field.elements()) {
    std::string package = element.as_string();
    // Debian policy §5.6.1, with an optional ":arch" qualifier.
    if (!matches(package, "[a-z0-9][a-z0-9+.-]+(:[a-z0-9-]+)?")) {
      element.fail("'" + shown(package) + "' is not a Debian package name (lower-case letters, " +
                   "digits, '+', '-' and '.')");
    }
    packages.push_back(std::move(package));
  }
  return packages;
}

std::vector<std::vector<std::string>> read_build(const JsonField& field) {
  std::vector<std::vector<std::string>> steps;
  for (const JsonField& step : field.elements()) {
    steps.push_back(read_argv(step, TemplateField::build));
  }
  return steps;
}

std::map<std::string, std::string> read_env(const JsonField& field) {
  std::map<std::string, std::string> env;
  for (const std::string& key : field.keys()) {
    const JsonField value = field.member(key);
    if (!matches(key, "[A-Za-z_][A-Za-z0-9_]*")) {
      value.fail("'" + shown(key) + "' is not a valid environment variable name (letters, digits " +
                 "and '_', not starting with a digit)");
    }
    env[key] = read_template(value, TemplateField::run);
  }
  return env;
}

Timing read_timing(const JsonField& field) {
  field.expect_object({"source", "metric", "regex", "unit"});
  Timing timing;
  if (field.has("source")) {
    timing.source = read_enum(field.member("source"), kTimingSourceWords);
  }
  const bool reported = timing.source == TimingSource::reported;
  if (!reported) {
    for (const char* key : {"regex", "unit"}) {
      if (field.has(key)) field.member(key).fail("only used with \"source\": \"reported\"");
    }
    if (field.has("metric") && timing.source == TimingSource::simulated) {
      field.member("metric").fail(
          "only used with \"source\": \"process\" (a simulated cost "
          "is counted, not timed)");
    }
    timing.metric_by_threads = true;
    if (field.has("metric")) {
      const std::size_t choice = read_choice(field.member("metric"), {"wall", "cpu", "auto"});
      timing.metric_by_threads = choice == 2;
      if (choice < 2) timing.metric = static_cast<TimingMetric>(choice);
    }
    return timing;
  }
  if (field.has("metric")) {
    field.member("metric").fail(
        "only used with \"source\": \"process\" (a reported time is "
        "whatever the tracer printed)");
  }
  const JsonField regex = field.member("regex");
  timing.regex = regex.as_string();
  if (const auto error = reported_regex_error(timing.regex)) regex.fail(*error);
  if (field.has("unit")) {
    timing.unit = read_enum(field.member("unit"), kTimeUnitWords);
  }
  return timing;
}

// The longest timeout accepted: a week. Anything longer is a typo or "never", and values far
// beyond it overflow the clock arithmetic (1e10 s in nanoseconds exceeds 64 bits), which once
// made every run "time out after 0.0 s".
constexpr double kMaxTimeoutSeconds = 7 * 24 * 3600;
// Timeouts are kept in milliseconds: anything shorter would round to 0, which means "none".
constexpr double kMinTimeoutSeconds = 0.001;

double read_positive_seconds(const JsonField& field) {
  const double seconds = field.as_number();
  if (!(seconds > 0) || !std::isfinite(seconds)) {
    field.fail("must be a positive number of seconds, found " + describe_json(field.value()));
  }
  if (seconds > kMaxTimeoutSeconds || seconds < kMinTimeoutSeconds) {
    field.fail("must be between 0.001 and 604800 seconds (one week), found " +
               describe_json(field.value()));
  }
  return seconds;
}

Timeouts read_timeouts(const JsonField& field) {
  field.expect_object({"build", "run"});
  Timeouts timeouts;
  if (field.has("build")) timeouts.build_seconds = read_positive_seconds(field.member("build"));
  if (field.has("run")) timeouts.run_seconds = read_positive_seconds(field.member("run"));
  return timeouts;
}

int read_threads(const JsonField& field) {
  const long long threads = field.as_integer();
  if (threads < 1 || threads > 4096) {
    field.fail("must be between 1 and 4096, found " + describe_json(field.value()));
  }
  return static_cast<int>(threads);
}

bool any_uses(const std::vector<std::string>& templates, std::string_view name) {
  for (const std::string& t : templates) {
    if (uses_placeholder(t, name)) return true;
  }
  return false;
}

// Everything the tracer sees of its invocation: argv and environment values.
std::vector<std::string> invocation(const Adapter& adapter) {
  std::vector<std::string> out = adapter.run;
  for (const auto& [key, value] : adapter.env) out.push_back(value);
  return out;
}

void check_scene_reaches_tracer(const JsonField& root, const Adapter& adapter) {
  const bool via_stdin =
      adapter.stdin_template && uses_placeholder(*adapter.stdin_template, "scene");
  if (via_stdin || any_uses(invocation(adapter), "scene")) return;
  root.member("run").fail(
      "the scene never reaches the tracer: put '{scene}' in run (or "
      "\"stdin\": \"{scene}\" for a tracer that reads standard input)");
}

// The image must be found where this run wrote it and nowhere an earlier run could have left
// one: {image} and {workdir} both live in a directory created empty for each run.
void check_image(const JsonField& root, const Adapter& adapter) {
  const JsonField field = root.member("image");
  const std::string& image = adapter.image;
  const bool at_image = image.rfind("{image}", 0) == 0;
  const bool in_workdir = image.rfind("{workdir}/", 0) == 0;
  bool climbs = false;
  for (const auto& part : std::filesystem::path(image)) climbs = climbs || part == "..";
  if ((!at_image && !in_workdir) || climbs) {
    field.fail(
        "must be '{image}' or a path under '{workdir}/' (both are fresh for every run, so "
        "an image left by an earlier run is never taken for this one), found " +
        json(image).dump());
  }
  if (at_image && !any_uses(invocation(adapter), "image")) {
    field.fail(
        "'{image}' is never given to the tracer: put '{image}' in run or env, or name "
        "the file the tracer writes, e.g. \"{workdir}/trace.ppm\"");
  }
  if (in_workdir && !uses_placeholder(adapter.cwd, "workdir") &&
      !any_uses(invocation(adapter), "workdir")) {
    field.fail(
        "the tracer cannot know '{workdir}': run it there (\"cwd\": \"{workdir}\", the "
        "default) or pass '{workdir}' in run or env");
  }
}

ImageKind read_image_kind(const JsonField& field) { return read_enum(field, kImageKindWords); }

// A Monte Carlo tracer must get a different seed for every run, or its runs are one sample
// repeated and their noise cannot be measured; a deterministic one has no use for a seed.
void check_seed(const JsonField& root, const Adapter& adapter) {
  const bool seeded = any_uses(invocation(adapter), "seed") ||
                      (adapter.stdin_template && uses_placeholder(*adapter.stdin_template, "seed"));
  if (adapter.images == ImageKind::monte_carlo && !seeded) {
    root.member("run").fail(
        "\"images\": \"monte-carlo\" needs '{seed}' in run or env (e.g. "
        "\"--seed\", \"{seed}\"): every run must render with its own seed");
  }
  if (adapter.images == ImageKind::deterministic && seeded) {
    root.member("run").fail(
        "'{seed}' is only given to \"images\": \"monte-carlo\" tracers; "
        "add that, or drop '{seed}'");
  }
}

Adapter read_fields(const JsonField& root) {
  root.expect_object(top_level_keys());
  Adapter a;
  a.name = read_name(root.member("name"));
  if (root.has("description")) a.description = root.member("description").as_string();
  a.scene_format = read_enum(root.member("scene_format"), kSceneFormatWords);
  if (root.has("source_dir")) a.source_dir = read_source_dir(root.member("source_dir"));
  if (root.has("requires")) a.packages = read_packages(root.member("requires"));
  if (root.has("build")) a.build = read_build(root.member("build"));
  a.run = read_argv(root.member("run"), TemplateField::run);
  if (root.has("stdin")) a.stdin_template = read_template(root.member("stdin"), TemplateField::run);
  if (root.has("cwd")) a.cwd = read_cwd(root.member("cwd"));
  a.image = read_template(root.member("image"), TemplateField::run);
  if (root.has("images")) a.images = read_image_kind(root.member("images"));
  if (root.has("env")) a.env = read_env(root.member("env"));
  a.timing.metric_by_threads = true;
  if (root.has("timing")) a.timing = read_timing(root.member("timing"));
  if (root.has("threads")) a.threads = read_threads(root.member("threads"));
  if (a.timing.metric_by_threads) {
    a.timing.metric = a.threads > 1 ? TimingMetric::wall : TimingMetric::cpu;
  }
  if (root.has("pin_cpus")) a.pin_cpus = root.member("pin_cpus").as_bool();
  if (root.has("submodules")) a.submodules = root.member("submodules").as_bool();
  if (root.has("timeout_s")) a.timeouts = read_timeouts(root.member("timeout_s"));
  check_scene_reaches_tracer(root, a);
  check_image(root, a);
  check_seed(root, a);
  return a;
}

}  // namespace

Adapter parse_adapter(std::string_view text, const std::string& origin) {
  if (text.find_first_not_of(" \t\r\n") == std::string_view::npos) {
    throw UsageError(origin + ": the file is empty (an adapter is a JSON object)");
  }
  const json document = parse_json_input(text, origin);  // core/json_reader.h
  try {
    Adapter adapter = read_fields(JsonField(document, "$"));
    adapter.file = origin;
    adapter.canonical = document.dump();  // nlohmann's objects are std::map: keys sorted
    return adapter;
  } catch (const FieldError& e) {
    throw UsageError(origin + ": " + e.path() + ": " + e.what());
  }
}

Adapter load_adapter(const std::filesystem::path& path) {
  return parse_adapter(read_json_text(path), path.string());
}

std::string adapter_hash(const Adapter& adapter) { return sha256_hex(adapter.canonical); }

std::filesystem::path source_directory(const Adapter& adapter,
                                       const std::filesystem::path& repo_root) {
  if (adapter.source_dir.empty()) return repo_root;
  std::filesystem::path folder = repo_root;
  for (const std::filesystem::path& part : std::filesystem::path(adapter.source_dir)) {
    if (part.empty() || part == ".") continue;
    folder /= part;
    std::error_code error;
    if (std::filesystem::is_symlink(std::filesystem::symlink_status(folder, error))) {
      throw UsageError(fmt::format(
          "source_dir \"{}\": {} is a symbolic link in this commit (to {}); the build runs in "
          "a folder inside the repository only",
          adapter.source_dir, (folder.lexically_relative(repo_root)).string(),
          std::filesystem::read_symlink(folder, error).string()));
    }
  }
  return repo_root / adapter.source_dir;
}

std::string_view to_string(SceneFormat format) { return word_of(kSceneFormatWords, format, "?"); }

std::string_view to_string(TimingSource source) { return word_of(kTimingSourceWords, source, "?"); }

std::string_view to_string(TimingMetric metric) {
  return metric == TimingMetric::wall ? "wall" : "cpu";
}

std::string_view to_string(TimeUnit unit) { return word_of(kTimeUnitWords, unit, "ms"); }

std::string_view to_string(ImageKind kind) {
  return word_of(kImageKindWords, kind, "deterministic");
}

}  // namespace raygate
