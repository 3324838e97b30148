// `raygate adapter check FILE...`: validates adapter files and shows what raygate will run,
// placeholders and all, so a user can read an adapter back before a CI job trips over it.
// Exit 0 when every file is valid, 2 when any is not (each problem is printed, not just the
// first file's). Missing Debian packages are a warning: the build may still find its tools.
#include <fmt/core.h>

#include <memory>
#include <string>
#include <vector>

#include "adapter/adapter.h"
#include "adapter/packages.h"
#include "cli/commands.h"
#include "core/error.h"
#include "core/exit_codes.h"
#include "runner/timing/timing_modes.h"

namespace raygate::cli {
namespace {

// Shell-style quoting for display only (nothing is ever run through a shell): an element with
// spaces or shell syntax is shown quoted, so the argv boundaries are visible.
std::string quoted(const std::string& arg) {
  const bool plain = !arg.empty() && arg.find_first_of(" \t\n'\"\\$`;&|<>()*?![]#~") ==
                                         std::string::npos;
  if (plain) return arg;
  std::string out = "'";
  for (const char c : arg) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string command_line(const std::vector<std::string>& argv) {
  std::string out;
  for (const std::string& arg : argv) out += (out.empty() ? "" : " ") + quoted(arg);
  return out;
}

std::string timing_line(const Timing& timing) {
  const TimingMode& mode = adapter_timing_mode(timing);
  if (!timing.regex.empty()) {
    const char* unit = timing.unit == TimeUnit::seconds ? "seconds" : "milliseconds";
    return fmt::format("{}: last line matching /{}/, group in {}", mode.description(),
                       timing.regex, unit);
  }
  if (!timing.metric_by_threads || mode.counted()) return std::string(mode.description());
  return fmt::format("{} (metric auto: {})", mode.description(),
                     timing.metric == TimingMetric::wall
                         ? "threads > 1, so wall time, which shows the parallel speed-up"
                         : "one thread, so CPU time, which a busy runner does not inflate by "
                           "the time spent waiting for a CPU");
}

// What "images" means for how the pictures are judged.
std::string images_line(ImageKind kind) {
  if (kind == ImageKind::monte_carlo) {
    return "monte-carlo: every run renders with its own {seed}; the runs' images are judged "
           "on whether they converge to the same picture as the reference (per tile, within "
           "noise, docs/monte-carlo-images.md)";
  }
  return "deterministic: the same pixels every run; judged per pixel against the reference "
         "(docs/gate.md)";
}

std::string seconds(double s) { return fmt::format("{:g} s", s); }

void print_build(const Adapter& a) {
  if (a.build.empty()) {
    fmt::print("  build       (no steps: the tracer is already installed)\n");
    return;
  }
  for (std::size_t i = 0; i < a.build.size(); ++i) {
    fmt::print("  {:<11} {}. {}\n", i == 0 ? "build" : "", i + 1, command_line(a.build[i]));
  }
  fmt::print("  {:<11} timeout {} for the whole build\n", "", seconds(a.timeouts.build_seconds));
}

void print_run(const Adapter& a) {
  fmt::print("  run         {}\n", command_line(a.run));
  fmt::print("              timeout {} per run, in {}\n", seconds(a.timeouts.run_seconds), a.cwd);
  if (a.stdin_template) fmt::print("  stdin       {}\n", *a.stdin_template);
  for (const auto& [key, value] : a.env) fmt::print("  env         {}={}\n", key, value);
  fmt::print("  image       {}\n", a.image);
  fmt::print("  images      {}\n", images_line(a.images));
  fmt::print("  timing      {}\n", timing_line(a.timing));
  fmt::print("  threads     {}{}\n", a.threads,
             a.pin_cpus ? fmt::format(" (pinned to {} CPU{})", a.threads, a.threads == 1 ? "" : "s")
                        : "");
}

void print_summary(const Adapter& a) {
  fmt::print("{}: ok\n", a.file.string());
  fmt::print("  name        {}\n", a.name);
  if (!a.description.empty()) fmt::print("  description {}\n", a.description);
  fmt::print("  format      {} scenes\n", to_string(a.scene_format));
  fmt::print("  source      {}\n", a.source_dir.empty() ? "repository root" : a.source_dir);
  fmt::print("  submodules  {}\n", a.submodules ? "re-synced for every commit" : "left alone");
  if (!a.packages.empty()) {
    std::string list;
    for (const std::string& p : a.packages) list += (list.empty() ? "" : " ") + p;
    fmt::print("  requires    {}\n", list);
  }
  print_build(a);
  print_run(a);
  fmt::print("  hash        {}\n", adapter_hash(a));
}

void warn_missing_packages(const Adapter& a) {
  try {
    const std::vector<std::string> missing = missing_packages(a);
    if (missing.empty()) return;
    std::string list;
    for (const std::string& p : missing) list += (list.empty() ? "" : ", ") + p;
    fmt::print(stderr, "raygate: warning: {}: Debian packages not installed: {}\n",
               a.file.string(), list);
    fmt::print(stderr, "  install them with: {}\n", apt_get_line(missing));
  } catch (const InfraError& e) {
    fmt::print(stderr, "raygate: warning: {}: cannot check \"requires\": {}\n", a.file.string(),
               e.what());
  }
}

int run_check(const std::vector<std::string>& files) {
  int invalid = 0;
  for (const std::string& file : files) {
    try {
      const Adapter adapter = load_adapter(file);
      print_summary(adapter);
      warn_missing_packages(adapter);
    } catch (const UsageError& e) {
      fmt::print(stderr, "raygate: error: {}\n", e.what());
      ++invalid;
    }
  }
  return invalid == 0 ? to_int(ExitCode::pass) : to_int(ExitCode::usage);
}

}  // namespace

void add_adapter_command(CLI::App& app, int& exit_code) {
  CLI::App* adapter = app.add_subcommand("adapter", "Work with adapter files (adapters/README.md)");
  adapter->require_subcommand(1);
  auto files = std::make_shared<std::vector<std::string>>();
  CLI::App* check = adapter->add_subcommand(
      "check", "Validate adapter files and show the commands raygate would run");
  check->add_option("files", *files, "Adapter JSON files")->required();
  check->callback([files, &exit_code] { exit_code = run_check(*files); });
}

}  // namespace raygate::cli
