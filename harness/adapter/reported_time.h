// The `reported` timing source: a regex over the tracer's own output, for tracers whose process
// time is dominated by start-up or a UI. parse_reported_seconds() is declared in adapter.h;
// this header adds the check the loader uses, so an adapter's regex is known to work up front.
#pragma once

#include <optional>
#include <string>

namespace raygate {

// Why `pattern` cannot serve as timing.regex (does not compile as ECMAScript, or does not have
// exactly one capture group), or nullopt if it can. Messages are raygate's own words, stable
// across standard library versions.
std::optional<std::string> reported_regex_error(const std::string& pattern);

}  // namespace raygate
