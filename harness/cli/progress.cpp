#include "cli/progress.h"

#include <fmt/core.h>
#include <unistd.h>

#include <cmath>

#include "core/sanitize.h"

namespace raygate::cli {

Progress::~Progress() { clear(); }

void Progress::clear() {
  if (stream_ != nullptr && interactive_ && dirty_) {
    fmt::print(stream_, "\r\033[K");
    std::fflush(stream_);
    dirty_ = false;
  }
}

void Progress::update(const ProgressState& s) {
  if (stream_ == nullptr || !interactive_) return;  // CI logs get the per-scene lines only
  std::string text = fmt::format("[{}/{}] {:<10} round {:>2}", s.scene_index, s.scene_count,
                                 s.scene_id, s.round);
  if (s.ratio > 0.0) {
    text += fmt::format("  ratio {:.3f} ±{:.1f}%", s.ratio, 100.0 * s.relative_half_width);
  }
  if (s.eta_seconds >= 0.0) text += "  ETA " + format_duration(s.eta_seconds);
  fmt::print(stream_, "\r\033[K{}", terminal_text(text));
  std::fflush(stream_);
  dirty_ = true;
}

void Progress::line(const std::string& text) {
  if (stream_ == nullptr) return;
  clear();
  fmt::print(stream_, "{}\n", terminal_text(text));  // subjects are the commit author's bytes
  std::fflush(stream_);
}

void Progress::status(const std::string& text) { line(text); }

bool is_terminal(std::FILE* stream) { return ::isatty(::fileno(stream)) == 1; }

std::string format_duration(double seconds) {
  const long total = std::lround(std::max(0.0, seconds));
  if (total < 60) return fmt::format("{}s", total);
  if (total < 3600) return fmt::format("{}m{:02}s", total / 60, total % 60);
  return fmt::format("{}h{:02}m", total / 3600, (total % 3600) / 60);
}

}  // namespace raygate::cli
