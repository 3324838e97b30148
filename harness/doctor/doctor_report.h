// What `raygate doctor` prints: the machine, one line per check with its advice, and the noise
// score, for people (terminal) and for machines (--json).
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "doctor/findings.h"
#include "doctor/noise.h"
#include "doctor/system_facts.h"

namespace raygate {

struct DoctorReport {
  SystemFacts facts;
  std::vector<Finding> findings;
  std::optional<NoiseScore> noise;
  std::string noise_error;  // why the noise score could not be measured
  std::string baseline_version;

  std::size_t warnings() const;
};

std::string doctor_text(const DoctorReport& report);
nlohmann::json doctor_json(const DoctorReport& report);

}  // namespace raygate
