// The machine-drift rule over stored measurements.
#include "store/drift.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "store/store_rows.h"

namespace raygate {

namespace {

bool usable(const HistoryRow& row) {
  return row.ratio && row.baseline_median_seconds && *row.ratio > 0.0 &&
         *row.baseline_median_seconds > 0.0;
}

auto measured_order(const HistoryRow& row) {
  return std::make_pair(parse_iso8601_unix(row.measured_at).value_or(0), row.document_id);
}

const HistoryRow* latest_usable(const std::vector<HistoryRow>& rows) {
  const HistoryRow* latest = nullptr;
  for (const HistoryRow& row : rows) {
    if (usable(row) && (!latest || measured_order(row) > measured_order(*latest))) latest = &row;
  }
  return latest;
}

bool same_machine_and_baseline(const HistoryRow& a, const HistoryRow& b) {
  return a.machine_hostname == b.machine_hostname && a.machine_cpu_model == b.machine_cpu_model &&
         a.baseline_sha256 == b.baseline_sha256;
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2.0;
}

double relative_half_width(const HistoryRow& row) {
  if (!row.ratio_lower || !row.ratio_upper) return 0.0;
  return (*row.ratio_upper - *row.ratio_lower) / 2.0 / *row.ratio;
}

// The scene of the latest document against the earlier history of the same machine; nullopt
// when there is none.
std::optional<SceneDrift> scene_drift(const HistoryRow& latest,
                                      const std::vector<HistoryRow>& rows) {
  std::vector<double> baselines;
  std::vector<double> ratios;
  for (const HistoryRow& row : rows) {
    // Only the same series (results/series.h): another tracer's ratios or another scene size's
    // seconds are not this series' history.
    if (!usable(row) || row.scene_id != latest.scene_id || row.series_id != latest.series_id ||
        row.role != latest.role || !same_machine_and_baseline(row, latest) ||
        measured_order(row) >= measured_order(latest)) {
      continue;
    }
    baselines.push_back(*row.baseline_median_seconds);
    ratios.push_back(*row.ratio);
  }
  if (baselines.empty()) return std::nullopt;
  SceneDrift drift;
  drift.scene_id = latest.scene_id;
  drift.baseline_change = *latest.baseline_median_seconds / median(baselines) - 1.0;
  drift.ratio_change = *latest.ratio / median(ratios) - 1.0;
  drift.baseline_moved = std::abs(drift.baseline_change) > kDriftBaselineFraction;
  drift.ratio_held = std::abs(drift.ratio_change) <=
                     std::max(kDriftRatioHeldFraction, relative_half_width(latest));
  return drift;
}

}  // namespace

std::optional<MachineDrift> detect_machine_drift(const std::vector<HistoryRow>& measurements) {
  const HistoryRow* latest = latest_usable(measurements);
  if (!latest) return std::nullopt;
  MachineDrift drift;
  drift.hostname = latest->machine_hostname;
  drift.cpu_model = latest->machine_cpu_model;
  drift.document_id = latest->document_id;
  drift.short_sha = latest->short_sha;
  for (const HistoryRow& row : measurements) {
    if (row.document_id != latest->document_id || !usable(row)) continue;
    if (auto scene = scene_drift(row, measurements)) drift.scenes.push_back(*scene);
  }
  drift.scenes_compared = drift.scenes.size();
  std::vector<double> faster;
  std::vector<double> slower;
  for (const SceneDrift& scene : drift.scenes) {
    if (!scene.baseline_moved || !scene.ratio_held) continue;
    (scene.baseline_change < 0 ? faster : slower).push_back(scene.baseline_change);
  }
  const std::vector<double>& drifted = faster.size() >= slower.size() ? faster : slower;
  if (drift.scenes_compared == 0 || drifted.size() * 2 <= drift.scenes_compared) {
    return std::nullopt;
  }
  drift.scenes_drifted = drifted.size();
  drift.median_baseline_change = median(drifted);
  return drift;
}

std::string describe_drift(const MachineDrift& drift) {
  return fmt::format(
      "machine drift: on {} ({}) the baseline took {:.1f}% {} time than in this machine's "
      "earlier results on {} of {} scenes while the normalized ratios held (document {}, {}): "
      "the machine got {}, not the code",
      drift.hostname.empty() ? "an unnamed host" : drift.hostname,
      drift.cpu_model.empty() ? "unknown CPU" : drift.cpu_model,
      std::abs(drift.median_baseline_change) * 100.0, drift.faster() ? "less" : "more",
      drift.scenes_drifted, drift.scenes_compared, drift.document_id, drift.short_sha,
      drift.faster() ? "faster" : "slower");
}

}  // namespace raygate
