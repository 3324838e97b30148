#include "consistency/consistency.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <set>

#include "core/error.h"
#include "core/format.h"

namespace raygate {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string baseline_mode(const BaselineRecord& baseline) {
  return fmt::format("accel {}, sampling {}, timing {}", baseline.accel, baseline.sampling,
                     baseline.timing);
}

std::string short_hash(const std::string& hash) { return hash.substr(0, 12); }

// The machine context is free-form JSON (null fields where the probe knew nothing).
std::string machine_field(const nlohmann::json& machine, const char* key, const char* unknown) {
  if (!machine.is_object()) return unknown;
  const auto it = machine.find(key);
  return it != machine.end() && it->is_string() ? it->get<std::string>() : unknown;
}

// "A x, B y": each document's `field` when the documents do not all agree on it; else empty.
template <typename Field>
std::string differing(const std::vector<DocumentRatios>& documents, Field field) {
  std::set<std::string> values;
  for (const DocumentRatios& d : documents) values.insert(field(d));
  if (values.size() < 2) return {};
  std::string text;
  for (const DocumentRatios& d : documents) {
    text += fmt::format("{}{} {}", text.empty() ? "" : ", ", d.label, field(d));
  }
  return text;
}

void add_scene_file_reasons(const std::vector<DocumentRatios>& documents,
                            std::vector<std::string>& reasons) {
  for (const std::string& id : documents.front().scene_order) {
    std::set<std::string> hashes;
    for (const DocumentRatios& d : documents) {
      if (auto it = d.scenes.find(id); it != d.scenes.end()) hashes.insert(it->second.scene_sha256);
    }
    if (hashes.size() > 1) {
      reasons.push_back(
          fmt::format("scene '{}' is a different scene file in some documents "
                      "(another size or resolution in the suite)",
                      id));
    }
  }
}

double mean_of(const std::vector<double>& values) {
  return std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
}

struct LineFit {
  double r2 = kNaN;
  double slope = kNaN;
  double intercept = kNaN;
};

LineFit fit_line(const std::vector<double>& x, const std::vector<double>& y) {
  LineFit fit;
  if (x.size() != y.size() || x.size() < 2) return fit;
  const double mx = mean_of(x);
  const double my = mean_of(y);
  double sxy = 0.0, sxx = 0.0, syy = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxy += (x[i] - mx) * (y[i] - my);
    sxx += (x[i] - mx) * (x[i] - mx);
    syy += (y[i] - my) * (y[i] - my);
  }
  if (!(sxx > 0.0) || !(syy > 0.0)) return fit;
  fit.r2 = sxy * sxy / (sxx * syy);
  fit.slope = sxy / sxx;
  fit.intercept = my - fit.slope * mx;
  return fit;
}

PairFit fit_pair(const std::vector<SceneConsistency>& scenes, std::size_t a, std::size_t b,
                 double min_r2) {
  std::vector<double> x, y;
  double difference_sum = 0.0;
  for (const SceneConsistency& s : scenes) {
    x.push_back(s.ratios[a]);
    y.push_back(s.ratios[b]);
    difference_sum += std::abs(s.ratios[b] - s.ratios[a]) / s.ratios[a];
  }
  const LineFit fit = fit_line(x, y);
  PairFit pair{a, b, scenes.size(), fit.r2, fit.slope, fit.intercept, 0.0, false};
  pair.mean_abs_relative_difference = difference_sum / static_cast<double>(scenes.size());
  pair.passes = std::isfinite(fit.r2) && fit.r2 >= min_r2;
  return pair;
}

// A document whose ratio is the same on every scene gives no line to fit: r² is undefined, as it
// is for two scenes, so the input cannot answer the question (exit 2), rather than failing it.
void refuse_ratios_without_spread(const ConsistencyResult& result) {
  for (std::size_t d = 0; d < result.documents.size(); ++d) {
    const double first = result.scenes.front().ratios[d];
    const bool varies =
        std::any_of(result.scenes.begin(), result.scenes.end(),
                    [&](const SceneConsistency& s) { return s.ratios[d] != first; });
    if (!varies) {
      throw UsageError(fmt::format(
          "{} ({}) has the same ratio, {:.4f}, on all {}; an r² needs scenes whose ratios differ "
          "(measure scenes of different cost)",
          result.documents[d].label, result.documents[d].path, first,
          count_text(result.scenes.size(), "scene")));
    }
  }
}

// Overall: every pair's points in one fit, so two documents give exactly their pair's r².
double pooled_r2(const std::vector<SceneConsistency>& scenes, std::size_t documents) {
  std::vector<double> x, y;
  for (std::size_t a = 0; a < documents; ++a) {
    for (std::size_t b = a + 1; b < documents; ++b) {
      for (const SceneConsistency& s : scenes) {
        x.push_back(s.ratios[a]);
        y.push_back(s.ratios[b]);
      }
    }
  }
  return fit_line(x, y).r2;
}

