// Typed reading of a JSON document that knows where it is: every accessor that finds the wrong
// thing throws a FieldError naming the JSONPath ("$.build[1][2]") and what it found, so a
// validation error points at the exact spot in the user's file. It reads what core/json_reader.h
// parsed; adapters, policies and results documents all check their fields with it.
#pragma once

#include <nlohmann/json.hpp>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace raygate {

// A problem at one place in a document; the caller prefixes the file name.
class FieldError : public std::runtime_error {
 public:
  FieldError(std::string path, const std::string& message)
      : std::runtime_error(message), path_(std::move(path)) {}
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

// "number 8", "string \"abc\"", "boolean true", "null", "an object", "an array".
std::string describe_json(const nlohmann::json& value);

class JsonField {
 public:
  JsonField(const nlohmann::json& value, std::string path)
      : value_(&value), path_(std::move(path)) {}

  const nlohmann::json& value() const { return *value_; }
  const std::string& path() const { return path_; }

  [[noreturn]] void fail(const std::string& message) const;

  // Checks this is an object whose keys are all in `known`; an unknown key fails with the
  // closest known one as a suggestion.
  void expect_object(const std::vector<std::string>& known) const;
  bool has(std::string_view key) const;          // for an object
  JsonField member(std::string_view key) const;  // fails "missing required key" if absent
  std::vector<std::string> keys() const;         // for an object, sorted
  std::vector<JsonField> elements() const;       // fails unless an array

  std::string as_string() const;
  bool as_bool() const;
  long long as_integer() const;
  // A whole number within [lowest, highest]: a fraction, a string or a number out of range
  // fails with the value found ("expected a whole number from 1 to 8, found number 2.5"), never
  // converted (a double past the integer's range is undefined behaviour, a wide one wraps).
  std::int64_t as_whole(std::int64_t lowest, std::int64_t highest) const;
  double as_number() const;  // integer or floating point

 private:
  [[noreturn]] void fail_type(std::string_view expected) const;
  std::string member_path(std::string_view key) const;

  const nlohmann::json* value_;
  std::string path_;
};

}  // namespace raygate
