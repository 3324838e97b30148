#include "core/json_field.h"

#include <fmt/core.h>

#include <algorithm>
#include <cctype>
#include <limits>

#include "core/suggest.h"

namespace raygate {
namespace {

bool is_identifier(std::string_view key) {
  if (key.empty() || std::isdigit(static_cast<unsigned char>(key[0]))) return false;
  return std::all_of(key.begin(), key.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
  });
}

// Long strings are cut so a pasted script does not flood the message.
std::string short_dump(const nlohmann::json& value) {
  std::string text = value.dump();
  constexpr std::size_t kMax = 60;
  if (text.size() > kMax) text = text.substr(0, kMax) + "...";
  return text;
}

std::string join(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& w : words) out += (out.empty() ? "" : ", ") + w;
  return out;
}

}  // namespace

std::string describe_json(const nlohmann::json& value) {
  if (value.is_number()) return "number " + value.dump();
  if (value.is_string()) return "string " + short_dump(value);
  if (value.is_boolean()) return "boolean " + value.dump();
  if (value.is_null()) return "null";
  if (value.is_object()) return "an object";
  return "an array";
}

void JsonField::fail(const std::string& message) const { throw FieldError(path_, message); }

void JsonField::fail_type(std::string_view expected) const {
  fail("expected " + std::string(expected) + ", found " + describe_json(*value_));
}

std::string JsonField::member_path(std::string_view key) const {
  // A key of 100,000 bytes would be quoted whole in every message under it: its start is enough.
  constexpr std::size_t kShownKey = 64;
  if (key.size() > kShownKey) {
    const std::string start = nlohmann::json(std::string(key.substr(0, 40)))
                                  .dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    return fmt::format("{}[{}... ({} bytes)]", path_, start, key.size());
  }
  if (is_identifier(key)) return path_ + "." + std::string(key);
  return path_ + "[" + nlohmann::json(key).dump() + "]";
}

void JsonField::expect_object(const std::vector<std::string>& known) const {
  if (!value_->is_object()) fail_type("an object");
  for (const auto& [key, unused] : value_->items()) {
    if (std::find(known.begin(), known.end(), key) != known.end()) continue;
    std::string message = "unknown key '" + key + "'";
    if (const auto guess = closest_match(key, known)) {
      message += " (did you mean '" + *guess + "'?)";
    } else {
      message += " (known keys: " + join(known) + ")";
    }
    throw FieldError(member_path(key), message);
  }
}

bool JsonField::has(std::string_view key) const {
  return value_->is_object() && value_->contains(key);
}

JsonField JsonField::member(std::string_view key) const {
  if (!value_->is_object()) fail_type("an object");
  const auto it = value_->find(key);
  if (it == value_->end()) fail("missing required key '" + std::string(key) + "'");
  return JsonField(*it, member_path(key));
}

std::vector<std::string> JsonField::keys() const {
  if (!value_->is_object()) fail_type("an object");
  std::vector<std::string> out;
  for (const auto& [key, unused] : value_->items()) out.push_back(key);
  return out;
}

std::vector<JsonField> JsonField::elements() const {
  if (!value_->is_array()) fail_type("an array");
  std::vector<JsonField> out;
  for (std::size_t i = 0; i < value_->size(); ++i) {
    out.emplace_back((*value_)[i], path_ + "[" + std::to_string(i) + "]");
  }
  return out;
}

std::string JsonField::as_string() const {
  if (!value_->is_string()) fail_type("a string");
  return value_->get<std::string>();
}

bool JsonField::as_bool() const {
  if (!value_->is_boolean()) fail_type("true or false");
  return value_->get<bool>();
}

long long JsonField::as_integer() const {
  if (!value_->is_number_integer()) fail_type("an integer");
  if (value_->is_number_unsigned() && value_->get<unsigned long long>() > 1'000'000'000ULL) {
    fail("expected a reasonable integer, found " + describe_json(*value_));
  }
  return value_->get<long long>();
}

std::int64_t JsonField::as_whole(std::int64_t lowest, std::int64_t highest) const {
  const nlohmann::json& v = *value_;
  if (!v.is_number_integer()) fail_type("a whole number");
  // nlohmann keeps every non-negative number as unsigned; one past int64's range fits no range.
  constexpr auto kMaxSigned = static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max());
  const bool fits = (!v.is_number_unsigned() || v.get<std::uint64_t>() <= kMaxSigned) &&
                    v.get<std::int64_t>() >= lowest && v.get<std::int64_t>() <= highest;
  if (!fits) {
    fail("expected a whole number from " + std::to_string(lowest) + " to " +
         std::to_string(highest) + ", found " + describe_json(v));
  }
  return v.get<std::int64_t>();
}

double JsonField::as_number() const {
  if (!value_->is_number()) fail_type("a number");
  return value_->get<double>();
}

}  // namespace raygate
