#include "explain/explanation.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "core/format.h"

namespace raygate {

std::string_view to_string(ExplainSource source) {
  return source == ExplainSource::explain_runs ? "explain-runs" : "simulated-runs";
}

std::optional<ExplainSource> explain_source_named(std::string_view text) {
  if (text == "explain-runs") return ExplainSource::explain_runs;
  if (text == "simulated-runs") return ExplainSource::simulated_runs;
  return std::nullopt;
}

namespace {

double total_cycles(const FunctionProfile& profile) {
  double sum = 0.0;
  for (const auto& [name, cost] : profile) sum += estimated_cycles(cost.self);
  return sum;
}

FunctionChange change_of(const std::string& name, const FunctionProfile& base,
                         const FunctionProfile& head) {
  FunctionChange change;
  change.name = name;
  if (const auto b = base.find(name); b != base.end()) {
    change.file = b->second.file;
    change.base_cycles = estimated_cycles(b->second.self);
    change.base_instructions = b->second.self.ir;
  }
  if (const auto h = head.find(name); h != head.end()) {
    change.file = h->second.file;
    change.head_cycles = estimated_cycles(h->second.self);
    change.head_instructions = h->second.self.ir;
  }
  return change;
}

}  // namespace

Explanation explain_change(const FunctionProfile& base, const FunctionProfile& head,
                           std::size_t keep) {
  Explanation out;
  out.base_cycles = total_cycles(base);
  out.head_cycles = total_cycles(head);
  std::set<std::string> names;
  for (const auto& [name, cost] : base) names.insert(name);
  for (const auto& [name, cost] : head) names.insert(name);
  std::vector<FunctionChange> all;
  for (const std::string& name : names) all.push_back(change_of(name, base, head));
  // Largest increase first; names break ties so the order never depends on the map's.
  std::sort(all.begin(), all.end(), [](const FunctionChange& a, const FunctionChange& b) {
    if (a.delta_cycles() != b.delta_cycles()) return a.delta_cycles() > b.delta_cycles();
    return a.name < b.name;
  });
  if (all.size() > keep) all.resize(keep);
  out.functions = std::move(all);
  return out;
}

double share_of_change(const Explanation& explanation, const FunctionChange& function) {
  const double whole = explanation.head_cycles - explanation.base_cycles;
  return whole == 0.0 ? 0.0 : function.delta_cycles() / whole;
}

void to_json(nlohmann::json& json, const Explanation& e) {
  nlohmann::json functions = nlohmann::json::array();
  for (const FunctionChange& f : e.functions) {
    functions.push_back({{"name", f.name},
                         {"file", f.file},
                         {"base_cycles", f.base_cycles},
                         {"head_cycles", f.head_cycles},
                         {"base_instructions", f.base_instructions},
                         {"head_instructions", f.head_instructions}});
  }
  json = {{"source", std::string(to_string(e.source))},
          {"profiler", e.profiler},
          {"base_cycles", e.base_cycles},
          {"head_cycles", e.head_cycles},
          {"profile_seconds", e.profile_seconds},
          {"native_seconds", e.native_seconds},
          {"functions", functions}};
}

void from_json(const nlohmann::json& json, Explanation& e) {
  const std::string source = json.at("source").get<std::string>();
  const std::optional<ExplainSource> parsed = explain_source_named(source);
  if (!parsed) throw std::invalid_argument("explanation.source: unknown source \"" + source + "\"");
  e.source = *parsed;
  e.profiler = json.at("profiler").get<std::string>();
  e.base_cycles = json.at("base_cycles").get<double>();
  e.head_cycles = json.at("head_cycles").get<double>();
  e.profile_seconds = json.at("profile_seconds").get<double>();
  e.native_seconds = json.at("native_seconds").get<double>();
  e.functions.clear();
  for (const nlohmann::json& f : json.at("functions")) {
    FunctionChange change;
    change.name = f.at("name").get<std::string>();
    change.file = f.at("file").get<std::string>();
    change.base_cycles = f.at("base_cycles").get<double>();
    change.head_cycles = f.at("head_cycles").get<double>();
    change.base_instructions = f.at("base_instructions").get<std::uint64_t>();
    change.head_instructions = f.at("head_instructions").get<std::uint64_t>();
    e.functions.push_back(std::move(change));
  }
}

std::string count_text(double count) {
  const double size = std::abs(count);
  if (size >= 1e9) return fmt::format("{:.2f}G", count / 1e9);
  if (size >= 1e6) return fmt::format("{:.2f}M", count / 1e6);
  if (size >= 1e3) return fmt::format("{:.1f}k", count / 1e3);
  return fmt::format("{:.0f}", count);
}

std::vector<std::string> explanation_lines(const Explanation& e, std::size_t top) {
  std::string heading =
      fmt::format("where the time went ({}; estimated cycles {} -> {}, {}):", e.profiler,
                  count_text(e.base_cycles), count_text(e.head_cycles),
                  signed_percent(e.base_cycles > 0.0 ? e.head_cycles / e.base_cycles - 1.0 : 0.0));
  std::vector<std::string> lines{heading};
  for (std::size_t i = 0; i < e.functions.size() && i < top; ++i) {
    const FunctionChange& f = e.functions[i];
    const std::string sign = f.delta_cycles() >= 0.0 ? "+" : "";
    lines.push_back(fmt::format("  {}{} cycles ({} of the change), {} -> {} instructions  {}", sign,
                                count_text(f.delta_cycles()),
                                signed_percent(share_of_change(e, f), 0),
                                count_text(static_cast<double>(f.base_instructions)),
                                count_text(static_cast<double>(f.head_instructions)), f.name));
  }
  if (e.source == ExplainSource::explain_runs && e.native_seconds > 0.0) {
    lines.push_back(
        fmt::format("  profiling cost: {:.1f} s for one base and one head run "
                    "under cachegrind ({:.0f}x their {:.2f} s measured)",
                    e.profile_seconds, e.profile_seconds / e.native_seconds, e.native_seconds));
  }
  return lines;
}

}  // namespace raygate
