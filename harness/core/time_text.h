// Wall-clock timestamps as text, for documents and directory names (never for measuring: the
// runner measures with a steady clock).
#pragma once

#include <string>

namespace raygate {

std::string utc_timestamp();          // "2026-11-21T14:03:07Z"
std::string compact_utc_timestamp();  // "20261121-140307", sorts like time, safe in a path

}  // namespace raygate
