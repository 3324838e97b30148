// Wall-clock timestamps as text, for documents and directory names (never for measuring: the
// runner measures with a steady clock).
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace raygate {

std::string utc_timestamp();          // "2026-11-21T14:03:07Z"
std::string compact_utc_timestamp();  // "20261121-140307", sorts like time, safe in a path

// Whether `text` is a time as raygate and git write them: "2026-11-21T14:03:07Z", or with an
// offset ("+02:00") or fractional seconds, and a real date and time of day (no February 30th,
// no 25:61). Documents are checked with it: merge and history compare these texts as times.
bool is_iso8601_time(std::string_view text);

// The same time as seconds since 1970-01-01T00:00:00Z (its offset applied: 12:00+02:00 is
// 10:00Z), to put two such times in order; nullopt when `text` is not one.
std::optional<double> iso8601_epoch_seconds(std::string_view text);

}  // namespace raygate
