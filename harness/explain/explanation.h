// "Where did the slowdown come from?" (issue 27): for a scene whose speed REGRESSED, the
// functions whose self cost grew most from base to head: in sim mode in cachegrind's estimated
// cycles (the cost model of --timing sim, measure/simulated_cost.h) with their instructions; with
// --explain in timed mode in instructions counted by callgrind, with each function's inclusive
// instructions (its callees' too). Kept in the results document (scene "explanation"), so every
// report, and a report made later, shows the same.
#pragma once

#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "explain/function_profile.h"

namespace raygate {

// Where the profiles came from: the cachegrind files sim mode wrote for its own runs (free), or
// one extra run each of base and head under cachegrind for `--explain` in timed mode.
enum class ExplainSource { simulated_runs, explain_runs };
std::string_view to_string(ExplainSource source);
std::optional<ExplainSource> explain_source_named(std::string_view text);

// What an explanation ranks by: estimated cycles (sim mode's cachegrind files, with cache
// simulation), or instructions (callgrind without cache simulation: --explain in timed mode).
enum class ExplainCost { estimated_cycles, instructions };
std::string_view to_string(ExplainCost cost);
std::optional<ExplainCost> explain_cost_named(std::string_view text);

struct FunctionChange {
  std::string name;
  std::string file;
  double base_cycles = 0.0;  // self cost, estimated cycles (0 when ranked by instructions)
  double head_cycles = 0.0;
  std::uint64_t base_instructions = 0;  // self Ir
  std::uint64_t head_instructions = 0;
  // Self plus callees (callgrind); 0 when the profiler recorded no calls (cachegrind).
  std::uint64_t base_inclusive_instructions = 0;
  std::uint64_t head_inclusive_instructions = 0;

  double delta_cycles() const { return head_cycles - base_cycles; }
  double delta_instructions() const {
    return static_cast<double>(head_instructions) - static_cast<double>(base_instructions);
  }
  double delta_inclusive_instructions() const {
    return static_cast<double>(head_inclusive_instructions) -
           static_cast<double>(base_inclusive_instructions);
  }
  bool operator==(const FunctionChange&) const = default;
};

inline constexpr std::size_t kExplainedFunctions = 10;

struct Explanation {
  ExplainSource source = ExplainSource::simulated_runs;
  std::string profiler;                              // "valgrind-3.19.0 cachegrind, self cost"
  ExplainCost cost = ExplainCost::estimated_cycles;  // what `functions` are ranked by
  bool inclusive = false;    // the functions carry inclusive instructions (callgrind)
  double base_cycles = 0.0;  // the whole run's estimated cycles (every function); 0 by instructions
  double head_cycles = 0.0;
  std::uint64_t base_instructions = 0;  // the whole run's instructions (every function)
  std::uint64_t head_instructions = 0;
  // Largest increase of self cost first; at most kExplainedFunctions.
  std::vector<FunctionChange> functions;
  // explain_runs: the wall seconds of the two profiled runs, and of the same two runs timed
  // without the profiler (their medians), so the profiler's cost is stated as measured.
  double profile_seconds = 0.0;
  double native_seconds = 0.0;

  // The whole run's cost and a function's self change in `cost`'s unit.
  double base_cost() const;
  double head_cost() const;
  double delta_of(const FunctionChange& function) const;
  bool operator==(const Explanation&) const = default;
};

// The functions with the largest self-cost increase (in `cost`), head against base, at most
// `keep`; inclusive instructions too when both profiles have them.
Explanation explain_change(const FunctionProfile& base, const FunctionProfile& head,
                           std::size_t keep = kExplainedFunctions,
                           ExplainCost cost = ExplainCost::estimated_cycles);

// The share of the whole run's change a function's self change is: +0.8 = 80% of the slowdown.
double share_of_change(const Explanation& explanation, const FunctionChange& function);

// "cycles" or "instructions": the unit of a change column.
std::string_view cost_unit(const Explanation& explanation);

void to_json(nlohmann::json& json, const Explanation& explanation);
void from_json(const nlohmann::json& json, Explanation& explanation);

// The lines a terminal shows: a heading naming the profiler (and its measured cost), then the
// top `top` functions as "+12.3M cycles (+81% of the change)  NAME".
std::vector<std::string> explanation_lines(const Explanation& explanation, std::size_t top);

// "1.23G", "45.6M", "789k": a count people can compare at a glance.
std::string abbreviated_count(double count);

}  // namespace raygate
