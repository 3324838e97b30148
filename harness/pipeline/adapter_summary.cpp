#include "pipeline/adapter_summary.h"

#include <fmt/core.h>

#include <algorithm>
#include <vector>

#include "adapter/placeholders.h"
#include "builder/build_steps.h"

#include "runner/timing/timing_modes.h"

namespace raygate {
namespace {

std::string timing_line(const Timing& timing) {
  const TimingMode& mode = adapter_timing_mode(timing);
  if (!timing.regex.empty()) {
    const char* unit = timing.unit == TimeUnit::seconds        ? "seconds"
                       : timing.unit == TimeUnit::milliseconds ? "milliseconds"
                                                               : "[[hours:]minutes:]seconds";
    return fmt::format("{}: last line matching /{}/, group in {}", mode.description(), timing.regex,
                       unit);
  }
  if (!timing.metric_by_threads || mode.exact()) return std::string(mode.description());
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

std::string build_lines(const Adapter& a) {
  if (a.build.empty()) return "  build       (no steps: the tracer is already installed)\n";
  std::string out;
  for (std::size_t i = 0; i < a.build.size(); ++i) {
    out += fmt::format("  {:<11} {}. {}\n", i == 0 ? "build" : "", i + 1, argv_text(a.build[i]));
  }
  return out + fmt::format("  {:<11} timeout {} for the whole build\n", "",
                           seconds(a.timeouts.build_seconds));
}

std::string run_lines(const Adapter& a) {
  std::string out = fmt::format("  run         {}\n", argv_text(a.run));
  out += fmt::format("              timeout {} per run, in {}\n", seconds(a.timeouts.run_seconds),
                     a.cwd);
  if (a.stdin_template) out += fmt::format("  stdin       {}\n", *a.stdin_template);
  for (const auto& [key, value] : a.env) out += fmt::format("  env         {}={}\n", key, value);
  out += fmt::format("  image       {}\n", a.image);
  out += fmt::format("  images      {}\n", images_line(a.images));
  out += fmt::format("  timing      {}\n", timing_line(a.timing));
  out += fmt::format(
      "  threads     {}{}\n", a.threads,
      a.pin_cpus ? fmt::format(" (pinned to {} CPU{})", a.threads, a.threads == 1 ? "" : "s") : "");
  return out;
}

// Every template of the adapter: build steps, run, stdin, cwd, image and env values.
std::vector<std::string> templates_of(const Adapter& a) {
  std::vector<std::string> all;
  for (const std::vector<std::string>& step : a.build)
    all.insert(all.end(), step.begin(), step.end());
  all.insert(all.end(), a.run.begin(), a.run.end());
  if (a.stdin_template) all.push_back(*a.stdin_template);
  all.push_back(a.cwd);
  all.push_back(a.image);
  for (const auto& [key, value] : a.env) all.push_back(value);
  return all;
}

}  // namespace

std::string repository_unused_note(const Adapter& a) {
  for (const std::string& text : templates_of(a)) {
    for (const char* name : {"src", "repo_root", "build"}) {
      if (uses_placeholder(text, name)) return "";
    }
  }
  const bool own_files = std::ranges::any_of(templates_of(a), [](const std::string& text) {
    return uses_placeholder(text, "raygate_source");
  });
  return fmt::format(
      "adapter {} uses nothing from the repository (no {{src}}, {{repo_root}} or {{build}} in "
      "its commands){}: every revision runs the same program, so a compare measures no change "
      "of the repository's",
      a.name,
      own_files ? "; its script is raygate's own ({raygate_source}), not the repository's" : "");
}

std::string adapter_summary(const Adapter& a) {
  std::string out = fmt::format("{}: ok\n", a.file.string());
  out += fmt::format("  name        {}\n", a.name);
  if (!a.description.empty()) out += fmt::format("  description {}\n", a.description);
  out += fmt::format("  format      {} scenes\n", to_string(a.scene_format));
  out += fmt::format("  source      {}\n", a.source_dir.empty() ? "repository root" : a.source_dir);
  out +=
      fmt::format("  submodules  {}\n", a.submodules ? "re-synced for every commit" : "left alone");
  if (!a.packages.empty()) {
    std::string list;
    for (const std::string& p : a.packages) list += (list.empty() ? "" : " ") + p;
    out += fmt::format("  requires    {}\n", list);
  }
  out += build_lines(a);
  out += run_lines(a);
  if (const std::string note = repository_unused_note(a); !note.empty()) {
    out += fmt::format("  repository  {}\n", note);
  }
  return out + fmt::format("  hash        {}\n", adapter_hash(a));
}

}  // namespace raygate
