#include "report/counters_line.h"

#include <fmt/core.h>

#include <algorithm>
#include <map>
#include <vector>

namespace raygate {
namespace {

struct Readings {
  std::string unit;
  std::vector<double> values;
  std::vector<double> wall_seconds;  // of the same runs
};

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

std::string value_text(double value, const std::string& unit) {
  if (unit == "seconds") return fmt::format("{:.3f} s", value);
  return fmt::format("{:.4g} {}", value, unit);
}

// Counter name -> role -> its readings, over every successful run of every round.
using ByCounter = std::map<std::string, std::map<std::string, Readings>>;

ByCounter collect(const ResultsDocument& document) {
  ByCounter found;
  for (const SceneResult& scene : document.scenes) {
    for (const Round& round : scene.runs.rounds) {
      for (const auto& [role, run] : round.runs) {
        if (!run.ok) continue;
        for (const auto& [name, counter] : run.counters) {
          Readings& readings = found[name][role];
          readings.unit = counter.unit;
          readings.values.push_back(counter.value);
          readings.wall_seconds.push_back(run.wall_seconds);
        }
      }
    }
  }
  return found;
}

std::string role_text(const std::string& role, const Readings& readings) {
  const double value = median(readings.values);
  std::string text = fmt::format("{} {}", role, value_text(value, readings.unit));
  const double wall = median(readings.wall_seconds);
  if (readings.unit == "seconds" && wall > 0.0) {
    text += fmt::format(" ({:.0f}% of its process wall time)", 100.0 * value / wall);
  }
  return text;
}

}  // namespace

std::string counters_line(const ResultsDocument& document) {
  std::string line;
  for (const auto& [name, roles] : collect(document)) {
    if (!line.empty()) line += "; ";
    line += name + " (median per run):";
    bool first = true;
    for (const auto& [role, readings] : roles) {
      line += (first ? " " : ", ") + role_text(role, readings);
      first = false;
    }
  }
  return line;
}

}  // namespace raygate
