#include "core/domain.h"

#include "core/enum_words.h"

namespace raygate {

namespace {

// One table per enum: its values and their words, the only place each word is spelt.
constexpr EnumWords<Role, 4> kRoleWords{{{Role::baseline, "baseline"},
                                         {Role::tracer, "tracer"},
                                         {Role::base, "base"},
                                         {Role::head, "head"}}};
constexpr EnumWords<DocumentKind, 2> kKindWords{
    {{DocumentKind::run, "run"}, {DocumentKind::compare, "compare"}}};
constexpr EnumWords<SceneStatus, 2> kStatusWords{
    {{SceneStatus::measured, "measured"}, {SceneStatus::failed, "failed"}}};

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
