// The words of raygate's domain as types: which program a round ran (Role), what a results
// document holds (DocumentKind) and how a scene ended (SceneStatus). Records hold these enums;
// the words ("head", "compare", "measured") appear only where a document, a store row or a run
// directory is read or written, through the to_string / parse_* pairs here. So a mistyped word
// is a compile error, not a branch that silently never runs (tests/harness/core/domain_words_test
// keeps comparisons with the words out of the rest of harness/).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace raygate {

// A program a scene's rounds run: raygate's own reference tracer, or a revision of the tracer
// under test ("tracer" in a run; "base" and "head" in a compare).
enum class Role { baseline, tracer, base, head };

std::string_view to_string(Role role);
// The word as a string: a round's runs are keyed by it (runner/scheduler.h), as on disk.
std::string role_name(Role role);
// nullopt for anything but the four words (the caller names the field).
std::optional<Role> parse_role(std::string_view word);

// A results document measured one revision against the baseline (run) or two (compare).
enum class DocumentKind { run, compare };

std::string_view to_string(DocumentKind kind);
std::optional<DocumentKind> parse_document_kind(std::string_view word);
// Whether the document measured two revisions (base and head) rather than one.
inline bool is_compare(DocumentKind kind) { return kind == DocumentKind::compare; }
// The revisions a document of `kind` measured against the baseline: {tracer} or {base, head}.
std::vector<Role> revision_roles(DocumentKind kind);
// The revision whose ratio and images a reader cares about: head in a compare, else the tracer.
Role primary_role(DocumentKind kind);

// Whether a scene's rounds all ran (measured) or a run failed and cut them short.
enum class SceneStatus { measured, failed };

std::string_view to_string(SceneStatus status);
std::optional<SceneStatus> parse_scene_status(std::string_view word);

// No JSON but the words: nlohmann would write an enum as its number and read one back from it,
// silently. Deleted, so `json{{"role", role}}` does not compile; write to_string(role).
void to_json(nlohmann::json&, Role) = delete;
void to_json(nlohmann::json&, DocumentKind) = delete;
void to_json(nlohmann::json&, SceneStatus) = delete;
void from_json(const nlohmann::json&, Role&) = delete;
void from_json(const nlohmann::json&, DocumentKind&) = delete;
void from_json(const nlohmann::json&, SceneStatus&) = delete;

}  // namespace raygate
