// What a long measurement says while it runs. On a terminal: one line, rewritten in place
// ("[3/13] mount  round 7  ratio 0.512 ±0.8%  ETA 1m40s"). Elsewhere (CI logs): one plain line
// per finished scene, nothing rewritten, so logs stay readable.
#pragma once

#include <cstdio>
#include <string>

namespace raygate::cli {

struct ProgressState {
  std::size_t scene_index = 0;  // 1-based
  std::size_t scene_count = 0;
  std::string scene_id;
  std::size_t round = 0;
  double ratio = 0.0;                // 0 until known
  double relative_half_width = 0.0;  // of the ratio's 95% CI
  double eta_seconds = -1.0;         // < 0: unknown
};

class Progress {
 public:
  // interactive: rewrite one line (use is_terminal(stream) to decide). A null stream says
  // nothing (--quiet).
  Progress(std::FILE* stream, bool interactive) : stream_(stream), interactive_(interactive) {}
  ~Progress();

  void update(const ProgressState& state);
  // A finished scene's line; on a terminal it replaces the progress line.
  void line(const std::string& text);

 private:
  void clear();
  std::FILE* stream_;
  bool interactive_;
  bool dirty_ = false;  // a progress line is on screen
};

bool is_terminal(std::FILE* stream);
// "1m40s", "12s", "2h03m".
std::string format_duration(double seconds);

}  // namespace raygate::cli
