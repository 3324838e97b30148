// Writing and reading the results document's records field by field, so that each field's
// name is spelled once and a number that is not finite is written as null (results/
// json_number.h) and read back as the record's chosen value. Shared by results_json.cpp and
// summary_json.cpp; not a public schema of its own.
#pragma once

#include <initializer_list>
#include <string>
#include <utility>

#include <nlohmann/json.hpp>

#include "results/json_number.h"

namespace raygate::json_record {

using json = nlohmann::json;

// Non-finite numbers have no JSON form: they are written as null and read back as `if_null`.
inline double number_at(const json& object, const char* key, double if_null = 0.0) {
  const json& value = object.at(key);
  return value.is_null() ? if_null : value.get<double>();
}

// Members named in one list, so a record's fields are spelled once each: numbers written null
// when not finite and read back by number_at, strings read as they are.
using NumberFields = std::initializer_list<std::pair<const char*, double>>;
using NumberTargets = std::initializer_list<std::pair<const char*, double*>>;
using StringTargets = std::initializer_list<std::pair<const char*, std::string*>>;

inline json finite_numbers(NumberFields fields) {
  json j = json::object();
  for (const auto& [key, value] : fields) j[key] = finite_number(value);
  return j;
}

inline void read_numbers(const json& j, NumberTargets targets) {
  for (const auto& [key, target] : targets) *target = number_at(j, key);
}

inline void read_strings(const json& j, StringTargets targets) {
  for (const auto& [key, target] : targets) *target = j.at(key).get<std::string>();
}

}  // namespace raygate::json_record