void check_intervals(SceneConsistency& s) {
  std::size_t high = 0, low = 0;
  for (std::size_t i = 1; i < s.intervals.size(); ++i) {
    if (s.intervals[i].lower > s.intervals[high].lower) high = i;
    if (s.intervals[i].upper < s.intervals[low].upper) low = i;
  }
  s.highest_lower_document = high;
  s.lowest_upper_document = low;
  s.intervals_overlap = s.intervals[high].lower <= s.intervals[low].upper;
}

SceneConsistency scene_consistency(const std::string& id,
                                   const std::vector<DocumentRatios>& documents,
                                   const ConsistencyOptions& options) {
  SceneConsistency s;
  s.id = id;
  for (const DocumentRatios& d : documents) {
    const SceneRatio& r = d.scenes.at(id);
    s.ratios.push_back(r.ratio);
    s.intervals.push_back(r.interval);
  }
  s.mean_ratio = mean_of(s.ratios);
  double squares = 0.0, deviation_sum = 0.0;
  for (std::size_t i = 0; i < s.ratios.size(); ++i) {
    const double deviation = std::abs(s.ratios[i] - s.mean_ratio) / s.mean_ratio;
    squares += (s.ratios[i] - s.mean_ratio) * (s.ratios[i] - s.mean_ratio);
    deviation_sum += deviation;
    if (deviation > s.max_deviation) {
      s.max_deviation = deviation;
      s.max_deviation_document = i;
    }
  }
  const double n = static_cast<double>(s.ratios.size());
  s.cv = std::sqrt(squares / n) / s.mean_ratio;
  s.mean_deviation = deviation_sum / n;
  check_intervals(s);
  if (s.max_deviation > options.max_deviation) {
    s.reasons.push_back(
        fmt::format("ratio {:.4g} in {} is {:.1f}% from the mean {:.4g} (limit {:.1f}%)",
                    s.ratios[s.max_deviation_document], documents[s.max_deviation_document].label,
                    100.0 * s.max_deviation, s.mean_ratio, 100.0 * options.max_deviation));
  }
  if (!s.intervals_overlap) {
    const Interval& high = s.intervals[s.highest_lower_document];
    const Interval& low = s.intervals[s.lowest_upper_document];
    s.reasons.push_back(fmt::format("CIs do not overlap: {} {:.4g}-{:.4g} vs {} {:.4g}-{:.4g}",
                                    documents[s.lowest_upper_document].label, low.lower, low.upper,
                                    documents[s.highest_lower_document].label, high.lower,
                                    high.upper));
  }
  s.unstable = !s.reasons.empty();
  return s;
}

void check_options(const ConsistencyOptions& options) {
  if (!(options.min_r2 >= 0.0 && options.min_r2 <= 1.0)) {
    throw UsageError(fmt::format("--min-r2 {} is not between 0 and 1", options.min_r2));
  }
  if (!(options.max_deviation > 0.0) || !std::isfinite(options.max_deviation)) {
    throw UsageError(fmt::format("--max-deviation {} must be a positive fraction (0.1 = 10%)",
                                 options.max_deviation));
  }
}

void check_mixed(const std::vector<DocumentRatios>& documents, ConsistencyResult& result) {
  std::vector<std::string> reasons = mixed_reasons(documents);
  if (reasons.empty()) return;
  if (!result.options.allow_mixed) {
    std::string text;
    for (const std::string& reason : reasons) text += "; " + reason;
    throw UsageError("the documents' ratios do not compare" + text +
                     " (measure the same tracer revision with the same raygate-baseline on each "
                     "machine, or pass --allow-mixed)");
  }
  result.mixed = std::move(reasons);
}

// Scenes measured in every document, in the first document's order; the rest are reported.
std::vector<std::string> common_scenes(const std::vector<DocumentRatios>& documents,
                                       std::vector<MissingScene>& missing) {
  std::vector<std::string> all;
  std::set<std::string> seen;
  for (const DocumentRatios& d : documents) {
    for (const std::string& id : d.scene_order) {
      if (seen.insert(id).second) all.push_back(id);
    }
  }
  std::vector<std::string> common;
  for (const std::string& id : all) {
    MissingScene gap{id, {}};
    for (std::size_t i = 0; i < documents.size(); ++i) {
      if (!documents[i].scenes.count(id)) gap.missing_from.push_back(i);
    }
    if (gap.missing_from.empty()) {
      common.push_back(id);
    } else {
      missing.push_back(std::move(gap));
    }
  }
  return common;
}

void add_notes(ConsistencyResult& result) {
  for (const DocumentRatios& d : result.documents) {
    if (d.tracer_dirty) {
      result.notes.push_back(
          fmt::format("{}: the tracer tree was dirty (uncommitted changes): "
                      "its files may differ from commit {}",
                      d.label, d.tracer_short_sha));
    }
  }
}

}  // namespace

std::string document_label(std::size_t index) {
  if (index < 26) return std::string(1, static_cast<char>('A' + index));
  return fmt::format("D{}", index + 1);
}

