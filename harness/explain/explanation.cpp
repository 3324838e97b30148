#include "explain/explanation.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "core/enum_words.h"
#include "core/format.h"

namespace raygate {

namespace {

// The words of the document's "explain" section, each spelt once.
constexpr EnumWords<ExplainSource, 2> kSourceWords{
    {{ExplainSource::explain_runs, "explain-runs"},
     {ExplainSource::simulated_runs, "simulated-runs"}}};
constexpr EnumWords<ExplainCost, 2> kCostWords{
    {{ExplainCost::instructions, "instructions"},
     {ExplainCost::estimated_cycles, "estimated-cycles"}}};

}  // namespace

std::string_view to_string(ExplainSource source) {
  return word_of(kSourceWords, source, "simulated-runs");
}

std::optional<ExplainSource> explain_source_named(std::string_view text) {
  return value_of(kSourceWords, text);
}

std::string_view to_string(ExplainCost cost) {
  return word_of(kCostWords, cost, "estimated-cycles");
}

std::optional<ExplainCost> explain_cost_named(std::string_view text) {
  return value_of(kCostWords, text);
}

namespace {

double total_cycles(const FunctionProfile& profile) {
  double sum = 0.0;
  for (const auto& [name, cost] : profile) sum += estimated_cycles(cost.self);
  return sum;
}

std::uint64_t total_instructions(const FunctionProfile& profile) {
  std::uint64_t sum = 0;
  for (const auto& [name, cost] : profile) sum += cost.self.ir;
  return sum;
}

bool has_inclusive(const FunctionProfile& profile) {
  return !profile.empty() && std::all_of(profile.begin(), profile.end(), [](const auto& entry) {
    return entry.second.inclusive_known;
  });
}

// One side's numbers of a function: cycles only when they are the ranking's unit (without
// cache simulation they would only repeat the instructions under another name).
void fill_side(const FunctionCost& cost, ExplainCost unit, double& cycles,
               std::uint64_t& instructions, std::uint64_t& inclusive) {
  if (unit == ExplainCost::estimated_cycles) cycles = estimated_cycles(cost.self);
  instructions = cost.self.ir;
  inclusive = cost.inclusive_known ? cost.inclusive.ir : 0;
}

FunctionChange change_of(const std::string& name, const FunctionProfile& base,
                         const FunctionProfile& head, ExplainCost unit) {
  FunctionChange change;
  change.name = name;
  if (const auto b = base.find(name); b != base.end()) {
    change.file = b->second.file;
    fill_side(b->second, unit, change.base_cycles, change.base_instructions,
              change.base_inclusive_instructions);
  }
  if (const auto h = head.find(name); h != head.end()) {
    change.file = h->second.file;
    fill_side(h->second, unit, change.head_cycles, change.head_instructions,
              change.head_inclusive_instructions);
  }
  return change;
}

}  // namespace

double Explanation::base_cost() const {
  return cost == ExplainCost::instructions ? static_cast<double>(base_instructions) : base_cycles;
}

double Explanation::head_cost() const {
  return cost == ExplainCost::instructions ? static_cast<double>(head_instructions) : head_cycles;
}

double Explanation::delta_of(const FunctionChange& f) const {
  return cost == ExplainCost::instructions ? f.delta_instructions() : f.delta_cycles();
}

Explanation explain_change(const FunctionProfile& base, const FunctionProfile& head,
                           std::size_t keep, ExplainCost cost) {
  Explanation out;
  out.cost = cost;
  out.inclusive = has_inclusive(base) && has_inclusive(head);
  if (cost == ExplainCost::estimated_cycles) {
    out.base_cycles = total_cycles(base);
    out.head_cycles = total_cycles(head);
  }
  out.base_instructions = total_instructions(base);
  out.head_instructions = total_instructions(head);
  std::set<std::string> names;
  for (const auto& [name, c] : base) names.insert(name);
  for (const auto& [name, c] : head) names.insert(name);
  std::vector<FunctionChange> all;
  for (const std::string& name : names) all.push_back(change_of(name, base, head, cost));
  // Largest increase first; names break ties so the order never depends on the map's.
  std::sort(all.begin(), all.end(), [&out](const FunctionChange& a, const FunctionChange& b) {
    if (out.delta_of(a) != out.delta_of(b)) return out.delta_of(a) > out.delta_of(b);
    return a.name < b.name;
  });
  if (all.size() > keep) all.resize(keep);
  out.functions = std::move(all);
  return out;
}

double share_of_change(const Explanation& explanation, const FunctionChange& function) {
  const double whole = explanation.head_cost() - explanation.base_cost();
  return whole == 0.0 ? 0.0 : explanation.delta_of(function) / whole;
}

std::string_view cost_unit(const Explanation& explanation) {
  return explanation.cost == ExplainCost::instructions ? "instructions" : "cycles";
}

void to_json(nlohmann::json& json, const Explanation& e) {
  nlohmann::json functions = nlohmann::json::array();
  for (const FunctionChange& f : e.functions) {
    functions.push_back({{"name", f.name},
                         {"file", f.file},
                         {"base_cycles", f.base_cycles},
                         {"head_cycles", f.head_cycles},
                         {"base_instructions", f.base_instructions},
                         {"head_instructions", f.head_instructions},
                         {"base_inclusive_instructions", f.base_inclusive_instructions},
                         {"head_inclusive_instructions", f.head_inclusive_instructions}});
  }
  json = {{"source", std::string(to_string(e.source))},
          {"profiler", e.profiler},
          {"cost", std::string(to_string(e.cost))},
          {"inclusive", e.inclusive},
          {"base_cycles", e.base_cycles},
          {"head_cycles", e.head_cycles},
          {"base_instructions", e.base_instructions},
          {"head_instructions", e.head_instructions},
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
  // Documents written before callgrind explanations: cachegrind, estimated cycles, self only.
  const std::string cost = json.value("cost", std::string("estimated-cycles"));
  const std::optional<ExplainCost> unit = explain_cost_named(cost);
  if (!unit) throw std::invalid_argument("explanation.cost: unknown cost \"" + cost + "\"");
  e.cost = *unit;
  e.inclusive = json.value("inclusive", false);
  e.base_cycles = json.at("base_cycles").get<double>();
  e.head_cycles = json.at("head_cycles").get<double>();
  e.base_instructions = json.value("base_instructions", std::uint64_t{0});
  e.head_instructions = json.value("head_instructions", std::uint64_t{0});
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
    change.base_inclusive_instructions = f.value("base_inclusive_instructions", std::uint64_t{0});
    change.head_inclusive_instructions = f.value("head_inclusive_instructions", std::uint64_t{0});
    e.functions.push_back(std::move(change));
  }
}

std::string abbreviated_count(double count) {
  const double size = std::abs(count);
  if (size >= 1e9) return fmt::format("{:.2f}G", count / 1e9);
  if (size >= 1e6) return fmt::format("{:.2f}M", count / 1e6);
  if (size >= 1e3) return fmt::format("{:.1f}k", count / 1e3);
  return fmt::format("{:.0f}", count);
}

std::vector<std::string> explanation_lines(const Explanation& e, std::size_t top) {
  const double base = e.base_cost();
  const double head = e.head_cost();
  const std::string_view unit = cost_unit(e);
  std::vector<std::string> lines{
      fmt::format("where the time went ({}; {} {} -> {}, {}):", e.profiler,
                  e.cost == ExplainCost::instructions ? "instructions" : "estimated cycles",
                  abbreviated_count(base), abbreviated_count(head),
                  signed_percent(base > 0.0 ? head / base - 1.0 : 0.0))};
  for (std::size_t i = 0; i < e.functions.size() && i < top; ++i) {
    const FunctionChange& f = e.functions[i];
    const double delta = e.delta_of(f);
    std::string line =
        fmt::format("  {}{} {} ({} of the change)", delta >= 0.0 ? "+" : "",
                    abbreviated_count(delta), unit, signed_percent(share_of_change(e, f), 0));
    if (e.cost == ExplainCost::estimated_cycles) {
      line += fmt::format(", {} -> {} instructions",
                          abbreviated_count(static_cast<double>(f.base_instructions)),
                          abbreviated_count(static_cast<double>(f.head_instructions)));
    }
    if (e.inclusive) {
      line += fmt::format(", inclusive {} -> {}",
                          abbreviated_count(static_cast<double>(f.base_inclusive_instructions)),
                          abbreviated_count(static_cast<double>(f.head_inclusive_instructions)));
    }
    lines.push_back(line + "  " + f.name);
  }
  if (e.source == ExplainSource::explain_runs && e.native_seconds > 0.0) {
    lines.push_back(
        fmt::format("  profiling cost: {:.1f} s for one base and one head run under the profiler "
                    "({:.0f}x their {:.2f} s measured)",
                    e.profile_seconds, e.profile_seconds / e.native_seconds, e.native_seconds));
  }
  return lines;
}

}  // namespace raygate
