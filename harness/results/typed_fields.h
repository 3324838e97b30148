// Reading the typed parts of a results document (settings, scaling, the maps by role) from JSON
// with the JSONPath of every value (core/json_field.h), so a wrong type names the exact spot: the
// few shapes those parts use, beyond JsonField's own accessors. Internal to the JSON boundary of
// results/.
#pragma once

#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/domain.h"
#include "core/json_field.h"

namespace raygate::typed_fields {

// A number, or null for one that was not finite when written (results/json_number.h): NaN.
inline double number_or_nan(const JsonField& field) {
  if (field.value().is_null()) return std::numeric_limits<double>::quiet_NaN();
  return field.as_number();
}

// A whole number within [lowest, highest] (JsonField::as_whole).
inline std::int64_t whole(const JsonField& field, std::int64_t lowest, std::int64_t highest) {
  return field.as_whole(lowest, highest);
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

// An object keyed by role words (ratios, scores, scaling fits) as a map by Role: the words
// exist only here and in role_object. A key that names no role fails at its own path.
template <typename Read>
auto by_role(const JsonField& field, Read read)
    -> std::map<Role, decltype(read(std::declval<const JsonField&>()))> {
  std::map<Role, decltype(read(std::declval<const JsonField&>()))> out;
  for (const std::string& word : field.keys()) {
    const JsonField value = field.member(word);
    const std::optional<Role> role = parse_role(word);
    if (!role) value.fail("unknown role \"" + word + "\" (tracer, base, head or baseline)");
    out.emplace(*role, read(value));
  }
  return out;
}

// The inverse: each role's value written under its word.
template <typename Value, typename Write>
nlohmann::json role_object(const std::map<Role, Value>& values, Write write) {
  nlohmann::json out = nlohmann::json::object();
  for (const auto& [role, value] : values) out[std::string(to_string(role))] = write(value);
  return out;
}

// A record with its own nlohmann from_json / to_json (summary_json.h), read or written as is.
template <typename Value>
Value record_of(const JsonField& field) {
  return field.value().get<Value>();
}
template <typename Value>
nlohmann::json record_json(const Value& value) {
  return value;
}

}  // namespace raygate::typed_fields
