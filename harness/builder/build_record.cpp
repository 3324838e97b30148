#include "builder/build_record.h"

namespace raygate {
namespace {

// Bumped when a field changes meaning; an entry written by another version is rebuilt rather
// than misread.
constexpr int kRecordVersion = 1;

nlohmann::json step_to_json(const BuildStepRecord& step) {
  return {{"argv", step.argv},
          {"outcome", step.outcome},
          {"succeeded", step.succeeded},
          {"wall_seconds", step.wall_seconds},
          {"cpu_seconds", step.cpu_seconds},
          {"log", step.log.string()}};
}

BuildStepRecord step_from_json(const nlohmann::json& j) {
  BuildStepRecord step;
  step.argv = j.at("argv").get<std::vector<std::string>>();
  step.outcome = j.at("outcome").get<std::string>();
  step.succeeded = j.at("succeeded").get<bool>();
  step.wall_seconds = j.at("wall_seconds").get<double>();
  step.cpu_seconds = j.at("cpu_seconds").get<double>();
  step.log = j.at("log").get<std::string>();
  return step;
}

}  // namespace

nlohmann::json build_record_to_json(const BuildRecord& record) {
  nlohmann::json steps = nlohmann::json::array();
  for (const BuildStepRecord& step : record.steps) steps.push_back(step_to_json(step));
  return {{"record_version", kRecordVersion},
          {"sha", record.sha},
          {"dirty", record.dirty},
          {"adapter_name", record.adapter_name},
          {"adapter_hash", record.adapter_hash},
          {"compiler", record.compiler},
          {"key", record.key},
          {"build_dir", record.build_dir.string()},
          {"src_dir", record.src_dir.string()},
          {"steps", steps},
          {"total_seconds", record.total_seconds},
          {"cached", record.cached},
          {"success", record.success},
          {"failure", record.failure},
          {"log_tail", record.log_tail}};
}

BuildRecord build_record_from_json(const nlohmann::json& j) {
  if (j.at("record_version").get<int>() != kRecordVersion) {
    throw nlohmann::json::other_error::create(501, "unsupported build record version", &j);
  }
  BuildRecord record;
  record.sha = j.at("sha").get<std::string>();
  record.dirty = j.at("dirty").get<bool>();
  record.adapter_name = j.at("adapter_name").get<std::string>();
  record.adapter_hash = j.at("adapter_hash").get<std::string>();
  record.compiler = j.at("compiler").get<std::string>();
  record.key = j.at("key").get<std::string>();
  record.build_dir = j.at("build_dir").get<std::string>();
  record.src_dir = j.at("src_dir").get<std::string>();
  for (const nlohmann::json& step : j.at("steps")) record.steps.push_back(step_from_json(step));
  record.total_seconds = j.at("total_seconds").get<double>();
  record.cached = j.at("cached").get<bool>();
  record.success = j.at("success").get<bool>();
  record.failure = j.at("failure").get<std::string>();
  record.log_tail = j.at("log_tail").get<std::string>();
  return record;
}

}  // namespace raygate
