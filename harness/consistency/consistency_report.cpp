#include "consistency/consistency_report.h"

#include <fmt/core.h>

#include <cmath>

#include "core/format.h"
#include "results/json_number.h"

namespace raygate {
namespace {

using nlohmann::json;

std::string r2_text(double r2) { return std::isfinite(r2) ? fmt::format("{:.4f}", r2) : "n/a"; }

std::string labels(const ConsistencyResult& result, const std::vector<std::size_t>& indices) {
  std::string text;
  for (std::size_t i : indices) text += (text.empty() ? "" : ", ") + result.documents[i].label;
  return text;
}

std::string document_line(const DocumentRatios& d) {
  return fmt::format("{}  {}  {} ({})  tracer {} {}  baseline {} ({})", d.path, d.hostname,
                     d.cpu_model, is_compare(d.kind) ? "compare, head" : "run", d.adapter_name,
                     d.tracer_short_sha, d.baseline_version,
                     d.baseline_source_sha256.substr(0, 12));
}

std::string verdict_line(const ConsistencyResult& result) {
  const std::size_t unstable = result.unstable_scenes().size();
  if (result.machine_independent()) {
    return fmt::format("machine-independent: every pair r² >= {:.2f} and no unstable scene",
                       result.options.min_r2);
  }
  std::size_t failing_pairs = 0;
  for (const PairFit& p : result.pairs) failing_pairs += p.passes ? 0 : 1;
  return fmt::format(
      "NOT machine-independent for this tracer: {} of {} with r² < {:.2f}, {} unstable",
      failing_pairs, count_text(result.pairs.size(), "pair"), result.options.min_r2,
      count_text(unstable, "scene"));
}

void table_scenes(const ConsistencyResult& result, std::string& out) {
  out += fmt::format("\n{:<12}", "scene");
  for (const DocumentRatios& d : result.documents) out += fmt::format(" {:>8}", d.label);
  out += fmt::format(" {:>8} {:>6} {:>8} {:>12}  {}\n", "mean", "CV", "mean dev", "max dev", "CIs");
  for (const SceneConsistency& s : result.scenes) {
    out += fmt::format("{:<12}", s.id);
    for (double ratio : s.ratios) out += fmt::format(" {:>8.4f}", ratio);
    const std::string max_dev = fmt::format("{} ({})", percent(s.max_deviation),
                                            result.documents[s.max_deviation_document].label);
    out += fmt::format(" {:>8.4f} {:>6} {:>8} {:>12}  {}{}\n", s.mean_ratio, percent(s.cv),
                       percent(s.mean_deviation), max_dev,
                       s.intervals_overlap ? "overlap" : "apart", s.unstable ? "  UNSTABLE" : "");
  }
}

}  // namespace

std::string consistency_table(const ConsistencyResult& result) {
  std::string out = fmt::format("raygate consistency: {} documents, {} in all of them\n",
                                result.documents.size(), count_text(result.scenes.size(), "scene"));
  for (const DocumentRatios& d : result.documents) {
    out += fmt::format("  {}  {}\n", d.label, document_line(d));
  }
  for (const std::string& m : result.mixed) out += "  mixed (--allow-mixed): " + m + "\n";
  for (const std::string& note : result.notes) out += "  note: " + note + "\n";
  out +=
      "\nr² of the per-scene ratios (linear fit of one document's ratios against the other's):\n";
  for (const PairFit& p : result.pairs) {
    out +=
        fmt::format("  {} vs {}  {:>3} scenes  r² {}  slope {:.3f}  mean |difference| {:>6}  {}\n",
                    result.documents[p.a].label, result.documents[p.b].label, p.scenes,
                    r2_text(p.r2), p.slope, percent(p.mean_abs_relative_difference),
                    p.passes ? "ok" : fmt::format("below {:.2f}", result.options.min_r2));
  }
  out += fmt::format("  overall (every pair pooled)  r² {}  lowest pair r² {}\n",
                     r2_text(result.overall_r2), r2_text(result.min_pair_r2));
  table_scenes(result, out);
  for (const MissingScene& m : result.missing) {
    out += fmt::format("missing: {} not measured in {} (excluded)\n", m.id,
                       labels(result, m.missing_from));
  }
  const auto unstable = result.unstable_scenes();
  if (!unstable.empty()) {
    out += fmt::format("\nnot machine-stable ({}, limit {} deviation):\n",
                       count_text(unstable.size(), "scene"), percent(result.options.max_deviation));
    for (const SceneConsistency* s : unstable) {
      for (const std::string& reason : s->reasons) out += fmt::format("  {}: {}\n", s->id, reason);
    }
  }
  out += fmt::format("\n{}\n", verdict_line(result));
  return out;
}

namespace {

// Each document as read: who measured it, which baseline and which tracer revision.
json document_json(const DocumentRatios& d) {
  return {{"label", d.label},
          {"path", d.path},
          {"kind", std::string(to_string(d.kind))},
          {"role", std::string(to_string(d.role))},
          {"hostname", d.hostname},
          {"cpu_model", d.cpu_model},
          {"baseline",
           {{"version", d.baseline_version},
            {"source_sha256", d.baseline_source_sha256},
            {"mode", d.baseline_mode}}},
          {"tracer",
           {{"sha", d.tracer_sha},
            {"dirty", d.tracer_dirty},
            {"adapter", d.adapter_name},
            {"adapter_hash", d.adapter_hash}}},
          {"scenes_measured", d.scenes.size()}};
}

json pair_json(const ConsistencyResult& result, const PairFit& p) {
  return {{"a", result.documents[p.a].label},
          {"b", result.documents[p.b].label},
          {"scenes", p.scenes},
          {"r2", finite_number(p.r2)},
          {"slope", finite_number(p.slope)},
          {"intercept", finite_number(p.intercept)},
          {"mean_abs_relative_difference", finite_number(p.mean_abs_relative_difference)},
          {"passes", p.passes}};
}

json scene_json(const ConsistencyResult& result, const SceneConsistency& s) {
  json intervals = json::array();
  for (const Interval& i : s.intervals) {
    intervals.push_back({finite_number(i.lower), finite_number(i.upper)});
  }
  return {{"id", s.id},
          {"ratios", s.ratios},
          {"intervals", intervals},
          {"mean_ratio", s.mean_ratio},
          {"cv", s.cv},
          {"mean_deviation", s.mean_deviation},
          {"max_deviation", s.max_deviation},
          {"max_deviation_document", result.documents[s.max_deviation_document].label},
          {"intervals_overlap", s.intervals_overlap},
          {"unstable", s.unstable},
          {"reasons", s.reasons}};
}

json missing_json(const ConsistencyResult& result, const MissingScene& m) {
  json from = json::array();
  for (std::size_t i : m.missing_from) from.push_back(result.documents[i].label);
  return {{"id", m.id}, {"missing_from", from}};
}

// One array of `items`, each as `to_json` writes it.
template <typename Item, typename ToJson>
json array_of(const std::vector<Item>& items, ToJson to_json) {
  json array = json::array();
  for (const Item& item : items) array.push_back(to_json(item));
  return array;
}

}  // namespace

json consistency_json(const ConsistencyResult& result) {
  json unstable = json::array();
  for (const SceneConsistency* s : result.unstable_scenes()) unstable.push_back(s->id);
  return {{"documents", array_of(result.documents, document_json)},
          {"options",
           {{"min_r2", result.options.min_r2},
            {"max_deviation", result.options.max_deviation},
            {"allow_mixed", result.options.allow_mixed}}},
          {"mixed", result.mixed},
          {"notes", result.notes},
          {"pairs", array_of(result.pairs, [&](const PairFit& p) { return pair_json(result, p); })},
          {"overall_r2", finite_number(result.overall_r2)},
          {"min_pair_r2", finite_number(result.min_pair_r2)},
          {"scenes", array_of(result.scenes,
                              [&](const SceneConsistency& s) { return scene_json(result, s); })},
          {"missing", array_of(result.missing,
                               [&](const MissingScene& m) { return missing_json(result, m); })},
          {"unstable", unstable},
          {"machine_independent", result.machine_independent()},
          {"exit_code", result.exit_code()}};
}

std::string consistency_markdown(const ConsistencyResult& result) {
  std::string out = "## Ratio consistency across machines\n\n";
  out += "| | document | host | CPU | tracer | baseline |\n|---|---|---|---|---|---|\n";
  for (const DocumentRatios& d : result.documents) {
    out += fmt::format("| {} | `{}` | {} | {} | {} {} | {} `{}` |\n", d.label, d.path, d.hostname,
                       d.cpu_model, d.adapter_name, d.tracer_short_sha, d.baseline_version,
                       d.baseline_source_sha256.substr(0, 12));
  }
  for (const std::string& m : result.mixed) out += "\n> mixed (--allow-mixed): " + m + "\n";
  for (const std::string& note : result.notes) out += "\n> note: " + note + "\n";
  out += "\n| pair | scenes | r² | slope | mean abs difference | |\n|---|---|---|---|---|---|\n";
  for (const PairFit& p : result.pairs) {
    out += fmt::format("| {} vs {} | {} | {} | {:.3f} | {} | {} |\n", result.documents[p.a].label,
                       result.documents[p.b].label, p.scenes, r2_text(p.r2), p.slope,
                       percent(p.mean_abs_relative_difference), p.passes ? "ok" : "**low**");
  }
  out += fmt::format("| overall | {} | {} | | | |\n", result.scenes.size(),
                     r2_text(result.overall_r2));
  out += "\n| scene |";
  for (const DocumentRatios& d : result.documents) out += " " + d.label + " |";
  out += " mean | CV | mean dev | max dev | CIs |\n|---|";
  for (std::size_t i = 0; i < result.documents.size(); ++i) out += "---|";
  out += "---|---|---|---|---|\n";
  for (const SceneConsistency& s : result.scenes) {
    out += fmt::format("| {}{} |", s.id, s.unstable ? " **unstable**" : "");
    for (double ratio : s.ratios) out += fmt::format(" {:.4f} |", ratio);
    out += fmt::format(" {:.4f} | {} | {} | {} ({}) | {} |\n", s.mean_ratio, percent(s.cv),
                       percent(s.mean_deviation), percent(s.max_deviation),
                       result.documents[s.max_deviation_document].label,
                       s.intervals_overlap ? "overlap" : "apart");
  }
  out += "\n";
  for (const MissingScene& m : result.missing) {
    out += fmt::format("- missing: `{}` not measured in {} (excluded)\n", m.id,
                       labels(result, m.missing_from));
  }
  for (const SceneConsistency* s : result.unstable_scenes()) {
    for (const std::string& reason : s->reasons) {
      out += fmt::format("- unstable: `{}`: {}\n", s->id, reason);
    }
  }
  out += fmt::format("\n**{}**\n", verdict_line(result));
  return out;
}

}  // namespace raygate
