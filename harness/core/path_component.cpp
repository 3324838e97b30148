#include "core/path_component.h"

#include <fmt/format.h>

#include "core/error.h"

namespace raygate {
namespace {

bool allowed(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' ||
         c == '_' || c == '-';
}

// The name in quotes with every byte outside printable ASCII as \xNN: NUL, newlines and
// escape sequences stay visible in a one-line message instead of hiding or corrupting it.
std::string quoted(std::string_view name) {
  std::string out = "'";
  for (const char c : name) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte >= 0x7f || c == '\\' || c == '\'') {
      out += fmt::format("\\x{:02x}", byte);
    } else {
      out += c;
    }
  }
  return out + "'";
}

}  // namespace

std::string component_problem(std::string_view name) {
  if (name.empty()) return "is empty";
  if (name == "." || name == "..") return "is a reference to a folder, not a name";
  if (name.size() > kMaxComponentLength) {
    return "is " + std::to_string(name.size()) + " bytes long, more than the " +
           std::to_string(kMaxComponentLength) + " allowed";
  }
  for (const char c : name) {
    if (!allowed(c)) {
      return "may hold only letters, digits, '.', '_' and '-' (it becomes a file or folder name)";
    }
  }
  return "";
}

std::string checked_component(std::string_view name, std::string_view field) {
  const std::string problem = component_problem(name);
  if (!problem.empty()) {
    throw UsageError(std::string(field) + " " + quoted(name) + " " + problem);
  }
  return std::string(name);
}

std::filesystem::path join_component(const std::filesystem::path& dir, std::string_view name,
                                     std::string_view field, std::string_view suffix) {
  std::string file = checked_component(name, field);
  file += suffix;
  return dir / file;
}

}  // namespace raygate
