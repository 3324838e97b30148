// Series keys from a results document.
#include "results/series.h"

#include <fmt/core.h>

#include "checkout/remote_cache.h"
#include "checkout/repository_identity.h"
#include "core/sha256.h"

namespace raygate {

std::string SeriesKey::id() const {
  // A separator that no part contains keeps ("ab", "c") and ("a", "bc") apart.
  std::string text = fmt::format("{}\n{}\n{}\n{}\n{}\n{}\n{}", repository, adapter, suite, scene,
                                 settings, timing, baseline);
  // Appended only when known, so stored rows of older documents keep their series.
  if (!measurement.empty()) text += "\nmeasurement " + measurement;
  return sha256_hex(text).substr(0, 16);
}

std::string repository_key(const RevisionRecord& revision) {
  if (!revision.repository_id.empty()) return revision.repository_id;
  if (revision.repository.empty()) return "unknown";
  if (is_url(revision.repository)) return "url:" + normalize_remote_url(revision.repository);
  return "path:" + std::filesystem::path(revision.repository).lexically_normal().string();
}

std::string scene_settings(const SuiteScene& entry, const BaselineRecord& baseline) {
  return fmt::format("scene={} size={} {}x{} sampling={}", entry.scene, entry.size, entry.width,
                     entry.height, baseline.sampling);
}

// The tracer's clock and the baseline's. Documents since the clocks were matched (issue 18) name
// the tracer's in settings.tracer_clock; older ones only have the metric (wall/cpu), which with
// their baseline timing ("in-process") keeps them a series of their own.
std::string timing_identity(const ResultsDocument& document) {
  const MeasurementSettings& s = document.settings;
  std::string tracer = s.tracer_clock.value_or("");
  if (tracer.empty()) tracer = s.metric.value_or("");
  return (tracer.empty() ? "-" : tracer) + " " + document.baseline.timing;
}

std::string baseline_identity(const BaselineRecord& baseline) {
  return baseline.source_sha256 + " accel=" + baseline.accel;
}

SeriesKey series_key(const ResultsDocument& document, const RevisionRecord& revision,
                     const SceneResult& scene) {
  return {repository_key(revision),
          revision.adapter_name,
          document.suite,
          scene.entry.id,
          scene_settings(scene.entry, document.baseline),
          timing_identity(document),
          baseline_identity(document.baseline),
          revision.adapter_measurement};
}

std::string unknown_series_id(std::int64_t document_id) {
  return fmt::format("unknown-{}", document_id);
}

}  // namespace raygate
