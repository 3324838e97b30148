// An adapter: how raygate builds one ray tracer's revision and runs it on one scene
// (DESIGN.md §5, adapters/README.md). This header is the record every later stage reads; the
// JSON file is parsed and fully validated once, here, so the builder and runner never see an
// adapter that can fail for a reason the user could have been told about up front.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace raygate {

enum class SceneFormat { nff, pov, obj, pbrt };

enum class TimingSource {
  process,    // measured by raygate from wait4 (wall or user+sys CPU)
  reported,   // parsed from the tracer's own output with a regex
  simulated,  // estimated cycles counted by Valgrind's cachegrind (docs/simulated-timing.md)
};
enum class TimingMetric { wall, cpu };  // for TimingSource::process
// For TimingSource::reported: the captured number's unit. clock: "[[h:]m:]s", as Blender prints
// its render time ("Time: 00:01.23").
enum class TimeUnit { seconds, milliseconds, clock };

// What kind of images the tracer makes ("images" in the file): the same pixels every run, judged
// by the per-pixel rule, or Monte Carlo renders whose noise changes with the seed, judged by
// whether they converge to the same image (docs/monte-carlo-images.md).
enum class ImageKind { deterministic, monte_carlo };

struct Timing {
  TimingSource source = TimingSource::process;
  TimingMetric metric = TimingMetric::wall;
  // "metric": "auto" (the default in adapter files): `metric` follows the adapter's threads,
  // CPU seconds for one thread, wall seconds for more. On a shared runner a process waits for a
  // CPU as long as its neighbours keep it busy; CPU time does not count that wait, and only
  // wall time shows a multi-threaded tracer's speed-up.
  bool metric_by_threads = false;
  std::string regex;  // reported only: ECMAScript, exactly one capture group (the number)
  TimeUnit unit = TimeUnit::seconds;
  bool operator==(const Timing&) const = default;
};

struct Timeouts {
  double build_seconds = 1800;  // for the whole build, all steps together
  double run_seconds = 600;     // for one run of the tracer on one scene
  bool operator==(const Timeouts&) const = default;
};

// Templates (strings holding placeholders) are kept unexpanded; see placeholders.h.
struct Adapter {
  std::filesystem::path file;  // where it was loaded from, for messages
  std::string name;
  std::string description;
  SceneFormat scene_format = SceneFormat::nff;
  std::string source_dir;                       // relative to the repository root; "" = root
  std::vector<std::string> packages;            // "requires": Debian packages the build needs
  std::vector<std::vector<std::string>> build;  // argv per step, in order
  std::vector<std::string> run;                 // argv of one run
  std::optional<std::string> stdin_template;    // "stdin": file fed on standard input
  std::string cwd = "{workdir}";                // working directory of the run
  std::string image;                            // where the image appears after a run
  ImageKind images = ImageKind::deterministic;
  std::map<std::string, std::string> env;  // extra environment of the run
  Timing timing;
  int threads = 1;         // passed as {threads}
  bool pin_cpus = false;   // raygate pins the run to `threads` CPUs
  bool submodules = true;  // re-sync submodules for every commit
  Timeouts timeouts;
  std::string canonical;  // the document with sorted keys and no whitespace (adapter_hash)

  bool operator==(const Adapter&) const = default;
};

// Parses and validates adapter JSON. `origin` (usually the file path) starts every message:
// "adapters/x.json: $.run[3]: unknown placeholder '{scen}' (did you mean '{scene}'?)".
// Throws UsageError for anything wrong with the text.
Adapter parse_adapter(std::string_view text, const std::string& origin);

// Reads and parses an adapter file; a missing or unreadable file is a UsageError too.
Adapter load_adapter(const std::filesystem::path& path);

// SHA-256 (hex) of the canonical document: the same for any whitespace or key order, different
// when any value changes. Builds are cached by (commit, adapter hash).
std::string adapter_hash(const Adapter& adapter);

// The folder {src} stands for: the repository root, or its source_dir subfolder. A UsageError
// when a folder on the way to it is a symbolic link in the checkout: the commit is untrusted,
// and a link would send the build steps anywhere, as the `..` read_source_dir refuses would.
std::filesystem::path source_directory(const Adapter& adapter,
                                       const std::filesystem::path& repo_root);

// The run time a tracer printed, in seconds, for timing.source "reported": the last match of
// the regex in `output` (a tracer that prints progress prints its total last), converted from
// the adapter's unit. nullopt if nothing matched or the capture is not a finite number >= 0.
// Throws RegexTooCostly (adapter/timing_regex.h) when the pattern backtracks past its bound.
std::optional<double> parse_reported_seconds(const Adapter& adapter, std::string_view output);

// Names as written in adapter files ("nff", "process", "wall", "s").
std::string_view to_string(SceneFormat format);
std::string_view to_string(TimingSource source);
std::string_view to_string(TimingMetric metric);
std::string_view to_string(TimeUnit unit);
std::string_view to_string(ImageKind kind);  // "deterministic", "monte-carlo"

}  // namespace raygate
