// A history series (docs/store.md "Series"): the measurements whose normalized ratios mean the
// same thing from commit to commit, so trends, drift checks and the report's trend plot compare
// only within one. A ratio moves when the code moves, but also when another tracer, adapter,
// suite, scene size or resolution, timing clock or baseline is measured; each of those starts a
// series of its own.
#pragma once

#include <string>

#include "results/results.h"

namespace raygate {

struct SeriesKey {
  std::string repository;  // repository_key()
  std::string adapter;     // the adapter's name
  std::string suite;
  std::string scene;     // the suite's scene id
  std::string settings;  // scene_settings()
  std::string timing;    // timing_identity()
  std::string baseline;  // baseline_identity()
  // What the measurement depends on (RevisionRecord::adapter_measurement): the build's flags
  // and how the tracer is run, so another build of the same adapter name is another series.
  // "" for documents from before it was recorded, whose ids stay what they were.
  std::string measurement;

  // 16 hex digits of the SHA-256 of every part: equal keys, equal ids.
  std::string id() const;

  bool operator==(const SeriesKey&) const = default;
};

// The tracer's repository: the recorded repository_id (root commit or origin URL), else for
// documents written before it was recorded the location as named, "url:<normalized>" or
// "path:<path>"; "unknown" when the document names none.
std::string repository_key(const RevisionRecord& revision);

// "scene=<generator> size=<n> <w>x<h> sampling=<center|corners>" (0 meaning the scene's own).
std::string scene_settings(const SuiteScene& entry, const BaselineRecord& baseline);

// "<settings.metric> <baseline.timing>": which clock timed the tracer and which the baseline.
// The baseline's timing string is opaque identity; any change to it starts a new series.
std::string timing_identity(const ResultsDocument& document);

// "<source_sha256> accel=<accel>": the baseline ratios are relative to.
std::string baseline_identity(const BaselineRecord& baseline);

SeriesKey series_key(const ResultsDocument& document, const RevisionRecord& revision,
                     const SceneResult& scene);

// The series id of rows whose document could not be read back when the series columns were
// added (store migration 2): each such document is a series of its own, never joined to others.
std::string unknown_series_id(std::int64_t document_id);

}  // namespace raygate
