#include "core/domain.h"

#include <array>
#include <utility>

namespace raygate {

namespace {

// One table per enum: its values and their words, the only place each word is spelt.
constexpr std::array<std::pair<Role, std::string_view>, 4> kRoleWords{{
    {Role::baseline, "baseline"}, {Role::tracer, "tracer"}, {Role::base, "base"}, {Role::head, "head"}}};
constexpr std::array<std::pair<DocumentKind, std::string_view>, 2> kKindWords{{
    {DocumentKind::run, "run"}, {DocumentKind::compare, "compare"}}};
constexpr std::array<std::pair<SceneStatus, std::string_view>, 2> kStatusWords{{
    {SceneStatus::measured, "measured"}, {SceneStatus::failed, "failed"}}};

template <typename Enum, std::size_t N>
std::string_view word_of(const std::array<std::pair<Enum, std::string_view>, N>& table, Enum value) {
  for (const auto& [known, word] : table) {
    if (known == value) return word;
  }
  return "unknown";
}

template <typename Enum, std::size_t N>
std::optional<Enum> value_of(const std::array<std::pair<Enum, std::string_view>, N>& table,
                             std::string_view word) {
  for (const auto& [value, known] : table) {
    if (known == word) return value;
  }
  return std::nullopt;
}

}  // namespace

std::string_view to_string(Role role) { return word_of(kRoleWords, role); }
std::string role_name(Role role) { return std::string(to_string(role)); }
std::optional<Role> parse_role(std::string_view word) { return value_of(kRoleWords, word); }

std::string_view to_string(DocumentKind kind) { return word_of(kKindWords, kind); }
std::optional<DocumentKind> parse_document_kind(std::string_view word) {
  return value_of(kKindWords, word);
}

std::vector<Role> revision_roles(DocumentKind kind) {
  if (is_compare(kind)) return {Role::base, Role::head};
  return {Role::tracer};
}

Role primary_role(DocumentKind kind) { return is_compare(kind) ? Role::head : Role::tracer; }

std::string_view to_string(SceneStatus status) { return word_of(kStatusWords, status); }
std::optional<SceneStatus> parse_scene_status(std::string_view word) {
  return value_of(kStatusWords, word);
}

}  // namespace raygate
