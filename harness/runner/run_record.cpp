#include "runner/run_record.h"

#include <stdexcept>

namespace raygate {

void to_json(nlohmann::json& json, const RunRecord& run) {
  json = nlohmann::json{{"ok", run.ok},
                        {"outcome", run.outcome},
                        {"seconds", run.seconds},
                        {"wall_seconds", run.wall_seconds},
                        {"user_seconds", run.user_seconds},
                        {"system_seconds", run.system_seconds},
                        {"max_rss_kib", run.max_rss_kib},
                        {"reported_seconds", nullptr},
                        {"image", run.image.string()},
                        {"log", run.log.string()}};
  if (run.reported_seconds) json["reported_seconds"] = *run.reported_seconds;
  if (!run.failure.empty()) json["failure"] = run.failure;
  if (run.simulated) json["cachegrind"] = *run.simulated;
  // Written only when there are some, so documents without counters hash as before.
  for (const auto& [name, counter] : run.counters) {
    json["counters"][name] = {{"value", counter.value}, {"unit", counter.unit}};
  }
  // Written only when true, so a document from before raygate-meter reads back and hashes the
  // same (the store's duplicate check compares canonical JSON).
  if (run.max_rss_own) json["max_rss_own"] = true;
  if (run.max_rss_own) json["peak_method"] = std::string(to_string(run.peak_method));
  if (run.stopped_by_budget) json["stopped_by_budget"] = true;  // only then, as above
}

void from_json(const nlohmann::json& json, RunRecord& run) {
  run.ok = json.at("ok").get<bool>();
  run.outcome = json.at("outcome").get<std::string>();
  run.failure = json.value("failure", std::string());
  run.seconds = json.at("seconds").get<double>();
  run.wall_seconds = json.at("wall_seconds").get<double>();
  run.user_seconds = json.at("user_seconds").get<double>();
  run.system_seconds = json.at("system_seconds").get<double>();
  run.max_rss_kib = json.at("max_rss_kib").get<long>();
  run.max_rss_own = json.value("max_rss_own", false);  // absent in documents from before it
  run.peak_method = run.max_rss_own ? PeakMethod::largest_process : PeakMethod::raygate_process;
  if (const auto method = json.find("peak_method"); method != json.end()) {  // from issue 40 on
    const auto parsed = parse_peak_method(method->get<std::string>());
    if (!parsed) throw std::invalid_argument("unknown peak_method " + method->dump());
    run.peak_method = *parsed;
  }
  const nlohmann::json& reported = json.at("reported_seconds");
  run.reported_seconds =
      reported.is_null() ? std::nullopt : std::optional<double>(reported.get<double>());
  if (const auto found = json.find("cachegrind"); found != json.end()) {
    run.simulated = found->get<SimulatedCounters>();
  }
  if (const auto found = json.find("counters"); found != json.end()) {
    for (const auto& [name, counter] : found->items()) {
      run.counters[name] = {counter.at("value").get<double>(),
                            counter.at("unit").get<std::string>()};
    }
  }
  run.image = json.at("image").get<std::string>();
  run.log = json.at("log").get<std::string>();
  run.stopped_by_budget = json.value("stopped_by_budget", false);
}

}  // namespace raygate
