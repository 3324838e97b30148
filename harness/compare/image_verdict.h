// The verdict of one image check. In memory an enum; its words ("pass", "fail", ...) are only
// for documents, database rows and printed text (to_string, and parse_image_verdict to read).
#pragma once

#include <optional>
#include <string_view>

namespace raygate {

// Ordered by how much a verdict says against a scene, so the worst of several checks is their
// maximum: "missing" (no golden, a note and never a failure) below "pass", so a scene shows what
// was checked (head against base) rather than the golden it lacks; "inconclusive" (a Monte Carlo
// image neither shown within its tolerance nor beyond it) above "warn"; "error" (the check could
// not be made) below "fail", because a found difference outranks one that could not be looked for.
enum class ImageVerdict { missing, pass, warn, inconclusive, error, fail };

std::string_view to_string(ImageVerdict verdict);
// The verdict named by its word; nullopt for anything else (the caller names the field).
std::optional<ImageVerdict> parse_image_verdict(std::string_view text);

}  // namespace raygate
