#include "pipeline/terminal_progress.h"

#include <fmt/core.h>
#include <unistd.h>

#include <cmath>

#include "core/sanitize.h"

namespace raygate {

namespace {

// TerminalProgress is for whoever watches. When nobody can (the terminal was closed: writes fail with
// EIO), it is dropped; fmt::print would throw, and from the destructor that ends raygate with
// SIGABRT instead of the hang-up's exit code and the line saying what was kept.
void put(std::FILE* stream, const std::string& text) {
  std::fputs(text.c_str(), stream);
  std::fflush(stream);
}

}  // namespace

TerminalProgress::~TerminalProgress() { clear(); }

void TerminalProgress::clear() {
  if (stream_ != nullptr && interactive_ && dirty_) {
    put(stream_, "\r\033[K");
    dirty_ = false;
  }
}

void TerminalProgress::update(const ProgressState& s) {
  if (stream_ == nullptr || !interactive_) return;  // CI logs get the per-scene lines only
  std::string text =
      fmt::format("[{}/{}] {:<10} round {:>2}", s.scene_index, s.scene_count, s.scene_id, s.round);
  if (s.ratio > 0.0) {
    text += fmt::format("  ratio {:.3f} ±{:.1f}%", s.ratio, 100.0 * s.relative_half_width);
  }
  if (s.eta_seconds >= 0.0) text += "  ETA " + format_duration(s.eta_seconds);
  put(stream_, "\r\033[K" + terminal_text(text));
  dirty_ = true;
}

void TerminalProgress::line(const std::string& text) {
  if (stream_ == nullptr) return;
  clear();
  put(stream_, terminal_text(text) + "\n");  // subjects are the commit author's bytes
}

void TerminalProgress::status(const std::string& text) { line(text); }

std::string format_duration(double seconds) {
  const long total = std::lround(std::max(0.0, seconds));
  if (total < 60) return fmt::format("{}s", total);
  if (total < 3600) return fmt::format("{}m{:02}s", total / 60, total % 60);
  return fmt::format("{}h{:02}m", total / 3600, (total % 3600) / 60);
}

}  // namespace raygate
