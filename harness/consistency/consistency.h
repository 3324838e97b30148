// Are a tracer's normalized ratios machine-independent (paper-notes.md, DESIGN.md §1)? Given
// results documents of the same tracer revision measured with the same baseline on different
// machines (or at different times), this compares the per-scene ratios: r² of the linear fit of
// one document's ratios against another's (the paper's figure), and per scene how far each
// document's ratio strays from the scene's mean. A scene is not machine-stable when it strays by
// more than a threshold or when its confidence intervals do not overlap.
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "measure/bootstrap.h"
#include "results/results.h"

namespace raygate {

inline constexpr double kDefaultMinR2 = 0.9;
inline constexpr double kDefaultMaxDeviation = 0.1;  // 10% of the scene's mean ratio
inline constexpr std::size_t kMinScenesForR2 = 3;    // two points always fit a line exactly

struct ConsistencyOptions {
  double min_r2 = kDefaultMinR2;
  double max_deviation = kDefaultMaxDeviation;
  bool allow_mixed = false;  // accept different baselines or tracer revisions (with notes)
};

// One scene's ratio in one document.
struct SceneRatio {
  double ratio = 0.0;
  Interval interval;         // the ratio's 95% CI, as its document stored it
  std::string scene_sha256;  // the NFF measured: same id, other file = another scene
};

// What consistency needs of one results document.
struct DocumentRatios {
  std::string label;  // "A", "B", ...
  std::string path;   // as the user named it
  DocumentKind kind = DocumentKind::run;
  Role role = Role::tracer;  // the revision whose ratios are used: tracer (run), head (compare)
  std::string hostname;
  std::string cpu_model;
  std::string baseline_version;
  std::string baseline_source_sha256;
  std::string baseline_mode;  // "accel none, sampling center, timing in-process"
  std::string tracer_sha;
  std::string tracer_short_sha;
  bool tracer_dirty = false;
  std::string adapter_name;
  std::string adapter_hash;
  std::map<std::string, SceneRatio> scenes;  // measured scenes only, by suite id
  std::vector<std::string> scene_order;      // ids in document order
};

// Throws UsageError naming `path` when the document has no tracer (run) or head (compare)
// revision. Failed scenes and scenes without a ratio are left out.
DocumentRatios document_ratios(const ResultsDocument& document, const std::string& path,
                               const std::string& label);

// "A".."Z", then "D27", "D28", ...
std::string document_label(std::size_t index);

// The reasons the documents' ratios do not compare: different baselines, tracer revisions,
// adapters, or scene files under one id. Empty when they do.
std::vector<std::string> mixed_reasons(const std::vector<DocumentRatios>& documents);

// Squared Pearson correlation of (x, y): the r² of the least-squares line through them.
// NaN when either side has no variance or the sizes differ or are below 2.
double r_squared(const std::vector<double>& x, const std::vector<double>& y);

struct PairFit {
  std::size_t a = 0;  // indices into ConsistencyResult::documents
  std::size_t b = 0;
  std::size_t scenes = 0;
  double r2 = 0.0;     // NaN when undefined (a document whose ratios are all equal)
  double slope = 0.0;  // b's ratio = intercept + slope * a's ratio
  double intercept = 0.0;
  double mean_abs_relative_difference = 0.0;  // mean over scenes of |b - a| / a
  bool passes = false;                        // r2 >= min_r2
};

struct SceneConsistency {
  std::string id;
  std::vector<double> ratios;       // one per document, in document order
  std::vector<Interval> intervals;  // one per document
  double mean_ratio = 0.0;          // arithmetic mean over documents
  double cv = 0.0;                  // population standard deviation / mean (bench/paper-experiment)
  double mean_deviation = 0.0;      // mean over documents of |ratio - mean| / mean
  double max_deviation = 0.0;       // the largest of those
  std::size_t max_deviation_document = 0;
  bool intervals_overlap = true;           // some ratio lies in every document's CI
  std::size_t highest_lower_document = 0;  // when they do not: the pair that is furthest apart
  std::size_t lowest_upper_document = 0;
  bool unstable = false;
  std::vector<std::string> reasons;  // why unstable, one line each
};

struct MissingScene {
  std::string id;
  std::vector<std::size_t> missing_from;  // document indices
};

struct ConsistencyResult {
  ConsistencyOptions options;
  std::vector<DocumentRatios> documents;
  std::vector<std::string> mixed;  // mixed_reasons, when allowed
  std::vector<std::string> notes;  // e.g. a dirty tracer tree
  std::vector<PairFit> pairs;      // every a < b
  double overall_r2 = 0.0;         // one fit over every pair's points pooled
  double min_pair_r2 = 0.0;
  std::vector<SceneConsistency> scenes;  // measured in every document, first document's order
  std::vector<MissingScene> missing;

  std::vector<const SceneConsistency*> unstable_scenes() const;
  // Every pair's r² at least min_r2 and no unstable scene.
  bool machine_independent() const;
  int exit_code() const;  // 0 machine-independent, 1 not
};

// Throws UsageError for fewer than 2 documents, for mixed documents unless allowed (listing
// every reason), and when fewer than kMinScenesForR2 scenes were measured in every document.
ConsistencyResult analyse_consistency(std::vector<DocumentRatios> documents,
                                      const ConsistencyOptions& options);

}  // namespace raygate
