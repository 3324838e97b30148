// The one gate through which a name from a user's file or a stored document (suite name, scene
// id, adapter name, shard label, a sha read back from a store) becomes part of a path. Anything
// that could climb out of its folder ("..", "/x", "a/b"), hide ("."), or fail as a file name
// (empty, NUL, too long) is refused with a UsageError naming the field, so raygate never writes
// or deletes outside its cache because of what a document said.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

namespace raygate {

// Longest accepted name. File systems allow 255 bytes; raygate appends suffixes (".nff",
// "-dirty-<hash>", ".lock", ".tmp-XXXXXX") to some names, so it keeps well below that.
inline constexpr std::size_t kMaxComponentLength = 128;

// Why `name` cannot be one path component, or "" when it can: letters, digits, '.', '_' and
// '-' only (ASCII), not "." or "..", 1..kMaxComponentLength bytes.
std::string component_problem(std::string_view name);

// `name` unchanged when it is a safe component; otherwise a UsageError
// "<field> <quoted name>: <problem>". `field` says where the name came from, e.g.
// "suite.json: $.scenes[2].id" or "scene id".
std::string checked_component(std::string_view name, std::string_view field);

// dir / checked_component(name, field) + suffix: the only way names become paths. `suffix`
// is raygate's own (".nff", ".json"), never user input.
std::filesystem::path join_component(const std::filesystem::path& dir, std::string_view name,
                                     std::string_view field, std::string_view suffix = {});

}  // namespace raygate
