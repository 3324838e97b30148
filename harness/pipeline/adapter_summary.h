// An adapter read back as people read it (`raygate adapter check`): what raygate will build and
// run, placeholders and all, how runs are timed (runner/timing/) and how images are judged, so a
// user can check an adapter before a CI job trips over it.
#pragma once

#include <string>

#include "adapter/adapter.h"

namespace raygate {

// "" when the adapter builds or runs something of the repository under test; else why every
// revision runs the same program (issue 40: blender-cycles runs raygate's own script and
// Blender from PATH, and nothing told the user). Said by adapter check and by run/compare.
std::string repository_unused_note(const Adapter& adapter);

// "FILE: ok" and one indented line per field, each ending in a newline.
std::string adapter_summary(const Adapter& adapter);

}  // namespace raygate
