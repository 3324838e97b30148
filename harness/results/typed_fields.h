// Reading the typed parts of a results document (settings, scaling) from JSON with the JSONPath
// of every value (core/json_field.h), so a wrong type names the exact spot: the few shapes those
// parts use, beyond JsonField's own accessors. Internal to the JSON boundary of results/.
#pragma once

#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "core/json_field.h"

namespace raygate::typed_fields {

// A number, or null for one that was not finite when written (results/json_number.h): NaN.
inline double number_or_nan(const JsonField& field) {
  if (field.value().is_null()) return std::numeric_limits<double>::quiet_NaN();
  return field.as_number();
}

// A whole number within [lowest, highest].
inline std::int64_t whole(const JsonField& field, std::int64_t lowest, std::int64_t highest) {
  const nlohmann::json& v = field.value();
  if (!v.is_number_integer()) field.fail("expected a whole number, found " + describe_json(v));
  const bool fits = v.is_number_unsigned()
                        ? v.get<std::uint64_t>() <= static_cast<std::uint64_t>(highest)
                        : v.get<std::int64_t>() >= lowest && v.get<std::int64_t>() <= highest;
  if (!fits)
    field.fail("expected a whole number from " + std::to_string(lowest) + " to " +
               std::to_string(highest) + ", found " + describe_json(v));
  return v.get<std::int64_t>();
}

inline int int_of(const JsonField& field) {
  return static_cast<int>(
      whole(field, std::numeric_limits<int>::min(), std::numeric_limits<int>::max()));
}

inline std::size_t count_of(const JsonField& field) {
  return static_cast<std::size_t>(whole(field, 0, std::numeric_limits<std::int64_t>::max()));
}

inline std::vector<int> int_list(const JsonField& field) {
  std::vector<int> out;
  for (const JsonField& element : field.elements()) out.push_back(int_of(element));
  return out;
}

inline std::vector<std::string> string_list(const JsonField& field) {
  std::vector<std::string> out;
  for (const JsonField& element : field.elements()) out.push_back(element.as_string());
  return out;
}

// An object of numbers (or nulls) by key.
inline std::map<std::string, double> number_map(const JsonField& field) {
  std::map<std::string, double> out;
  for (const std::string& key : field.keys()) out[key] = number_or_nan(field.member(key));
  return out;
}

}  // namespace raygate::typed_fields
