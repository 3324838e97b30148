#include "measure/compare_budget.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace raygate {

double scene_time_share(double budget_seconds, double elapsed_seconds, std::size_t scenes_left) {
  if (scenes_left == 0) throw std::invalid_argument("scene_time_share: no scenes left");
  if (budget_seconds <= 0.0) return std::numeric_limits<double>::infinity();
  return std::max(0.0, budget_seconds - elapsed_seconds) / static_cast<double>(scenes_left);
}

}  // namespace raygate
