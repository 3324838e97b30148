#include "measure/simulated_cost.h"

#include <algorithm>
#include <vector>

#include "measure/counted_spread.h"

namespace raygate {

namespace {

// The members in cachegrind's event order, with their names: one table for JSON both ways.
struct CounterField {
  const char* name;
  std::uint64_t SimulatedCounters::*member;
};
constexpr CounterField kFields[] = {
    {"Ir", &SimulatedCounters::ir},     {"I1mr", &SimulatedCounters::i1mr},
    {"ILmr", &SimulatedCounters::ilmr}, {"Dr", &SimulatedCounters::dr},
    {"D1mr", &SimulatedCounters::d1mr}, {"DLmr", &SimulatedCounters::dlmr},
    {"Dw", &SimulatedCounters::dw},     {"D1mw", &SimulatedCounters::d1mw},
    {"DLmw", &SimulatedCounters::dlmw},
};

bool all_equal(const std::vector<double>& values) {
  return std::all_of(values.begin(), values.end(), [&](double v) { return v == values.front(); });
}

}  // namespace

SimulatedCounters& SimulatedCounters::operator+=(const SimulatedCounters& other) {
  for (const CounterField& field : kFields) this->*field.member += other.*field.member;
  processes += other.processes;
  return *this;
}

double estimated_cycles(const SimulatedCounters& c) {
  const double l1_misses = static_cast<double>(c.i1mr + c.d1mr + c.d1mw);
  const double ll_misses = static_cast<double>(c.ilmr + c.dlmr + c.dlmw);
  return static_cast<double>(c.ir) + kL1MissCycles * l1_misses + kLastLevelMissCycles * ll_misses;
}

void to_json(nlohmann::json& json, const SimulatedCounters& counters) {
  json = nlohmann::json::object();
  for (const CounterField& field : kFields) json[field.name] = counters.*field.member;
  json["processes"] = counters.processes;
  json["estimated_cycles"] = estimated_cycles(counters);
}

void from_json(const nlohmann::json& json, SimulatedCounters& counters) {
  for (const CounterField& field : kFields) {
    counters.*field.member = json.at(field.name).get<std::uint64_t>();
  }
  counters.processes = json.value("processes", 1);
}

double relative_spread(std::span<const double> costs) {
  if (costs.empty()) return 0.0;
  const auto [lowest, highest] = std::minmax_element(costs.begin(), costs.end());
  return *lowest > 0.0 ? (*highest - *lowest) / *lowest : 0.0;
}

std::optional<ChangeSummary> exact_change(std::span<const CompareRound> rounds) {
  if (rounds.size() < 2) return std::nullopt;
  std::vector<double> baseline, base, head;
  for (const CompareRound& round : rounds) {
    if (round.baseline_seconds) baseline.push_back(*round.baseline_seconds);
    base.push_back(round.base_seconds);
    head.push_back(round.head_seconds);
  }
  const double spread =
      std::max({relative_spread(baseline), relative_spread(base), relative_spread(head)});
  if (!counts_agree(spread)) return std::nullopt;
  ChangeSummary summary = summarize_change(rounds);
  summary.exact = true;
  if (spread == 0.0) {
    // Every round is the same round: the change is a fact and its interval a point.
    summary.change = head.front() / base.front() - 1.0;
    summary.change_interval = {summary.change, summary.change};
    return summary;
  }
  // Counts within the tolerance: if no two runs of a contender differ by more than it, each
  // contender's mean cost lies within the tolerance of its every run, so the change lies between
  // the runs' extremes widened by the tolerance, whatever two or three runs did not show.
  const auto [base_low, base_high] = std::minmax_element(base.begin(), base.end());
  const auto [head_low, head_high] = std::minmax_element(head.begin(), head.end());
  const double t = kCountedSpreadTolerance;
  summary.change_interval = {*head_low * (1.0 - t) / (*base_high * (1.0 + t)) - 1.0,
                             *head_high * (1.0 + t) / (*base_low * (1.0 - t)) - 1.0};
  return summary;
}

ChangeSummary measured_change(std::span<const CompareRound> rounds, const BootstrapOptions& options,
                              bool counted, const std::optional<SequenceLevels>& sequence) {
  if (counted) {
    if (std::optional<ChangeSummary> exact = exact_change(rounds)) return *exact;
  }
  return summarize_change(rounds, options, sequence);
}

bool costs_identical(std::span<const RoundSample> rounds) {
  if (rounds.size() < 2) return false;
  std::vector<double> tracer, baseline;
  for (const RoundSample& round : rounds) {
    tracer.push_back(round.tracer_seconds);
    baseline.push_back(round.baseline_seconds);
  }
  return all_equal(tracer) && all_equal(baseline);
}

}  // namespace raygate