DocumentRatios document_ratios(const ResultsDocument& document, const std::string& path,
                               const std::string& label) {
  DocumentRatios d;
  d.label = label;
  d.path = path;
  d.kind = document.kind;
  d.role = primary_role(document.kind);
  const RevisionRecord* revision = document.revision(d.role);
  if (revision == nullptr) {
    throw UsageError(fmt::format("{}: a {} document without a '{}' revision (revisions[].role)",
                                 path, to_string(document.kind), to_string(d.role)));
  }
  d.hostname = machine_field(document.machine, "hostname", "unknown host");
  d.cpu_model = machine_field(document.machine, "cpu_model", "unknown CPU");
  // `raygate-baseline --version` carries the source hash too; it is shown from its own field.
  const std::string& version = document.baseline.version;
  d.baseline_version = version.substr(0, version.find(" source-sha256:"));
  d.baseline_source_sha256 = document.baseline.source_sha256;
  d.baseline_mode = baseline_mode(document.baseline);
  d.tracer_sha = revision->worktree.sha;
  d.tracer_short_sha = revision->worktree.short_sha.empty() ? revision->worktree.sha.substr(0, 7)
                                                            : revision->worktree.short_sha;
  d.tracer_dirty = revision->worktree.dirty;
  d.adapter_name = revision->adapter_name;
  d.adapter_hash = revision->adapter_hash;
  for (const SceneResult& scene : document.scenes) {
    const RatioSummary* ratio = scene.ratio(d.role);
    if (scene.status != SceneStatus::measured || ratio == nullptr) continue;
    if (!(ratio->ratio > 0.0) || !std::isfinite(ratio->ratio)) continue;
    d.scenes[scene.entry.id] = {ratio->ratio, ratio->ratio_interval, scene.scene_sha256};
    d.scene_order.push_back(scene.entry.id);
  }
  return d;
}

std::vector<std::string> mixed_reasons(const std::vector<DocumentRatios>& documents) {
  std::vector<std::string> reasons;
  auto add = [&](const std::string& what, const std::string& values) {
    if (!values.empty()) reasons.push_back(what + ": " + values);
  };
  add("different raygate-baseline sources (ratios against different baselines do not compare)",
      differing(documents, [](const DocumentRatios& d) {
        return d.baseline_version + " " + short_hash(d.baseline_source_sha256);
      }));
  add("different baseline settings",
      differing(documents, [](const DocumentRatios& d) { return "(" + d.baseline_mode + ")"; }));
  add("different tracer revisions",
      differing(documents, [](const DocumentRatios& d) { return short_hash(d.tracer_sha); }));
  add("different adapters (build or run settings)",
      differing(documents, [](const DocumentRatios& d) {
        return d.adapter_name + " " + short_hash(d.adapter_hash);
      }));
  if (!documents.empty()) add_scene_file_reasons(documents, reasons);
  return reasons;
}

double r_squared(const std::vector<double>& x, const std::vector<double>& y) {
  return fit_line(x, y).r2;
}

std::vector<const SceneConsistency*> ConsistencyResult::unstable_scenes() const {
  std::vector<const SceneConsistency*> out;
  for (const SceneConsistency& s : scenes) {
    if (s.unstable) out.push_back(&s);
  }
  return out;
}

bool ConsistencyResult::machine_independent() const {
  const bool pairs_pass =
      std::all_of(pairs.begin(), pairs.end(), [](const PairFit& p) { return p.passes; });
  return pairs_pass && unstable_scenes().empty();
}

int ConsistencyResult::exit_code() const { return machine_independent() ? 0 : 1; }

ConsistencyResult analyse_consistency(std::vector<DocumentRatios> documents,
                                      const ConsistencyOptions& options) {
  check_options(options);
  if (documents.size() < 2) {
    throw UsageError(
        fmt::format("consistency needs at least 2 results documents, got {}", documents.size()));
  }
  ConsistencyResult result;
  result.options = options;
  check_mixed(documents, result);
  result.documents = std::move(documents);
  add_notes(result);
  const std::vector<std::string> common = common_scenes(result.documents, result.missing);
  if (common.size() < kMinScenesForR2) {
    throw UsageError(
        fmt::format("only {} measured in every document; an r² needs at "
                    "least {} (measure the same suite on every machine)",
                    count_text(common.size(), "scene"), kMinScenesForR2));
  }
  for (const std::string& id : common) {
    result.scenes.push_back(scene_consistency(id, result.documents, options));
  }
  refuse_ratios_without_spread(result);
  const std::size_t n = result.documents.size();
  result.min_pair_r2 = std::numeric_limits<double>::infinity();
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = a + 1; b < n; ++b) {
      result.pairs.push_back(fit_pair(result.scenes, a, b, options.min_r2));
      const double r2 = result.pairs.back().r2;
      result.min_pair_r2 = std::isfinite(r2) ? std::min(result.min_pair_r2, r2) : kNaN;
    }
  }
  result.overall_r2 = pooled_r2(result.scenes, n);
  return result;
}

}  // namespace raygate
